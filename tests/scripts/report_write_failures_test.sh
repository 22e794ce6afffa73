#!/usr/bin/env bash
# The calibration report is written as a unit: a rerun that fails on a full disk keeps the
# previous report whole (its summary.json and tables from one run), names the reason, and
# leaves no temporary file or half-built folder; a --no-plots rerun leaves no plots of the
# run before. The full disk is a small tmpfs (needs root and mount; skipped otherwise).
# Usage: report_write_failures_test.sh RBCAL WORK_DIR
set -uo pipefail
rbcal=$1 dir=$2
fail() { echo "FAIL: $*"; exit 1; }
umount "$dir/disk" 2>/dev/null
rm -rf "$dir" && mkdir -p "$dir/disk"

# --no-plots after a run with plots: the old plots go with the old report.
"$rbcal" calibrate --method direct -o "$dir/plain" >"$dir/plots.log" 2>&1 || fail "first run: $(cat "$dir/plots.log")"
ls "$dir/plain"/*.png >/dev/null 2>&1 || echo "note: no PNG written (no gnuplot?): the --no-plots check is void"
"$rbcal" calibrate --method direct --no-plots -o "$dir/plain" >"$dir/noplots.log" 2>&1 || fail "--no-plots: $(cat "$dir/noplots.log")"
ls "$dir/plain"/*.png >/dev/null 2>&1 && fail "a --no-plots rerun left the previous run's plots"
ls -d "$dir"/plain.* 2>/dev/null && fail "staging or old folders left beside the report"

if ! mount -t tmpfs -o size=2m tmpfs "$dir/disk" 2>/dev/null; then
  echo "SKIP: cannot mount a tmpfs here (needs root); the --no-plots check passed"
  exit 77
fi
trap 'umount "$dir/disk" 2>/dev/null' EXIT
"$rbcal" calibrate --method direct --no-plots --seed 7 -o "$dir/disk/report" >"$dir/first.log" 2>&1 ||
  fail "first run on the tmpfs: $(cat "$dir/first.log")"
before=$(md5sum "$dir/disk/report"/* | md5sum)
# Fill the disk but for a few kB: the report (tens of kB) cannot be written again.
dd if=/dev/zero of="$dir/disk/filler" bs=1k count=4096 >/dev/null 2>&1
avail=$(df -k --output=avail "$dir/disk" | tail -1)
[ "$avail" -lt 16 ] || fail "the tmpfs still has $avail kB free"
"$rbcal" calibrate --method direct --no-plots --seed 8 -o "$dir/disk/report" >"$dir/full.log" 2>&1
status=$?
[ "$status" -ne 0 ] || fail "a report written on a full disk exited 0: $(cat "$dir/full.log")"
grep -q "No space left on device" "$dir/full.log" || fail "the error does not name the full disk: $(cat "$dir/full.log")"
[ "$(md5sum "$dir/disk/report"/* | md5sum)" = "$before" ] || fail "the previous report changed"
grep -q '"seed": 7' "$dir/disk/report/summary.json" || fail "the previous summary is not the seed-7 run's"
leftovers=$(find "$dir/disk" -name '*.tmp.*' -o -name 'report.new.*' -o -name 'report.old.*' | head -3)
[ -z "$leftovers" ] || fail "left behind: $leftovers"
echo "report written as a unit: full disk named, previous report kept whole, nothing left behind"
