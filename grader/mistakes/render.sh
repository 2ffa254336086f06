#!/bin/sh
# render.sh: renders each graded scene of a part with each of its known mistakes, for the grader's diagnosis.
#
# Usage: grader/mistakes/render.sh PART [BUILD]
#   PART   a part's folder name, 1.4-bvh, whose known mistakes grader/mistakes/PART.txt lists
#   BUILD  the build's folder name, build (default) or build-sanitize
# Writes grader/BUILD/mistakes/PART/NAME/IMAGE for each mistake NAME and each graded line of
# milestones/PART/references/renders.txt (illustrations, !IMAGE, are not graded), rendered as
# the reference was, by the mistake's program (built before: make -C grader mistakes). The
# grader compares a failing image with these (grader/docs/diagnosis.md). A mistake's renders
# are kept while its program's checksum is the one they were made by (NAME/.program).
# Exit status 1 when a program is missing or fails.
case ${1:-} in -h | --help | '') sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
set -u
top=$(cd "$(dirname "$0")/../.." && pwd)
part=$1 build=${2:-build}
catalog=$top/grader/mistakes/$part.txt
renders=$top/milestones/$part/references/renders.txt
[ -f "$catalog" ] || { echo "render.sh: no $catalog" >&2; exit 1; }
[ -f "$renders" ] || { echo "render.sh: no $renders" >&2; exit 1; }
failed=0
while read -r name program _; do
    case $name in '' | '#'*) continue ;; esac
    program=$top/$(echo "$program" | sed "s|\\\$BUILD|$build|")
    [ -x "$program" ] || { echo "render.sh: $name: no program $program" >&2; failed=1; continue; }
    out=$top/grader/$build/mistakes/$part/$name
    sum=$(cksum <"$program")
    [ "$(cat "$out/.program" 2>/dev/null)" = "$sum" ] && continue
    rm -rf "$out" && mkdir -p "$out" || exit 1
    while read -r image scene options; do
        case $image in '' | '#'* | '!'*) continue ;; esac
        image=${image#\~}
        image=${image%%[=>]*}
        # shellcheck disable=SC2086 # the options are words by design
        "$program" -q "$top/$scene" "$out/$image" $options </dev/null 2>"$out/${image%.*}.log" ||
            { echo "render.sh: $name failed on $image (its output: $out/${image%.*}.log)" >&2; failed=1; }
    done <"$renders"
    [ $failed -eq 0 ] && echo "$sum" >"$out/.program"
done <"$catalog"
exit $failed
