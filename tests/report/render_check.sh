#!/usr/bin/env bash
# Opens the validation report in headless Chromium and checks that it
# renders with its images:
#  1. a test-only copy of report.html (same directory, so the relative image
#     paths hold) gets a script that, on the load event, counts the <img>
#     elements and those with naturalWidth > 0; --dump-dom returns the DOM
#     with that count, which must equal the number of <img> in the report;
#  2. a control copy with one image path broken must be caught by the same
#     check (so the check can fail);
#  3. a screenshot of the report must not be blank (background below 97 %
#     of the pixels, many colours), and a screenshot of an empty page must
#     be judged blank by the same measure.
# usage: render_check.sh REPORT_DIR
set -euo pipefail
dir=$(cd "$1" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
html="$dir/report.html"
[ -s "$html" ] || { echo "FAIL: no $html"; exit 1; }
browser=$(command -v chromium || command -v chromium-browser || true)
[ -n "$browser" ] || { echo "FAIL: chromium not installed (scripts/install-deps.sh installs it)"; exit 1; }

profile=$(mktemp -d)
check="$dir/.render_check.html" control="$dir/.render_check_control.html" empty="$dir/.render_check_empty.html"
shot="$dir/.render_check.png" emptyshot="$dir/.render_check_empty.png"
trap 'rm -rf "$profile" "$check" "$control" "$empty" "$shot" "$emptyshot"' EXIT

chrome() {
  timeout 60 "$browser" --headless --disable-gpu --no-sandbox --no-first-run --disable-extensions \
    --user-data-dir="$profile" --allow-file-access-from-files "$@" 2>/dev/null
}

probe='<script>window.addEventListener("load",function(){var im=document.images,ok=0,bad=[];
for(var i=0;i<im.length;++i){if(im[i].complete&&im[i].naturalWidth>0)ok++;else bad.push(im[i].getAttribute("src"));}
var p=document.createElement("pre");p.id="render-check";p.textContent="RENDER images="+im.length+" loaded="+ok+" broken="+bad.join(",");
document.body.appendChild(p);});</script>'
inject() {  # $1 source, $2 destination: the probe just before </body>
  python3 -c 'import sys; s=open(sys.argv[1]).read(); open(sys.argv[2],"w").write(s.replace("</body>", sys.argv[3]+"</body>"))' \
    "$1" "$2" "$probe"
}
render_line() {
  chrome --virtual-time-budget=15000 --dump-dom "file://$1" | grep -o 'RENDER images=[0-9]* loaded=[0-9]* broken=[^<]*' || true
}

expected=$(grep -o '<img ' "$html" | wc -l)
[ "$expected" -gt 0 ] || { echo "FAIL: the report has no <img>"; exit 1; }
if grep -Eqi '(src|href)="(https?:|//)|<script|<link' "$html"; then
  echo "FAIL: report.html refers to external resources or has a script"; exit 1
fi

inject "$html" "$check"
line=$(render_line "$check")
echo "report: $line (expected $expected images)"
[ "$line" = "RENDER images=$expected loaded=$expected broken=" ] || { echo "FAIL: not every image loaded"; exit 1; }

first=$(grep -o '<img src="[^"]*"' "$html" | head -1 | sed 's/<img src="//; s/"$//')
sed "0,/<img src=\"$first\"/s//<img src=\"missing-$first\"/" "$html" > "$control.tmp"
inject "$control.tmp" "$control"; rm -f "$control.tmp"
line=$(render_line "$control")
echo "control with $first broken: $line"
[ "$line" = "RENDER images=$expected loaded=$((expected - 1)) broken=missing-$first" ] ||
  { echo "FAIL: the check did not catch a broken image"; exit 1; }

chrome --window-size=1000,1400 --virtual-time-budget=15000 --screenshot="$shot" "file://$html" >/dev/null
[ -s "$shot" ] || { echo "FAIL: no screenshot"; exit 1; }
read -r w h frac colours < <(python3 "$here/png_stats.py" "$shot")
echo "screenshot ${w}x${h}: non-background fraction $frac, $colours colours"
printf '<!DOCTYPE html><html><head><meta charset="utf-8"></head><body></body></html>\n' > "$empty"
chrome --window-size=1000,1400 --screenshot="$emptyshot" "file://$empty" >/dev/null
read -r _ _ efrac ecolours < <(python3 "$here/png_stats.py" "$emptyshot")
echo "empty page control: non-background fraction $efrac, $ecolours colours"
blank() { python3 -c 'import sys; sys.exit(0 if float(sys.argv[1]) < 0.03 or int(sys.argv[2]) < 50 else 1)' "$1" "$2"; }
blank "$efrac" "$ecolours" || { echo "FAIL: the blank-page control was not judged blank"; exit 1; }
if blank "$frac" "$colours"; then echo "FAIL: the report's screenshot is blank"; exit 1; fi
echo "PASS: report.html renders with all $expected images"
