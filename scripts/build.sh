#!/usr/bin/env bash
# Configures and builds rbcal (Release) into ./build; re-running rebuilds incrementally.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$(nproc)"
