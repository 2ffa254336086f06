#!/bin/sh
# grade-report.sh: opens grader/grade's report of a made-up class in headless Chromium and
# checks what an instructor relies on; with --figure, keeps a screenshot of it.
#
# Usage: grader/tests/grade-report.sh GRADE RAYTRA [--figure PNG]   (make -C grader test;
#        make -C grader report-figure writes docs/figures/grading-report.png)
#   GRADE   the grader, grader/build/grade;  RAYTRA  part 1.1's program
# In the page: every image loads, no error is raised, and a failing scene's line closes and
# opens again on a click, showing its heat map. Skips (exit 0, said) without Chromium.
set -u
[ $# -eq 2 ] || [ $# -eq 4 ] || { echo "usage: $0 GRADE RAYTRA [--figure PNG]" >&2; exit 2; }
case $1 in /*) grade=$1 ;; *) grade=$(pwd)/$1 ;; esac
case $2 in /*) raytra=$2 ;; *) raytra=$(pwd)/$2 ;; esac
figure=""
[ $# -eq 4 ] && case $4 in /*) figure=$4 ;; *) figure=$(pwd)/$4 ;; esac
top=$(cd "$(dirname "$0")/../.." && pwd)
# $CHROMIUM, or chromium, chromium-browser or google-chrome on PATH (common/deps.sh says which).
if ! chromium=$("$top/common/deps.sh" chromium); then
    echo "grade-report.sh: SKIPPED: no Chromium (\$CHROMIUM, or chromium, chromium-browser or" \
        "google-chrome on PATH; common/deps.sh test installs it)"
    exit 0
fi
refs=$top/milestones/1.1-spheres-red/references
tmp=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
cd "$tmp" || exit 2

# The class: images right, one wrong, one missing; programs right, one wrong, one that
# crashes, one that hangs on a scene, one that does not build.
for s in alan.turing edsger.dijkstra john.backus ken.thompson; do
    mkdir -p "class/$s" && cp "$refs"/*.png "class/$s/"
done
sed 's/^s 25 -5 -90   10$/s 25.5 -5 -90   10/' "$top/scenes/spheres-three.scn" >moved.scn
"$raytra" -q moved.scn class/edsger.dijkstra/spheres-three.png 2>/dev/null
rm class/john.backus/spheres-grid-wide.png
# Makes submission $1 a program from the shell script on stdin, which runs the model answer
# and the moved scene it carries (the sandbox shows it nothing outside its folder) as $m
# and $moved.
program() {
    mkdir -p "class/$1" && cat >"class/$1/raytra.sh" && cp "$raytra" "class/$1/model" &&
        cp moved.scn "class/$1/" || exit 2
    printf 'raytra: raytra.sh\n\tcp raytra.sh raytra\n\tchmod +x raytra\n' >"class/$1/Makefile"
}
# shellcheck disable=SC2016 # the students' scripts
{
    m='"$(dirname "$0")/model"' moved='"$(dirname "$0")/moved.scn"'
    printf '#!/bin/sh\nexec %s "$@"\n' "$m" | program margaret.hamilton
    printf '#!/bin/sh\ncase $1 in *spheres-three*) exec %s %s "$2" ;; esac\nexec %s "$@"\n' \
        "$m" "$moved" "$m" | program ada.lovelace
    printf '#!/bin/sh\nkill -SEGV $$\n' | program barbara.liskov
    printf '#!/bin/sh\ncase $1 in *demo*) exec sleep 30 ;; esac\nexec %s "$@"\n' "$m" |
        program dennis.ritchie
}
mkdir -p class/grace.hopper && printf 'raytra:\n\tcc -o raytra missing.c\n' >class/grace.hopper/Makefile
"$grade" -q --time-limit 2 --out out 1.1 class 2>grade.txt || { cat grade.txt; exit 1; }

# The checks, run in the page once it has loaded; the answer is a <pre id="result"> that
# --dump-dom prints.
cat >check.js <<'EOF'
var errors = [];
window.addEventListener('error', function (e) { errors.push(e.message || 'a resource failed: ' + (e.target.src || e.target.href)); }, true);
function loads(url) {
  return new Promise(function (done) { var i = new Image(); i.onload = function () { done(i.naturalWidth > 0); }; i.onerror = function () { done(false); }; i.src = url; });
}
window.addEventListener('load', function () {
  var out = [], imgs = Array.prototype.slice.call(document.images), backgrounds = [];
  imgs.forEach(function (i) { if (!i.complete || i.naturalWidth === 0) out.push('broken image: ' + i.alt); });
  document.querySelectorAll('.pic').forEach(function (e) {
    var m = /url\("?(data:[^")]*)/.exec(getComputedStyle(e).backgroundImage);
    if (m && backgrounds.indexOf(m[1]) < 0) backgrounds.push(m[1]);
  });
  var scene = document.querySelector('details.scene[open] img[alt="heat map of the differences"]');
  var details = scene && scene.closest('details.scene'), summary = details && details.querySelector('summary');
  if (!summary) out.push('no failing scene with a heat map');
  else {
    summary.click();
    var hidden = !details.open && !scene.checkVisibility();
    summary.click();
    out.push(hidden && details.open && scene.checkVisibility() && scene.offsetWidth > 0 && scene.naturalWidth > 0
             ? 'click: the failing scene closes and opens, its heat map shown ' + scene.offsetWidth + ' px wide'
             : 'click: the failing scene does not open and close with its heat map');
  }
  Promise.all(backgrounds.map(loads)).then(function (ok) {
    out.push('images: ' + imgs.length + ' pictures and ' + backgrounds.length + ' reference backgrounds, ' +
             ok.filter(function (x) { return !x; }).length + ' broken backgrounds');
    out.push('errors: ' + errors.length + (errors.length ? ' (' + errors.join('; ') + ')' : ''));
    var pre = document.createElement('pre'); pre.id = 'result'; pre.textContent = out.join('\n');
    document.body.appendChild(pre);
  });
});
EOF
{
    sed -n '1,/<head>/p' out/report.html
    printf '<script>\n' && cat check.js && printf '</script>\n'
    sed '1,/<head>/d' out/report.html
} >checked.html

# Runs Chromium headless on file $1 with the options that follow, in a fresh profile.
browse() {
    page=$1
    shift
    timeout 120 "$chromium" --headless --no-sandbox --disable-gpu --no-first-run \
        --disable-background-networking --disable-component-update --disable-sync \
        --user-data-dir="$(mktemp -d "$tmp/profile.XXXXXX")" "$@" "file://$tmp/$page" 2>>chromium.log
}
browse checked.html --virtual-time-budget=10000 --dump-dom >dom.html
sed -n '/<pre id="result">/,/<\/pre>/p' dom.html | sed 's/<[^>]*>//g' >result.txt

failures=0
# Checks that the page's answer has a line matching the pattern $1.
expect() {
    if grep -qE -- "$1" result.txt; then echo "ok   $1"; else echo "FAIL $1"; failures=$((failures + 1)); fi
}
expect '^images: [1-9][0-9]* pictures and [1-9][0-9]* reference backgrounds, 0 broken backgrounds$'
expect '^click: the failing scene closes and opens, its heat map shown [1-9][0-9]* px wide$'
expect '^errors: 0$'
if grep -q 'broken image' result.txt; then echo "FAIL: $(grep 'broken image' result.txt)"; failures=$((failures + 1)); fi
[ -s result.txt ] || { echo "FAIL: no answer from the page"; tail -5 chromium.log; failures=$((failures + 1)); }

if [ -n "$figure" ] && [ "$failures" -eq 0 ]; then
    browse out/report.html --hide-scrollbars --window-size=1280,1280 --screenshot="$tmp/shot.png" >/dev/null &&
        [ -s shot.png ] && cp shot.png "$figure" && echo "grade-report.sh: wrote $figure" ||
        { echo "FAIL: no screenshot"; failures=$((failures + 1)); }
fi
if [ "$failures" -ne 0 ]; then
    echo "grade-report.sh: $failures checks of the report in Chromium failed"
    exit 1
fi
echo "grade-report.sh: the report works in Chromium"
