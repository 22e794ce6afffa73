#!/usr/bin/env bash
# Builds the fuzz targets (clang, libFuzzer, AddressSanitizer, UBSan) in build-fuzz/ and runs
# each for SECONDS (default 60) from its seed corpus: `bash scripts/fuzz.sh [SECONDS]`.
# Needs Debian's clang (libFuzzer ships with it).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DRBCAL_FUZZ=ON -DRBCAL_BUILD_TESTS=OFF \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" -DRBCAL_FUZZ_SECONDS="$seconds"
cmake --build build-fuzz -j "$(nproc)"
ctest --test-dir build-fuzz -L fuzz --output-on-failure
