#!/usr/bin/env bash
# The main job from a fresh clone: install what is missing, build, run.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
# Until calibration lands, the main job is the solver demonstration.
./build/bin/rbcal couette
