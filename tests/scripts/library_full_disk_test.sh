#!/usr/bin/env bash
# `rbcal library generate` on a disk too small for a case's checkpoint: the sweep stops with
# an error naming the file and the full disk, exits non-zero, files no case as a solver
# failure (failed/) and leaves no temporary file; with room again, the same sweep finishes.
# The disk is a small tmpfs (needs root and mount; skipped otherwise).
# Usage: library_full_disk_test.sh RBCAL PLAN WORK_DIR
set -uo pipefail
rbcal=$1 plan=$2 dir=$3
fail() { echo "FAIL: $*"; exit 1; }
umount "$dir/disk" 2>/dev/null
rm -rf "$dir" && mkdir -p "$dir/disk"
mount -t tmpfs -o size=256k tmpfs "$dir/disk" 2>/dev/null || { echo "SKIP: cannot mount a tmpfs here"; exit 77; }
trap 'umount "$dir/disk" 2>/dev/null' EXIT
"$rbcal" library generate "$plan" --library "$dir/disk/lib" --threads 1 --quiet >"$dir/full.log" 2>&1
status=$?
[ "$status" -ne 0 ] || fail "a sweep on a full disk exited 0: $(cat "$dir/full.log")"
grep -q "No space left on device" "$dir/full.log" || fail "the error does not name the full disk: $(cat "$dir/full.log")"
[ -z "$(ls -A "$dir/disk/lib/failed" 2>/dev/null)" ] || fail "a write error was filed as a solver failure: $(ls "$dir/disk/lib/failed")"
leftovers=$(find "$dir/disk" -name '*.tmp.*' | head -3)
[ -z "$leftovers" ] || fail "temporary files left: $leftovers"
umount "$dir/disk"
trap - EXIT
mount -t tmpfs -o size=64m tmpfs "$dir/disk" 2>/dev/null || fail "remount"
trap 'umount "$dir/disk" 2>/dev/null' EXIT
"$rbcal" library generate "$plan" --library "$dir/disk/lib" --threads 1 --quiet >"$dir/room.log" 2>&1 ||
  fail "with room the sweep failed: $(cat "$dir/room.log")"
echo "full disk: the sweep stopped, named it, filed nothing as failed; with room it finished"
