#!/usr/bin/env bash
# The device path's checks and timings on a GPU host (docs/gpu.md), in one run that ends
# within SECONDS (default 540): the device tests, `rbcal bench --backend device` on three
# cases (and the CPU path on the same host's cores), the capsule deformation against the
# boundary-integral references, two dense library cases against their CPU results, then
# anchor cases until the time is up. Run from the repository root:
#   here:   cmake -S . -B build-cuda -DRBCAL_CUDA=ON -DRBCAL_NATIVE=OFF -DRBCAL_MARCH=x86-64-v3 -DRBCAL_PYTHON=OFF
#           cmake --build build-cuda --target rbcal device_tests
#           bash scripts/device-batch.sh pack build-cuda/bin/rbcal build-cuda/bin/device_tests
#   there:  bash scripts/gpu-check.sh [SECONDS] [ANCHOR...]
# ANCHOR: a case of data/library/anchors/cases/ by name, or any case file by its path. Runs
# resume from their checkpoints: a run cut off by SECONDS goes on in the next call while the
# machine is still warm (its files stay in the script's work folder there).
# PARALLEL=N runs N anchors at a time on the one GPU (default 1): a small case leaves the GPU
# idle between its kernels, which another case's kernels then fill. BACKEND=cpu runs them on
# the host's cores instead (to try the script without a GPU). CPU_CASES="CASE.json ..." runs
# those case files on the host's cores meanwhile, one after another, CPU_THREADS (default 12)
# threads each.
# Writes OUT/log.txt (everything printed) and OUT/runs.tar.gz (each run's result.json,
# series.csv and log); OUT defaults to ./gpu-check.out.
set -u
budget=${1:-540}
shift || true
anchors=("$@")
start=$(date +%s)
left() { echo $((budget - ($(date +%s) - start))); }
out=$(realpath -m "${OUT:-gpu-check.out}")
mkdir -p "$out"
here=$(pwd)
work=/tmp/gpu-check
rm -rf "$work/.devrun" && mkdir -p "$work/runs"
tar xJf .devrun.tar.xz -C "$work" || { echo "no .devrun.tar.xz (scripts/device-batch.sh pack)"; exit 2; }
# The binaries with the libraries they were built against; the driver's own library from
# the host (the tool's machines keep it under /usr/local/nvidia).
cat > "$work/run" <<EOF
#!/bin/sh
binary=\$1; shift
exec $work/.devrun/ld-linux-x86-64.so.2 --library-path "$work/.devrun:\${LD_LIBRARY_PATH:-}:/usr/local/nvidia/lib64:/usr/lib/x86_64-linux-gnu" "$work/.devrun/\$binary" "\$@"
EOF
chmod +x "$work/run"
run="$work/run"

bounded() {  # LIMIT COMMAND...: the command under min(LIMIT, what is left less 15 s)
  local limit=$1; shift
  [ "$(left)" -gt 20 ] || { echo "skipped (no time left): $*"; return; }
  [ "$limit" -lt "$(( $(left) - 15 ))" ] || limit=$(( $(left) - 15 ))
  timeout -s TERM "$limit" "$@"
}

backend=${BACKEND:-device}
parallel=${PARALLEL:-1}
# A GPU in exclusive-process mode takes one process at a time.
if [ "$parallel" -gt 1 ] && [ "$backend" = device ] &&
   nvidia-smi --query-gpu=compute_mode --format=csv,noheader 2>/dev/null | grep -qi exclusive; then
  echo "the GPU runs in exclusive-process mode: PARALLEL=$parallel becomes 1"
  parallel=1
fi

simulate() {  # NAME CASE LIMIT
  local name=$1 case=$2 limit=$3
  [ "$(left)" -gt 20 ] || { echo "$name: skipped (no time left)"; return; }
  local t0=$(date +%s)
  bounded "$limit" "$run" rbcal simulate "$case" --backend "$backend" -q --resume -o "$work/runs/$name.out" \
    >> "$work/runs/$name.log" 2>&1
  echo "$name: exit $? after $(( $(date +%s) - t0 )) s"
  grep -E "eta_re|Taylor" "$work/runs/$name.log" | sed 's/^/    /'
}

