#!/usr/bin/env bash
# Library cases on a lent many-core machine (the workplace's device tool), where no
# packages can be installed: docs/performance.md, "Library cases on the lent 16-core machine".
#   here:   bash scripts/device-batch.sh prepare BINARY
#           copies BINARY, its shared libraries and the loader into .devrun/ (ignore it in
#           .git/info/exclude and name it in the tool's carry list);
#   there:  THREADS=2 bash scripts/device-batch.sh run LIMIT TIER CASE_NAME...
#           runs data/cases/library_v2/TIER/CASE_NAME.json in parallel, THREADS threads each,
#           stopped (with a checkpoint) after LIMIT seconds; packs the finished results, all
#           series and the logs into $OUT/results.tar.gz and up to four unfinished
#           checkpoints into $OUT (what the tool brings back: 8 files of 16 MiB at most).
#   here:   bash scripts/device-batch.sh pack BINARY...
#           the same for several binaries (a GPU build's rbcal and device_tests), compressed
#           to .devrun.tar.xz, which the tool carries where the uncompressed folder would not
#           fit beside the repository (scripts/gpu-check.sh, and `run` without a .devrun/,
#           unpack it there).
# Back here, finished cases go to RUNS/TIER/NAME.out/ (result.json, series.csv), unfinished
# ones with their checkpoint.bin and series.csv, where `rbcal simulate CASE -o RUNS/TIER/NAME.out
# --resume` continues them.
set -u
mode=$1; shift
collect() {  # BINARY...: into .devrun/ with their shared libraries and the loader
  rm -rf .devrun && mkdir .devrun
  # netCDF writes only the calibration's ArviZ posterior file, which no run on the device
  # machine makes; its own libraries (HDF5, curl, TLS, XML, ICU: over 20 MB compressed) would
  # push the carried tree past the tool's 64 MiB. An empty stand-in with its name satisfies
  # the loader instead: the binaries bind functions lazily, so only a call would fail.
  for binary in "$@"; do
    netcdf=$(ldd "$binary" | awk '/libnetcdf/ {print $1; exit}')
    [ -n "$netcdf" ] && [ ! -f ".devrun/$netcdf" ] || continue
    echo "int rbcal_netcdf_stand_in;" > .devrun/netcdf_stand_in.c
    gcc -shared -fPIC -Wl,-soname,"$netcdf" -o ".devrun/$netcdf" .devrun/netcdf_stand_in.c && rm .devrun/netcdf_stand_in.c
  done
  for binary in "$@"; do
    cp "$binary" .devrun/
    for lib in $(LD_LIBRARY_PATH="$PWD/.devrun" ldd "$binary" | awk '/=>/ {print $3} /ld-linux/ {print $1}'); do
      cp -Ln "$lib" .devrun/
    done
  done
}
if [ "$mode" = prepare ]; then
  collect "$1"
  [ "$(basename "$1")" = rbcal ] || mv ".devrun/$(basename "$1")" .devrun/rbcal
  du -sh .devrun
  exit 0
fi
if [ "$mode" = pack ]; then
  rm -f .devrun.tar.xz
  collect "$@"
  tar cJf .devrun.tar.xz .devrun && rm -rf .devrun
  du -sh .devrun.tar.xz
  exit 0
fi
[ "$mode" = run ] || { echo "usage: $0 prepare BINARY | pack BINARY... | run LIMIT TIER CASE_NAME..."; exit 2; }
limit=$1 tier=$2; shift 2
here=$(pwd)
# The folder as carried, or unpacked from the archive that `pack` made.
[ -d .devrun ] || tar xJf .devrun.tar.xz || { echo "neither .devrun/ nor .devrun.tar.xz (prepare or pack first)"; exit 2; }
lscpu | grep -E "Model name|^CPU\(s\)|L3"
mkdir -p /tmp/runs
start=$(date +%s)
cd data/cases/library_v2
for n in "$@"; do
  OMP_NUM_THREADS=${THREADS:-1} timeout -s TERM "$limit" "$here/.devrun/ld-linux-x86-64.so.2" --library-path "$here/.devrun" \
    "$here/.devrun/rbcal" simulate "$tier/$n.json" -o "/tmp/runs/$n.out" > "/tmp/runs/$n.log" 2>&1 &
done
wait
echo "all stopped after $(( $(date +%s) - start )) s"
cd /tmp/runs
finished=() left=()
for n in "$@"; do
  if [ -f "$n.out/result.json" ]; then finished+=("$n"); else left+=("$n"); fi
  echo "$n: strain $(tail -n1 "$n.out/series.csv" 2>/dev/null | cut -d, -f1) $(grep -o 'eta_re (stresslet).*' "$n.log" | head -1)"
done
echo "finished: ${finished[*]}"; echo "unfinished: ${left[*]}"
files=()
for n in "${finished[@]}"; do files+=("$n.out/result.json" "$n.out/series.csv"); done
for n in "${left[@]}"; do [ -f "$n.out/series.csv" ] && files+=("$n.out/series.csv"); done
tar czf "$OUT/results.tar.gz" "${files[@]}" "${@/%/.log}"
kept=0
for n in "${left[@]}"; do
  [ "$kept" -ge 4 ] && break
  [ -f "$n.out/checkpoint.bin" ] && cp "$n.out/checkpoint.bin" "$OUT/$n.checkpoint.bin" && kept=$((kept + 1))
done
ls -la "$OUT"
