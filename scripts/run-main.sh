#!/usr/bin/env bash
# The main job from a fresh clone: install what is missing, build, run.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
# The main job: calibrate the shipped published sample (data/samples/kim2017_whole_blood.csv)
# on the shipped default surrogate; the report goes to ./calibration_report.
./build/bin/rbcal calibrate
