#!/bin/sh
# run.sh: shows that grading by statistics passes right Monte Carlo renders and fails wrong ones.
#
# Usage: tests/mc-variants/run.sh RAYTRA VARIANTS IMGDIFF REFDIR [TABLE]
#
# For every statistical reference (~IMAGE) of REFDIR/renders.txt:
#   1. RAYTRA (part 1.6) with seeds 1 to MC_SEEDS (default 20), none of those the reference
#      was made from, as PNG and as PFM: every render must pass;
#   2. each program VARIANTS/raytra-NAME (part 1.6 with one function replaced,
#      variants.c), as PNG with its default seed: the right ones (rv-first, own-rng) must
#      pass every scene; each wrong one must fail one scene at least, and every scene it
#      fails by the test its mistake should fail (bias or noise).
# Writes the table of verdicts, in Markdown, to TABLE when given (docs/grading.md shows it).
# Exit status 0 when everything is as expected, 1 otherwise.
set -u
[ $# -ge 4 ] || { echo "usage: $0 RAYTRA VARIANTS IMGDIFF REFDIR [TABLE]" >&2; exit 2; }
raytra=$1 variants=$2 imgdiff=$3 refdir=$4 table=${5:-}
top=$(cd "$(dirname "$0")/../.." && pwd)
seeds=${MC_SEEDS:-20}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

# Each variant and the test its mistake must fail (pass: a right solution), then the scenes
# where it may fail by another, and why:
#   not-stratified on demo: unstratified edges are noisier, and in 8-bit codes a noisier
#   pixel has a lower mean code (the sRGB curve is concave, values clamp at white), so
#   the extra noise shows as bias too (docs/grading.md).
expectations="rv-first:pass own-rng:pass no-cosine:bias one-over-s:bias
not-stratified:noise:demo=bias flipped:bias half-pixel:bias no-falloff:bias"

# The statistical references: NAME SCENE OPTIONS..., a line each.
sed -n 's/^~\([^[:space:]]*\)\.[a-z]*[[:space:]]/\1 /p' "$refdir/renders.txt" >"$tmp/scenes"
[ -s "$tmp/scenes" ] || { echo "run.sh: no statistical reference in $refdir/renders.txt" >&2; exit 2; }

# judge PROGRAM NAME SCENE EXT [options]: renders, judges; prints PASS, FAIL bias, FAIL noise...
# and leaves imgdiff's figures in $tmp/figures.
judge()
{
    program=$1 name=$2 scene=$3 ext=$4
    shift 4
    if ! "$program" -q -j 2 "$top/$scene" "$tmp/image.$ext" "$@" 2>"$tmp/log"; then
        echo "ERROR"
        return
    fi
    "$imgdiff" --machine "$refdir/$name.stats.exr" "$tmp/image.$ext" >"$tmp/figures" 2>&1
    case $? in
        0) echo "PASS" ;;
        1) echo "FAIL $(sed -n 's/^reason \([a-z]*\).*/\1/p' "$tmp/figures")" ;;
        *) echo "ERROR" ;;
    esac
}

failed=0
header="| | $(cut -d' ' -f1 "$tmp/scenes" | tr '\n' '|' | sed 's/|/ | /g')"
rule="|---|$(cut -d' ' -f1 "$tmp/scenes" | sed 's/.*/---|/' | tr -d '\n')"
printf '%s\n%s\n' "$header" "$rule" >"$tmp/table"

# 1. raytra itself with seeds of its own.
for ext in png pfm; do
    row="| raytra, seeds 1 to $seeds, .$ext |"
    while read -r name scene options; do
        passed=0 worst_z=0 worst_noise=0
        s=1
        while [ "$s" -le "$seeds" ]; do
            # shellcheck disable=SC2086 # the options are words by design
            verdict=$(judge "$raytra" "$name" "$scene" "$ext" $options --seed "$s")
            if [ "$verdict" = PASS ]; then
                passed=$((passed + 1))
            else
                echo "FAIL raytra --seed $s, $name.$ext: $verdict"
                grep '^reason' "$tmp/figures" | sed 's/^/    /'
                failed=$((failed + 1))
            fi
            # The largest |z| as a fraction of the critical one, the largest noise ratios.
            awk -v z="$worst_z" -v n="$worst_noise" '
                $1 == "bias_worst" { r = ($2 < 0 ? -$2 : $2) / $3; if (r > z) z = r }
                $1 == "noise_block" && $2 > n { n = $2 }
                END { printf "%.2f %.2f\n", z, n }' "$tmp/figures" >"$tmp/worst"
            read -r worst_z worst_noise <"$tmp/worst"
            s=$((s + 1))
        done
        echo "raytra .$ext $name: $passed of $seeds seeds pass; largest |z| $worst_z of the critical, noisiest square $worst_noise"
        row="$row $passed of $seeds pass |"
    done <"$tmp/scenes"
    echo "$row" >>"$tmp/table"
done

# 2. The variants, right and wrong.
for expectation in $expectations; do
    variant=${expectation%%:*} want=${expectation#*:} exceptions=
    case $want in *:*) exceptions=${want#*:} want=${want%%:*} ;; esac
    row="| $variant |"
    right=0
    while read -r name scene options; do
        # shellcheck disable=SC2086
        verdict=$(judge "$variants/raytra-$variant" "$name" "$scene" png $options)
        row="$row $verdict |"
        case $want:$verdict in
            pass:PASS | *:"FAIL $want") ;;
            pass:*) echo "FAIL $variant, $name: a right solution, judged $verdict"
                failed=$((failed + 1)) ;;
            *:PASS) ;;
            *) case " $exceptions " in
                   *" $name=${verdict#FAIL }"*) ;;
                   *) echo "FAIL $variant, $name: judged $verdict, where its mistake should fail the $want test"
                       failed=$((failed + 1)) ;;
               esac ;;
        esac
        [ "$verdict" != "FAIL $want" ] || right=$((right + 1))
        echo "$variant $name: $verdict$(sed -n 's/^reason / (/p' "$tmp/figures" | sed 's/$/)/')"
    done <"$tmp/scenes"
    if [ "$want" != pass ] && [ "$right" -eq 0 ]; then
        echo "FAIL $variant: a wrong solution that no scene fails by the $want test"
        failed=$((failed + 1))
    fi
    echo "$row" >>"$tmp/table"
done

[ -z "$table" ] || cp "$tmp/table" "$table"
cat "$tmp/table"
if [ "$failed" -eq 0 ]; then
    echo "check-statistics: right renders pass, wrong ones fail by the test they should"
else
    echo "check-statistics: $failed unexpected verdicts"
    exit 1
fi
