#!/bin/sh
# nonfinite.sh: no NaN or infinite value reaches any pixel of a rendered image.
#
# Usage: tests/nonfinite.sh pfm FILE...
#        tests/nonfinite.sh render RAYTRA REFDIR
#   pfm     checks that every float of each PFM file is finite
#   render  renders, as PFM, every scene of REFDIR/renders.txt with its options, every
#           scene of scenes/ with none, and the brightest scene the limits allow (made
#           here: 2000 point lights of 1e12 a millionth of a unit from a mirror floor
#           under a mirror ceiling, fall2016's 1/r^2, the largest ambient, directional
#           and area lights, at the largest --max-depth the part takes), and checks that
#           raytra succeeds, does not warn that pixels came out NaN or infinite (the
#           render loop writes such pixels magenta, so the floats alone cannot show
#           them), and that every float is finite
set -u

# Prints how many floats of PFM file $1 are NaN or infinite; false when there are any.
# PFM floats from raytra are little-endian (a negative scale), read here as 32-bit words
# in that order whatever the host's: a float is not finite when its eight exponent bits
# are all ones, that is its word in hex starts 7f or ff and then a digit of 8 or more.
count_nonfinite() {
    header=$(head -n 3 "$1" | wc -c)
    bad=$(od -A n -v -t x4 --endian=little -j "$header" "$1" |
        grep -E -o '(^| )[7f]f[89a-f][0-9a-f]{5}' | wc -l)
    echo "$bad"
    [ "$bad" -eq 0 ]
}

# Checks PFM file $1, saying what is wrong with it; false when it has a non-finite float.
check_pfm() {
    if [ "$(head -c 2 "$1")" != PF ] || [ "$(sed -n 3p "$1")" != -1.0 ]; then
        echo "FAIL $1: not a little-endian colour PFM file"
        return 1
    fi
    bad=$(count_nonfinite "$1") && return 0
    echo "FAIL $1: $bad floats are NaN or infinite"
    return 1
}

usage() {
    echo "usage: $0 pfm FILE... | render RAYTRA REFDIR" >&2
    exit 2
}
[ $# -ge 1 ] || usage
mode=$1
shift
if [ "$mode" = pfm ]; then
    status=0
    for file in "$@"; do
        check_pfm "$file" || status=1
    done
    exit $status
fi
if [ "$mode" != render ] || [ $# -ne 2 ]; then
    usage
fi
raytra=$1 refdir=$2
top=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d /tmp/raytra-nonfinite.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

# Every scene with the options of the reference renders, and every scene of scenes/ plainly.
{
    sed -e 's/#.*//' "$refdir/renders.txt" | awk 'NF >= 2 { $1 = ""; print substr($0, 2) }'
    (cd "$top" && ls scenes/*.scn)
} | sort -u >"$tmp/renders"

# The brightest scene within the limits (docs/robustness-tests.md): every light as bright as a
# number may be (colour times intensity at most 1e12), the point lights where 1/r^2 is
# largest (1e-7 from the point the camera sees, where raytra clamps r^2 to 1e-12), and
# the path bouncing between two perfect mirrors for as long as --max-depth lets it.
{
    echo "o convention fall2016"
    echo "c 0 5 0  0 -1 0  35  35 35  1 1"
    echo "l a 1e12 1e12 1e12"
    echo "l d 0 -1 0  1e6 1e6 1e6 1e6"
    echo "l s 0 4 0  0 -1 0  1 0 0  1  1e12 1e12 1e12"
    awk 'BEGIN { for (k = 0; k < 2000; k++) print "l p 0 1e-7 0  1e6 1e6 1e6 1e6" }'
    echo "m 1 1 1  1 1 1  0  1 1 1"
    echo "p 0 1 0 0"
    echo "p 0 -1 0 -10"
} >"$tmp/brightest.scn"
depth=
if "$raytra" --help 2>&1 | grep -q -- --max-depth; then depth="--max-depth 1000"; fi
echo "$tmp/brightest.scn $depth" >>"$tmp/renders"

passed=0 failed=0
while read -r scene options; do
    case $scene in /*) path=$scene ;; *) path=$top/$scene ;; esac
    # shellcheck disable=SC2086 # options are words by design
    if ! "$raytra" -q -j 2 $options "$path" "$tmp/out.pfm" 2>"$tmp/err"; then
        echo "FAIL $scene $options: raytra failed:"
        sed 's/^/    /' "$tmp/err"
        failed=$((failed + 1))
    elif grep -q 'NaN or infinite' "$tmp/err"; then
        echo "FAIL $scene $options: $(grep 'NaN or infinite' "$tmp/err")"
        failed=$((failed + 1))
    elif ! check_pfm "$tmp/out.pfm" >"$tmp/why"; then
        echo "FAIL $scene $options: $(cat "$tmp/why")"
        failed=$((failed + 1))
    else
        passed=$((passed + 1))
    fi
done <"$tmp/renders"
echo "nonfinite ($(basename "$(dirname "$refdir")")): $passed passed, $failed failed"
[ "$failed" -eq 0 ]
