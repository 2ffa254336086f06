#!/bin/sh
# same-box-tests.sh: --view box-tests draws in this part exactly what it draws in part 1.4.
#
# Usage: tests/same-box-tests.sh RAYTRA RAYTRA_1_4 MODES
#   RAYTRA      the part's program (1.5 or 1.6), which traces through part 1.4's Accel
#   RAYTRA_1_4  part 1.4's program
#   MODES       the modes RAYTRA takes as --mode ("0 1 2 3" for part 1.5), or "-" for
#               a part that always uses the BVH, mode 3 (part 1.6)
#
# The same geometry gives the same camera rays the same tests: each scene is drawn in
# view box-tests by both programs, as PFM (the larger ones at a quarter of their size);
# the files must be the same byte for byte, and the scale they print (the most tests of
# any pixel) the same. On scenes/exercises/1.4-four-spheres.scn the counts are worked out
# by hand (docs/exercises-answers.md, 1.4.1): at most 6 tests with the BVH, 4 in modes 0
# and 1.
set -u
[ $# -eq 3 ] || { echo "usage: $0 RAYTRA RAYTRA_1_4 MODES" >&2; exit 2; }
raytra=$1 part14=$2 modes=$3
top=$(cd "$(dirname "$0")/../../.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

count=0 failed=0
# Draws scene $1 at --scale $2 in mode $3 ("-": this part's only one, 3 in part 1.4)
# with both programs; checks they agree, and when $4 is given that the scale line says
# $4 tests.
compare() {
    scene=$1 scale=$2 mode=$3 want=${4:-}
    count=$((count + 1))
    this_mode="--mode $mode" part14_mode="--mode $mode"
    if [ "$mode" = - ]; then this_mode='' part14_mode="--mode 3"; fi
    # shellcheck disable=SC2086 # the modes are words by design
    if ! "$part14" --scale "$scale" --view box-tests $part14_mode "$top/scenes/$scene" "$tmp/a.pfm" \
        >/dev/null 2>"$tmp/a.txt" ||
        ! "$raytra" --scale "$scale" --view box-tests $this_mode "$top/scenes/$scene" "$tmp/b.pfm" \
            >/dev/null 2>"$tmp/b.txt"; then
        echo "FAIL $scene mode $mode: a render failed:"
        sed 's/^/    /' "$tmp/a.txt" "$tmp/b.txt"
        failed=$((failed + 1))
        return
    fi
    a=$(grep 'view box-tests' "$tmp/a.txt") b=$(grep 'view box-tests' "$tmp/b.txt")
    if ! cmp -s "$tmp/a.pfm" "$tmp/b.pfm" || [ -z "$a" ] || [ "$a" != "$b" ]; then
        echo "FAIL $scene mode $mode: box-tests differs from part 1.4's ('$b' against '$a')"
        failed=$((failed + 1))
    elif [ -n "$want" ] && ! echo "$b" | grep -q "white $want tests"; then
        echo "FAIL $scene mode $mode: '$b', where the answer worked out by hand is $want tests"
        failed=$((failed + 1))
    fi
}

for mode in $([ "$modes" = - ] && echo - || echo "$modes"); do
    case $mode in 0 | 1) want=4 ;; *) want=6 ;; esac
    compare exercises/1.4-four-spheres.scn 1 "$mode" "$want"
    for scene in bvh-torus.scn demo.scn; do
        compare "$scene" 0.25 "$mode"
    done
done

if [ "$failed" -gt 0 ]; then
    echo "same-box-tests: $failed of $count views differ"
    exit 1
fi
echo "same-box-tests: $count box-tests views the same as part 1.4's"
