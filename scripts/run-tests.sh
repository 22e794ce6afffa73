#!/usr/bin/env bash
# The test suite from a fresh clone: install what is missing, build, run the fast tests.
# Long physics validations are labelled `validation` and excluded here; run them with
#   ctest --test-dir build -L validation --output-on-failure
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)" -LE validation
