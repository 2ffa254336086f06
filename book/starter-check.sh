#!/bin/sh
# starter-check.sh: a starter's `make check`: runs the part's unit tests, renders its reference scenes, compares them.
#
# Usage: book/starter-check.sh PART_DIR RAYTRA TEST_DIR IMGDIFF OUT
#
# Makes OUT afresh. Runs every test program in TEST_DIR, each in OUT/tests/NAME; then
# renders each line of PART_DIR/references/renders.txt (IMAGE SCENE [arguments],
# SCENE from the top of the starter) into OUT/IMAGE, compares it with the
# reference by imgdiff's default tolerances and writes its heat map to
# OUT/NAME.heat.png and imgdiff's figures to OUT/NAME.diff.txt; a render that runs
# longer than RENDER_SECONDS (default 120) fails. Exit status 0
# when every test passes and every image matches, 1 otherwise.
case ${1:-} in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
set -u
[ $# -eq 5 ] || { echo "usage: $0 PART_DIR RAYTRA TEST_DIR IMGDIFF OUT" >&2; exit 2; }
top=$(cd "$(dirname "$0")/.." && pwd) || exit 2
absolute() { case $1 in /*) echo "$1" ;; *) echo "$PWD/$1" ;; esac; }
part_dir=$(absolute "$1") raytra=$(absolute "$2") test_dir=$(absolute "$3")
imgdiff=$(absolute "$4") out=$5
refdir=$part_dir/references
case $out in '' | / | . | ..) echo "starter-check: OUT must be a folder of its own" >&2; exit 2 ;; esac
trap 'exit 130' INT TERM

# OUT is made afresh: what an earlier check left there goes.
rm -rf "$out" && mkdir -p "$out/tests" || exit 2

# The unit tests, each in OUT/tests/NAME, where it may write files; Check prints
# each failing assertion with its file and line.
tests=0 tests_failed=0
for t in "$test_dir"/test_*; do
    [ -f "$t" ] && [ -x "$t" ] || continue
    tests=$((tests + 1))
    echo "== unit test ${t##*/}"
    mkdir "$out/tests/${t##*/}" || exit 2
    if ! (cd "$out/tests/${t##*/}" && "$t" </dev/null); then
        echo "FAIL ${t##*/} (the files it wrote are in $out/tests/${t##*/})"
        tests_failed=$((tests_failed + 1))
    fi
done

# The images: each render, its comparison and its heat map. A render that runs past
# RENDER_SECONDS (default 120) is stopped, when coreutils' timeout is there to do it.
limit=
command -v timeout >/dev/null 2>&1 && limit="timeout ${RENDER_SECONDS:-120}"
echo "== images: renders and heat maps go to $out/"
images=0 images_failed=0 hint=''
while read -r image scene options; do
    # "#? TEXT" says what a failure of the next line means; it is told with the failure.
    case $image in '#?') hint="$scene $options" && continue ;; esac
    # An illustration (!IMAGE, grader/docs/references.md) is raytra's own picture, not graded.
    case $image in '' | '#'*) continue ;; '!'*) hint='' && continue ;; esac
    # ~IMAGE: a Monte Carlo render, judged against its statistical reference
    # (grader/docs/statistics.md).
    ref=$refdir/$image
    case $image in '~'*) image=${image#\~} ref=$refdir/${image%.*}.stats.exr ;; esac
    # IMAGE=OTHER: matches OTHER's reference, and equals this program's own OTHER, an
    # earlier line, pixel for pixel; IMAGE>MASK: drawn wherever the reference MASK is
    # drawn (grader/docs/references.md).
    how='' own=''
    case $image in
    *'='*) ref=$refdir/${image#*=} own=$out/${image#*=} image=${image%%=*} ;;
    *'>'*) how=--cover ref=$refdir/${image#*>} image=${image%%>*} ;;
    esac
    images=$((images + 1))
    name=${image%.*}
    # shellcheck disable=SC2086 # the options, and $how, are words by design
    if ! $limit "$raytra" -q "$top/$scene" "$out/$image" $options </dev/null 2>"$out/$name.log"; then
        echo "FAIL $image: raytra failed or ran too long on $scene (its output: $out/$name.log):"
        tail -n 5 "$out/$name.log" | sed 's/^/    /'
        images_failed=$((images_failed + 1))
    elif "$imgdiff" $how --diff "$out/$name.heat.png" "$ref" "$out/$image" \
        >"$out/$name.diff.txt" 2>&1 && { [ -z "$own" ] || "$imgdiff" --threshold 0 --allow 0 \
        --diff "$out/$name.heat.png" "$own" "$out/$image" >"$out/$name.diff.txt" 2>&1; }; then
        echo "ok   $image"
    else
        echo "FAIL $image: $(tail -n 1 "$out/$name.diff.txt" | sed 's/^FAIL: //')${own:+" (it must equal this program's own ${own##*/} pixel for pixel)"}"
        [ -n "$hint" ] && echo "     what it means: $hint"
        [ -f "$out/$name.heat.png" ] && echo "     heat map: $out/$name.heat.png"
        images_failed=$((images_failed + 1))
    fi
    hint=''
done <"$refdir/renders.txt"

echo "unit tests: $((tests - tests_failed)) of $tests programs pass"
echo "images: $((images - images_failed)) of $images match their references"
if [ $tests_failed -eq 0 ] && [ $images_failed -eq 0 ]; then
    echo "make check: every test passes"
else
    echo "make check: FAILED"
    exit 1
fi
