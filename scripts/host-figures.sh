#!/bin/bash
# The figures docs/performance.md keeps per host, measured in one run: the fluid update
# against the streaming-store triad (2 threads and 1, double and float storage), the
# prefetch distance scan, and the coupled step against the plain fluid update on the bench
# case, from its seeded state and from a run's state. Two alternating passes of the fluid
# figures, three runs of the coupled one (two from the run's state); the summary gives each
# figure's range. Stop other heavy work first: the figures are the host's.
#
#   bash scripts/host-figures.sh [RBCAL] [OUT]     (defaults: build/bin/rbcal of this checkout, ./host-figures)
#
# About 4 minutes on a 2-core host. Every bench run's JSON stays in OUT. HOST_FIGURES_QUICK=1
# runs the same set on a tiny lattice in seconds (a check of the script, not figures).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
rbcal=$(realpath -m "${1:-$root/build/bin/rbcal}")  # paths as given, from the caller's folder
out=$(realpath -m "${2:-host-figures}")
cd "$root"
[ -x "$rbcal" ] || { echo "host-figures.sh: no rbcal at $rbcal (build it first: bash scripts/build.sh)" >&2; exit 1; }
mkdir -p "$out"

# Triad arrays of 4x the last-level cache together, at least 1 GiB each (some hosts report
# a large shared L3; the bench warns when the arrays are too small).
l3=$(getconf LEVEL3_CACHE_SIZE 2>/dev/null || echo 0)
triad=$(( l3 > 0 ? (4 * l3 / 3 / 1048576 > 1024 ? 4 * l3 / 3 / 1048576 : 1024) : 1024 ))

quick=()
case_steps=40
run_steps=8300
if [ "${HOST_FIGURES_QUICK:-0}" = 1 ]; then
  triad=8
  quick=(--box 16,16,16 --steps 1)
  case_steps=2
  run_steps=20
fi

bench() {  # NAME ARGS...: one bench run, its JSON kept as OUT/NAME.json
  local name=$1; shift
  echo "  $name" >&2
  "$rbcal" bench "$@" --json "$out/$name.json" > "$out/$name.txt"
}

echo "host-figures: $("$rbcal" bench --box 8,8,8 --steps 1 --rounds 1 --triad-mib 1 | sed -n 2p | sed 's/^ *//')" >&2
for pass in 1 2; do
  for threads in 2 1; do
    for precision in double float; do
      bench "fluid_t${threads}_${precision}_${pass}" --rounds 5 --triad-mib "$triad" --threads "$threads" \
        --precision "$precision" "${quick[@]}"
    done
  done
  for distance in 0 16 32 64 128; do
    bench "prefetch_${distance}_${pass}" --rounds 3 --triad-mib "$triad" --threads 2 --prefetch "$distance" "${quick[@]}"
  done
done
for run in 1 2 3; do
  bench "coupled_t2_${run}" --case data/cases/bench_dense_n8.json --case-steps "$case_steps" --threads 2
done
bench coupled_t1_1 --case data/cases/bench_dense_n8.json --case-steps "$case_steps" --threads 1
# A run's state as well: by strain 4 shear has carried most cells out of the box in x, where
# the runs spend nearly all their steps (docs/performance.md, "The coupled step against the
# fluid update").
echo "  the bench case to strain 4.3 (8300 steps)" >&2
"$rbcal" simulate data/cases/bench_dense_n8.json -o "$out/bench_case_run" --overwrite -q \
  --max-steps "$run_steps" > "$out/bench_case_run.txt" 2>&1
for run in 1 2; do
  bench "coupled_run_state_t2_${run}" --case data/cases/bench_dense_n8.json --case-steps "$case_steps" --threads 2 \
    --case-checkpoint "$out/bench_case_run/checkpoint.bin"
done

python3 - "$out" <<'EOF'
import glob, json, os, sys

out = sys.argv[1]

def runs(pattern):
    return [json.load(open(f)) for f in sorted(glob.glob(os.path.join(out, pattern + ".json")))]

def median_mlups(run):
    rounds = sorted(run["lattice_updates_per_s"])
    return 1e-6 * rounds[len(rounds) // 2]

def span(values, fmt):
    low, high = fmt.format(min(values)), fmt.format(max(values))
    return low if low == high else f"{low}-{high}"

first = runs("fluid_t2_double_*")[0]
print(f"host: {first['cpu_model']} ({first['cpu_signature']}), {first['vector_doubles']} doubles per vector, "
      f"THP {first['transparent_huge_pages']}, triad arrays {first['triad_array_mib']:.0f} MiB")
for threads in (2, 1):
    for precision in ("double", "float"):
        r = runs(f"fluid_t{threads}_{precision}_*")
        mlups = [median_mlups(j) for j in r]
        frac = [100 * j["roofline_fraction_streaming_triad"] for j in r]
        huge = [100 * j["huge_page_bytes"] / j["anonymous_bytes"] for j in r if j["anonymous_bytes"] > 0]
        triad = [1e-9 * x for j in r for x in j["triad_streaming_bytes_per_s"]]
        print(f"fluid update, {threads} thread(s), {precision}: {span(mlups, '{:.1f}')} MLUPS, "
              f"{span(frac, '{:.0f}')} % of the streaming-store triad ({span(triad, '{:.0f}')} GB/s over the rounds)"
              + (f", {span(huge, '{:.0f}')} % of memory in huge pages" if huge else ""))
scan = []
for distance in (0, 16, 32, 64, 128):
    mlups = [median_mlups(j) for j in runs(f"prefetch_{distance}_*")]
    scan.append(f"{distance}: {span(mlups, '{:.1f}')}")
print("prefetch scan, 2 threads, MLUPS: " + "; ".join(scan))
for threads in (2, 1):
    ratios = [j["whole_over_plain_fluid"] for j in runs(f"coupled_t{threads}_*")]
    print(f"coupled step / plain fluid (bench case), {threads} thread(s): " + ", ".join(f"{x:.2f}" for x in ratios))
state = runs("coupled_run_state_t2_*")
print(f"coupled step / plain fluid (bench case, a run's state at strain {state[0]['start_strain']:.2f}), 2 threads: "
      + ", ".join(f"{j['whole_over_plain_fluid']:.2f}" for j in state))
EOF
