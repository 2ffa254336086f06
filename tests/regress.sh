#!/bin/sh
# regress.sh: renders a part's reference scenes and compares them with the committed images.
#
# Usage: tests/regress.sh check|update RAYTRA IMGDIFF REFDIR
#
# REFDIR holds the reference images and renders.txt, which says how each was made,
# one image a line:   IMAGE  SCENE  [arguments...]
# with SCENE relative to the top of the repository; the arguments (a part's own
# positional arguments, then raytra options) follow SCENE and OUTPUT on the command line.
# An IMAGE written !IMAGE is an illustration, which grader/grade does not grade; it is a
# reference all the same. An IMAGE written ~IMAGE is a Monte Carlo render graded by
# statistics: beside IMAGE (raytra's render with its default seed), REFDIR holds
# NAME.stats.exr, its statistical reference (grader/docs/statistics.md), made from MCREF_RENDERS
# (default 64) renders with seeds 1000, 1001, ...
# IMAGE=OTHER (graded against the program's own OTHER) has OTHER's reference, which
# update leaves as it is; IMAGE>MASK (graded by coverage of MASK) has IMAGE's own.
#   check   renders each scene with 2 threads and compares it with IMAGE, using
#           imgdiff's default tolerances; renders it again with 1 thread and checks
#           that the two files are byte for byte the same; for ~IMAGE, also judges the
#           render against NAME.stats.exr, which it must pass.
#   update  renders each scene, prints imgdiff's comparison with the current image,
#           then replaces it (make references); for ~IMAGE, makes NAME.stats.exr anew
#           (compare/mcref.sh, with mcstats beside IMGDIFF) and judges the render against it.
set -u
[ $# -eq 4 ] || { echo "usage: $0 check|update RAYTRA IMGDIFF REFDIR" >&2; exit 2; }
mode=$1 raytra=$2 imgdiff=$3 refdir=$4
top=$(cd "$(dirname "$0")/.." && pwd)
list=$refdir/renders.txt
[ -f "$list" ] || { echo "regress.sh: no $list" >&2; exit 2; }
tmp=$(mktemp -d)
beat=
trap 'rm -rf "$tmp"; [ -z "$beat" ] || kill "$beat" 2>/dev/null' EXIT
trap 'exit 130' INT TERM

# Runs a command; while it runs, says every 5 s how long the render of $image has taken,
# so that a long one (minutes under the sanitizers) is not a silent one. The beat stops
# when its file goes, should the kill reach it before its shell is ready for it.
beats=0
beating() {
    beats=$((beats + 1))
    alive=$tmp/beating-$beats
    : >"$alive"
    (begun=$(date +%s)
     while sleep 5 && [ -e "$alive" ]; do
         echo "     ... $image: $(($(date +%s) - begun)) s"
     done) &
    beat=$!
    "$@"
    status=$?
    rm -f "$alive"
    kill "$beat" 2>/dev/null
    beat=
    return $status
}

failed=0
count=0
while read -r image scene options; do
    case $image in '' | '#'*) continue ;; esac
    stats=
    case $image in '~'*) image=${image#\~} stats=$refdir/${image%.*}.stats.exr ;; esac
    image=${image#!}
    image=${image%%>*}
    ref=${image#*=}
    image=${image%%=*}
    count=$((count + 1))
    two=$tmp/two-$image
    one=$tmp/one-$image
    # shellcheck disable=SC2086 # options are words by design
    if ! beating "$raytra" -q -j 2 "$top/$scene" "$two" $options 2>"$tmp/err"; then
        echo "FAIL $image: raytra failed on $scene:"
        sed 's/^/    /' "$tmp/err"
        failed=$((failed + 1))
        continue
    fi
    if [ "$mode" = update ] && [ "$ref" != "$image" ]; then
        echo "== $image: the new render against $ref, its reference (kept)"
        "$imgdiff" "$refdir/$ref" "$two" | sed 's/^/    /'
        continue
    fi
    if [ "$mode" = update ]; then
        if [ -f "$refdir/$image" ]; then
            echo "== $image: the new render against the old one"
            "$imgdiff" "$refdir/$image" "$two" | sed 's/^/    /'
        else
            echo "== $image: new"
        fi
        cp "$two" "$refdir/$image"
        if [ -n "$stats" ]; then
            echo "== ${stats##*/}: ${MCREF_RENDERS:-64} renders with independent seeds"
            # shellcheck disable=SC2086
            "$top/compare/mcref.sh" "$raytra" "$(dirname "$imgdiff")/mcstats" "$stats" \
                "$top/$scene" "${MCREF_RENDERS:-64}" 1000 $options || exit 1
            "$imgdiff" "$stats" "$two" | sed 's/^/    /'
        fi
        continue
    fi
    # shellcheck disable=SC2086
    beating "$raytra" -q -j 1 "$top/$scene" "$one" $options 2>/dev/null
    if ! cmp -s "$one" "$two"; then
        echo "FAIL $image: 1 and 2 threads give different files"
        failed=$((failed + 1))
    elif [ ! -f "$refdir/$ref" ]; then
        echo "FAIL $image: no reference image (make references creates it)"
        failed=$((failed + 1))
    elif ! "$imgdiff" "$refdir/$ref" "$two" >"$tmp/diff" 2>&1; then
        echo "FAIL $image: differs from the reference:"
        sed 's/^/    /' "$tmp/diff"
        failed=$((failed + 1))
    elif [ -n "$stats" ] && ! "$imgdiff" "$stats" "$two" >"$tmp/diff" 2>&1; then
        echo "FAIL $image: does not pass its statistical reference ${stats##*/}:"
        sed 's/^/    /' "$tmp/diff"
        failed=$((failed + 1))
    else
        echo "ok   $image"
    fi
done <"$list"

if [ "$mode" = check ]; then
    echo "$((count - failed)) of $count reference images match"
    [ "$failed" -eq 0 ]
fi
