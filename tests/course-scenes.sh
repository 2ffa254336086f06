#!/bin/sh
# course-scenes.sh: every scene of the course's corpus loads, or fails only because a mesh is missing.
#
# Usage: tests/course-scenes.sh check|render RAYTRA [SCALE]
#   check   raytra --check on every scene file (fast: reads, does not render)
#   render  renders every scene at SCALE times its resolution (default 0.1), as PFM, and
#           also fails on a NaN or infinite pixel (the render loop's warning, or a
#           non-finite float in the image: tests/nonfinite.sh)
#
# The corpus is ../shared/course-scenes beside the repository (see its SOURCES.md);
# when it is not there the test says so and passes. Its fall2016-a folder uses the
# fall2016 convention, the other folders the lecture's. A scene whose mesh is
# absent must fail with exactly the missing-mesh message; new_obj.txt is an OBJ
# mesh, not a scene, and must be recognised as one.
set -u
[ $# -ge 2 ] || { echo "usage: $0 check|render RAYTRA [SCALE]" >&2; exit 2; }
mode=$1 raytra=$2 scale=${3:-0.1}
top=$(cd "$(dirname "$0")/.." && pwd)
corpus=$top/../shared/course-scenes
if [ ! -d "$corpus" ]; then
    echo "course-scenes: SKIPPED: $corpus does not exist (the course corpus is not beside this checkout)"
    exit 0
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

count=0 loaded=0 missing=0 failed=0
for scene in $(cd "$corpus" && find . \( -name '*.scn' -o -name '*.txt' \) | sort); do
    scene=${scene#./}
    count=$((count + 1))
    case $scene in fall2016*) convention=fall2016 ;; *) convention=lecture ;; esac
    if [ "$mode" = check ]; then
        "$raytra" --check --convention $convention "$corpus/$scene" >/dev/null 2>"$tmp/err"
    else
        "$raytra" -q -j 2 --scale "$scale" --convention $convention "$corpus/$scene" \
            "$tmp/out.pfm" 2>"$tmp/err"
    fi
    status=$?
    # What is left once warnings, notes and the missing-mesh report are set aside.
    grep -v -e 'warning: ' -e '^raytra: note: ' -e 'cannot find mesh' -e '^    /' -e '^    [^/]' \
        "$tmp/err" >"$tmp/rest"
    if [ "$scene" = spring2016-b/test/new_obj.txt ]; then
        if [ $status -eq 1 ] && grep -q 'this is an OBJ mesh' "$tmp/err"; then
            echo "ok   $scene: recognised as an OBJ mesh"
            continue
        fi
    elif grep -q 'NaN or infinite' "$tmp/err"; then
        :
    elif [ "$mode" = render ] && [ $status -eq 0 ] &&
        ! "$top/tests/nonfinite.sh" pfm "$tmp/out.pfm" >>"$tmp/err"; then
        :
    elif [ $status -eq 0 ] && [ ! -s "$tmp/rest" ]; then
        loaded=$((loaded + 1))
        continue
    elif [ $status -eq 1 ] && grep -q 'cannot find mesh' "$tmp/err" && [ ! -s "$tmp/rest" ]; then
        echo "ok   $scene: $(grep -o "cannot find mesh '[^']*'" "$tmp/err" | head -1)"
        missing=$((missing + 1))
        continue
    fi
    echo "FAIL $scene (exit status $status):"
    sed 's/^/    /' "$tmp/err"
    failed=$((failed + 1))
done
echo "course-scenes ($mode): $count scene files: $loaded fine, $missing with a missing mesh" \
    "reported, $failed failed"
[ $failed -eq 0 ]
