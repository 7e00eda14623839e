#!/usr/bin/env bash
# `haze sheet -o SHEET.html`: the demo's sheet as one HTML page, loaded from file:// by headless
# Chromium (not by haze's writer): the page loads with no error event, holds one <img> per cue
# and every one decodes (naturalWidth > 0; counted by a script this test puts into a copy of the
# page, since the sheet itself holds none), each thumbnail is the cue's `haze render` (PSNR),
# every cue's number, label and change lines and the patch in universe.address order are in the
# page's text, and a cue label written as markup stays text (no extra image, no script run).
# Skipped (exit 77) where Chromium is not installed (tools/install-deps.sh installs it).
set -uo pipefail
haze=$1; root=$2
browser=$(command -v chromium || command -v chromium-browser) ||
  { echo "skipped: needs chromium (Debian package chromium, in tools/install-deps.sh)"; exit 77; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0; failed=0
check() { if eval "$2"; then pass=$((pass + 1)); else failed=$((failed + 1)); echo "FAIL: $1"; fi; }

cp -r "$root/examples/demo/." "$tmp/demo/"
show="$tmp/demo/demo.haze.json"
# A label that would be markup if it were not escaped: an image whose error handler marks the
# page, and a script that would run if the row's cell could be closed.
python3 - "$show" <<'PY'
import json, sys
show = json.load(open(sys.argv[1]))
show["cue_lists"][0]["cues"][0]["label"] = ("Preset <img src=x onerror=\"document.body.dataset.pwned=1\"> & "
    "</td></tr></table><script>document.body.dataset.pwned=2</script>'\"")
json.dump(show, open(sys.argv[1], "w"), indent=1)
PY
"$haze" sheet "$show" --quality draft -o "$tmp/sheet.html" >/dev/null 2>"$tmp/err" ||
  { echo "FAIL: haze sheet: $(cat "$tmp/err")"; exit 1; }
check "the sheet holds no script of its own" '! grep -qi "<script" "$tmp/sheet.html"'

# The probe, placed first in <head> of a copy so that its capturing listener sees every error
# event (an image that fails to decode fires one) before the body is parsed.
probe='<script>var haze_errors = 0; addEventListener("error", function () { haze_errors++; }, true);
addEventListener("load", function () {
  var decoded = Array.prototype.filter.call(document.images, function (i) { return i.complete && i.naturalWidth > 0; });
  document.documentElement.dataset.images = document.images.length;
  document.documentElement.dataset.decoded = decoded.length;
  document.documentElement.dataset.errors = haze_errors;
  document.documentElement.dataset.loaded = "yes";
});</script>'
python3 - "$tmp/sheet.html" "$tmp/probed.html" "$probe" <<'PY'
import sys
page = open(sys.argv[1], encoding="utf-8").read()
assert page.count("<head>") == 1, "one <head> in the sheet"
open(sys.argv[2], "w", encoding="utf-8").write(page.replace("<head>", "<head>" + sys.argv[3], 1))
PY
# file:// only, no network: a profile of its own in $tmp, background services off, every host
# name unresolvable.
"$browser" --headless --disable-gpu --no-sandbox --user-data-dir="$tmp/profile" --no-first-run \
  --disable-background-networking --disable-component-update --disable-sync --host-resolver-rules="MAP * ~NOTFOUND" \
  --virtual-time-budget=10000 --dump-dom "file://$tmp/probed.html" >"$tmp/dom.html" 2>"$tmp/chromium.log"
rc=$?
check "chromium ran (exit $rc)" '[ $rc -eq 0 ]'
[ $rc -eq 0 ] || tail -5 "$tmp/chromium.log"

cues=$(python3 -c 'import json,sys; print(len(json.load(open(sys.argv[1]))["cue_lists"][0]["cues"]))' "$show")
attr() { grep -o "data-$1=\"[^\"]*\"" "$tmp/dom.html" | head -1 | cut -d'"' -f2; }
check "the page loaded (load event ran)" '[ "$(attr loaded)" = yes ]'
check "no error event while loading ($(attr errors))" '[ "$(attr errors)" = 0 ]'
check "one image per cue: $(attr images) images for $cues cues" '[ "$(attr images)" = "$cues" ]'
check "every image decodes: $(attr decoded) of $cues" '[ "$(attr decoded)" = "$cues" ]'
check "the markup in a label did not run" '! grep -q "data-pwned" "$tmp/dom.html"'

# The page as Chromium parsed it: per cue row its texts and thumbnails; the patch rows.
python3 - "$tmp/dom.html" "$show" "$tmp" <<'PY' || failed=$((failed + 1))
import base64, html.parser, json, sys
dom, show, tmp = sys.argv[1], json.load(open(sys.argv[2])), sys.argv[3]

class Rows(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.table, self.rows, self.cell = None, {"cues": [], "patch": []}, None
    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "table": self.table = a.get("class")
        if tag == "tr" and self.table in self.rows and (self.table == "patch" or a.get("class") == "cue"):
            self.rows[self.table].append({"cells": [], "images": []})
        if tag == "td" and self.table in self.rows and self.rows[self.table]: self.rows[self.table][-1]["cells"].append("")
        if tag in ("div", "li") and self.table == "cues" and self.rows["cues"]: self.rows["cues"][-1]["cells"][-1] += "\n"
        if tag == "img" and self.rows["cues"]: self.rows["cues"][-1]["images"].append(a.get("src", ""))
        if tag == "td": self.cell = True
    def handle_endtag(self, tag):
        if tag == "table": self.table = None
        if tag == "td": self.cell = None
    def handle_data(self, data):
        if self.cell and self.table in self.rows and self.rows[self.table] and self.rows[self.table][-1]["cells"]:
            self.rows[self.table][-1]["cells"][-1] += data

p = Rows(); p.feed(open(dom, encoding="utf-8").read())
ok = True
def check(what, good):
    global ok
    if not good: print("FAIL: " + what); ok = False
cues = show["cue_lists"][0]["cues"]
check(f"{len(p.rows['cues'])} cue rows for {len(cues)} cues", len(p.rows["cues"]) == len(cues))
for i, (cue, row) in enumerate(zip(cues, p.rows["cues"])):
    first = [l for l in row["cells"][0].split("\n") if l]
    check(f"cue {cue['number']}: number and label {first[:2]}", first[:2] == [cue["number"], cue["label"]])
    changes = [l for l in row["cells"][-1].split("\n") if l]
    check(f"cue {cue['number']}: change lines {changes}", len(changes) >= 1 and all(l[0].isdigit() or l == "no change" for l in changes))
    check(f"cue {cue['number']}: one thumbnail", len(row["images"]) == 1)
    if row["images"]:
        png = base64.b64decode(row["images"][0].split(",", 1)[1])
        open(f"{tmp}/thumb{i}.png", "wb").write(png)
p.rows["patch"] = [r for r in p.rows["patch"] if len(r["cells"]) == 5]  # not the heading row (th)
patch = [(int(r["cells"][3]), int(r["cells"][4])) for r in p.rows["patch"] if r["cells"][4].isdigit()]
check(f"patch: {len(patch)} patched fixtures in universe.address order", len(patch) == 12 and patch == sorted(patch))
check("patch: 101 Spot 1 first", p.rows["patch"][0]["cells"][:3] == ["101 Spot 1", "spot", "Standard"])
# Cue 2's washes: the same range line as the PDF sheet's (tests/cli/sheet_desk.sh).
check("cue 2's washes as one range", any(l.startswith("201-204 LED Wash 19 @ 35 %, color #") for l in p.rows["cues"][1]["cells"][-1].split("\n")))
print("page text: " + ("ok" if ok else "FAIL"))
sys.exit(0 if ok else 1)
PY

# Each thumbnail is the cue's render: the PNG is lossless, so only the renderer's own
# frame-to-frame jitter could separate them (identical on llvmpipe, PSNR inf; the test allows
# > 35 dB, and wants 10 dB more than against the next cue's render, 7-14 dB).
numbers=$(python3 -c 'import json,sys; [print(c["number"]) for c in json.load(open(sys.argv[1]))["cue_lists"][0]["cues"]]' "$show")
psnr() { compare -metric PSNR "$1" "$2" null: 2>&1 | cut -d' ' -f1; }
i=0
for n in $numbers; do
  "$haze" render "$show" --cue "$n" --width 320 --height 180 --quality draft -o "$tmp/render$i.png" 2>/dev/null
  i=$((i + 1))
done
for ((i = 0; i < cues; i++)); do
  j=$(( (i + 1) % cues ))
  p=$(psnr "$tmp/thumb$i.png" "$tmp/render$i.png"); q=$(psnr "$tmp/thumb$i.png" "$tmp/render$j.png")
  echo "cue index $i: thumbnail vs its render $p dB, vs cue index $j's $q dB"
  check "cue index $i: thumbnail is its render (PSNR $p dB > 35) and not cue index $j's ($q dB)" \
    'awk -v p="$p" -v q="$q" "BEGIN { if (p == \"inf\") p = 99; exit !(p > 35 && q < p - 10) }"'
done

expect_error() {  # name, expected text, command...
  local name=$1 want=$2; shift 2
  "$@" >"$tmp/out" 2>"$tmp/err"; local rc=$?
  if [ $rc -ne 0 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] && grep -q -- "$want" "$tmp/err"; then pass=$((pass + 1))
  else failed=$((failed + 1)); echo "FAIL $name: rc=$rc:"; cat "$tmp/err"; fi
}
touch "$tmp/not-a-folder"
expect_error unwritable "not-a-folder/s.html" "$haze" sheet "$show" --quality draft -o "$tmp/not-a-folder/s.html"
expect_error not-html "HTML" "$haze" sheet "$show" -o "$tmp/s.htm"
check "no sheet left by the failures" '[ ! -e "$tmp/s.htm" ] && ! compgen -G "$tmp/.*tmp*" >/dev/null'
echo "$pass passed, $failed failed"
[ $failed -eq 0 ]
