#!/usr/bin/env bash
# report.html rendered by headless Chromium (Debian's chromium): the page loads from the
# report folder alone, its rendered DOM holds the headline table per sample with every
# method, the warnings list, the inline SVG plots (fit, posterior, predictive check per
# sample), the provenance and working links to the folder's files; the screenshot
# (report_html.png beside the folder) is written for a person to look at. Skipped (77)
# without chromium.
# Usage: report_html_render_test.sh REPORT_FOLDER
set -euo pipefail
folder=$(cd "$1" && pwd)
command -v chromium >/dev/null || { echo "SKIP: no chromium (Debian package chromium)"; exit 77; }
fail() { echo "FAIL: $*"; exit 1; }
render=(timeout 120 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --no-first-run
        --user-data-dir="$folder.chromium")
"${render[@]}" --dump-dom "file://$folder/report.html" > "$folder.dom.html" 2>/dev/null || fail "chromium could not load the page"
"${render[@]}" --window-size=1100,3200 --screenshot="$folder.png" "file://$folder/report.html" >/dev/null 2>&1 ||
  fail "chromium could not render the page"
rm -rf "$folder.chromium"
dom="$folder.dom.html"
grep -q "<h1>rbcal calibration report" "$dom" || fail "no title"
samples=$(grep -c "<h2>" "$dom")
[ "$samples" -ge 2 ] || fail "no sample section"
for method in "alpha method" "direct fit" "MCMC"; do
  [ "$(grep -c "<td>$method</td>" "$dom")" -ge 1 ] || fail "no row for $method"
done
svgs=$(grep -c "<svg" "$dom")
[ "$svgs" -ge 3 ] || fail "$svgs inline SVG plots"
grep -q "<h2>Provenance" "$dom" || fail "no provenance"
# With --compare (the synthetic report's), the joint posterior and the ratio in words.
if grep -q '"comparison"' "$folder/summary.json"; then
  grep -q "<h2>Joint posterior over the samples" "$dom" || fail "no joint posterior section"
  grep -q "probability that the ratio exceeds 1" "$dom" || fail "no comparison sentence"
fi
# Every link names a file of the folder.
for href in $(grep -o 'href="[^"#:]*"' "$dom" | sed 's/href="\(.*\)"/\1/' | sort -u); do
  [ -e "$folder/$href" ] || fail "link to a missing file: $href"
done
# A rendered page, not a blank one: PNG signature and some size.
[ "$(head -c 8 "$folder.png" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || fail "the screenshot is not a PNG"
[ "$(stat -c %s "$folder.png")" -gt 20000 ] || fail "the screenshot is nearly empty"
echo "PASS: rendered, $((samples - 1)) sample section(s), $svgs inline plots, links resolve; screenshot $folder.png"