{
  echo "== host"
  date -u
  nvidia-smi --query-gpu=name,memory.total,driver_version,clocks.max.sm,clocks.max.mem --format=csv
  lscpu | grep -E "Model name|^CPU\(s\)"
  if [ -z "${ANCHORS_ONLY:-}" ]; then  # ANCHORS_ONLY=1: only the anchor runs
  echo "== device tests (the GPU against the CPU path)"
  RBCAL_CASES_DIR="$here/data/cases" bounded 180 "$run" device_tests 2>&1 | grep -vE "^\[ RUN|^$"
  echo "== bench: dense N_a 8 case on the device"
  bounded 90 "$run" rbcal bench --case data/cases/bench_dense_n8.json --backend device --case-steps 400
  echo "== bench: the same on the host's CPU cores"
  bounded 90 "$run" rbcal bench --case data/cases/bench_dense_n8.json --case-steps 20
  echo "== bench: N_a 16 library case (16a box) on the device"
  bounded 120 "$run" rbcal bench --case studies/gpu-path/cases/n16_phieff0.40_Ca0.5_lambda5.json --backend device \
    --case-steps 200
  echo "== bench: the seed study's box at N_a 16 on the device"
  bounded 150 "$run" rbcal bench --case data/cases/bench_paper_n16.json --backend device --case-steps 40
  echo "== capsules (reference D: 0.156, 0.2695, 0.3885 at Ca_G 0.075, 0.15, 0.3)"
  for ca in 0.075 0.15 0.3; do simulate "capsule_CaG${ca}_n8" "studies/gpu-path/cases/capsule_CaG${ca}_n8.json" 90; done
  echo "== dense library cases (CPU: 4.0518 +- 0.0082 and 2.6907 +- 0.0142)"
  for n in phi0.44_Ca2.9_lambda2.58_n8 phi0.26_Ca0.8_lambda5_n8; do simulate "$n" "studies/gpu-path/cases/$n.json" 150; done
  fi
  # Each run's summary goes to its own file, printed in the given order once all are done.
  cpu_names=() cpu_pid=
  if [ -n "${CPU_CASES:-}" ]; then
    for c in $CPU_CASES; do cpu_names+=("$(basename "$c" .json)"); done
    (
      backend=cpu
      export OMP_NUM_THREADS=${CPU_THREADS:-12}
      for c in $CPU_CASES; do
        name=$(basename "$c" .json)
        simulate "$name" "$c" 600 > "$work/runs/$name.summary" 2>&1
      done
    ) &
    cpu_pid=$!
  fi
  echo "== anchors ($parallel at a time)"
  names=()
  for a in "${anchors[@]}"; do
    case "$a" in
      *.json) name=$(basename "$a" .json); file=$a ;;
      *) name=$a; file=data/library/anchors/cases/$a.json ;;
    esac
    names+=("$name")
    while [ "$(jobs -rp | grep -vx "${cpu_pid:-none}" | wc -l)" -ge "$parallel" ]; do wait -n; done
    simulate "$name" "$file" 600 > "$work/runs/$name.summary" 2>&1 &
  done
  wait
  for name in "${names[@]}"; do cat "$work/runs/$name.summary"; done
  if [ -n "$cpu_pid" ]; then
    echo "== on the host's cores"
    for name in "${cpu_names[@]}"; do cat "$work/runs/$name.summary" 2>/dev/null; done
  fi
  echo "== done after $(( $(date +%s) - start )) s"
} 2>&1 | tee "$out/log.txt"
(cd "$work/runs" && tar czf "$out/runs.tar.gz" $(ls -d *.log */result.json */series.csv 2>/dev/null))
ls -la "$out"
