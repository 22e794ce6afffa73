#!/usr/bin/env bash
# A sample with more points than are fitted (100,000) is refused up front with the memory its
# likelihood would need, and the command exits 1 (it had ended in std::bad_alloc as a warning,
# exit 0, at 669,000 points).
# Usage: too_many_points_test.sh RBCAL WORK_DIR
set -uo pipefail
rbcal=$1 dir=$2
rm -rf "$dir" && mkdir -p "$dir"
awk 'BEGIN { print "sample,kind,phi,shear_rate_per_s,viscosity_mPa_s,sd_mPa_s,n";
             print "big,plasma_assumed,0,0,1.45,0.2,1";
             for (i = 0; i < 50001; i++) { rate = 40 * 10 ^ (i / 50001 * 1.4);
               printf "big,suspension,0.35,%.6f,%.5f,0.2,3\n", rate, 4.0 * (rate / 40) ^ -0.05;
               printf "big,suspension,0.45,%.6f,%.5f,0.27,3\n", rate, 5.5 * (rate / 40) ^ -0.05 } }' >"$dir/big.csv"
"$rbcal" calibrate "$dir/big.csv" --no-plots -o "$dir/report" >"$dir/log" 2>&1
status=$?
[ "$status" -eq 1 ] || { echo "FAIL: exit $status"; cat "$dir/log"; exit 1; }
grep -q "100002 points to fit: the likelihood would need about .* GiB (.* GiB available), and at most 100000 points are fitted" "$dir/log" || { echo "FAIL: no refusal"; cat "$dir/log"; exit 1; }
echo "100002 points refused up front with the memory they would need; exit 1"
