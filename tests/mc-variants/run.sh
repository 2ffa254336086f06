#!/bin/sh
# run.sh: shows that grading by statistics passes right Monte Carlo renders and fails wrong ones.
#
# Usage: tests/mc-variants/run.sh RAYTRA VARIANTS IMGDIFF REFDIR [TABLE]
#
# For every statistical reference (~IMAGE) of REFDIR/renders.txt, each program
# VARIANTS/raytra-NAME (part 1.6 with one function replaced, variants.c) renders the
# scene with its default seed, and VARIANTS/mcjudge judges the render as the PNG, the PFM
# and the EXR it would write: the right ones must pass every scene; each wrong one must
# fail one scene at least, and every scene it fails by the test its mistake should fail:
# biased (the bias test, or the exact test of the pixels the references saw without
# noise), noise (noisier than the "good" standard allows), or smooth (too little noise).
# Then the reference's mean written as a PNG, and IMGDIFF on raytra's own reference
# images: each must pass its statistical reference. Writes the table of verdicts, in
# Markdown, to TABLE when given (grader/docs/statistics.md shows it).
# Exit status 0 when everything is as expected, 1 otherwise.
set -u
[ $# -ge 4 ] || { echo "usage: $0 RAYTRA VARIANTS IMGDIFF REFDIR [TABLE]" >&2; exit 2; }
raytra=$1 variants=$2 imgdiff=$3 refdir=$4 table=${5:-}
top=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

# Each variant, the standard it is judged by, and what it must do: pass (a right
# solution), or fail by a test (biased: bias or exact; tests joined by +: any of them)
# where it fails, on one scene at least; untold: a mistake one image cannot tell, shown
# for what it is judged. A mistake that one image cannot show passes some scenes
# (grader/docs/statistics.md). same-offsets and wide-filter are also known mistakes of the
# part, which the grader names when an image resembles theirs (grader/docs/diagnosis.md).
expectations="rv-first:good:pass own-rng:good:pass xorshift:good:pass drand48:good:pass
transposed:good:pass shift:good:pass multi-jitter:good:pass latin-hypercube:good:pass
hashed:good:pass random-light:ok:pass random-light:good:noise+biased
no-cosine:good:biased one-over-s:good:biased flipped:good:biased half-pixel:good:biased
no-falloff:good:biased bright-2:good:biased bright-1:good:biased light-1pct:good:biased
light-small:good:biased checker:good:biased
denoise:good:biased more-samples:good:smooth hard-shadow:good:smooth+biased no-jitter:good:smooth+biased
not-stratified:good:untold same-offsets:good:biased wide-filter:good:biased"

# The statistical references: NAME SCENE OPTIONS..., a line each.
sed -n 's/^~\([^[:space:]]*\)\.[a-z]*[[:space:]]/\1 /p' "$refdir/renders.txt" >"$tmp/scenes"
[ -s "$tmp/scenes" ] || { echo "run.sh: no statistical reference in $refdir/renders.txt" >&2; exit 2; }

failed=0
header="| variant (standard) | $(cut -d' ' -f1 "$tmp/scenes" | tr '\n' '|' | sed 's/|/ | /g')"
rule="|---|$(cut -d' ' -f1 "$tmp/scenes" | sed 's/.*/---|/' | tr -d '\n')"
printf '%s\n%s\n' "$header" "$rule" >"$tmp/table"

# verdict LINES: the verdicts of mcjudge's lines (PNG, PFM, EXR) in a word each: PASS, or
# the failed test; one word when all three agree, else "png / pfm / exr".
verdict()
{
    awk '{ w[NR] = $3 == "PASS" ? "PASS" : $4 }
         END { if (w[1] == w[2] && w[2] == w[3]) print w[1]; else print w[1] " / " w[2] " / " w[3] }' "$1"
}

for expectation in $expectations; do
    variant=${expectation%%:*} rest=${expectation#*:}
    standard=${rest%%:*} want=${rest#*:}
    ok=
    [ "$standard" = good ] || ok=--ok
    row="| $variant ($standard) |"
    right=0
    while read -r name scene options; do
        # shellcheck disable=SC2086 # the options are words by design
        if ! "$variants/raytra-$variant" -q -j 2 "$top/$scene" "$tmp/image.pfm" $options 2>"$tmp/log"; then
            echo "FAIL $variant, $name: the program failed: $(cat "$tmp/log")"
            failed=$((failed + 1))
            continue
        fi
        "$variants/mcjudge" $ok "$refdir/$name.stats.exr" "$tmp/image.pfm" >"$tmp/judged" ||
            { echo "FAIL $variant, $name: mcjudge failed"; failed=$((failed + 1)); continue; }
        v=$(verdict "$tmp/judged")
        row="$row $v |"
        echo "$variant ($standard) $name: $v"
        for w in $(awk '{ print $3 == "PASS" ? "PASS" : $4 }' "$tmp/judged"); do
            case $w in bias | exact) test=biased ;; *) test=$w ;; esac
            case +$want+:$w in
                *:PASS | *+$test+* | +untold+:*) ;;
                +pass+:*) echo "FAIL $variant, $name: a right solution, judged $w"
                    failed=$((failed + 1)) ;;
                *) echo "FAIL $variant, $name: judged $w, where its mistake should fail as $want"
                    failed=$((failed + 1)) ;;
            esac
            [ "$w" = PASS ] || right=$((right + 1))
        done
    done <"$tmp/scenes"
    if [ "$want" != pass ] && [ "$want" != untold ] && [ "$right" -eq 0 ]; then
        echo "FAIL $variant: a wrong solution that no scene fails"
        failed=$((failed + 1))
    fi
    echo "$row" >>"$tmp/table"
done

# The reference's mean, the converged image, handed in as a PNG: too little noise.
row="| the reference's mean, as a PNG |"
while read -r name scene options; do
    "$variants/mcjudge" --mean "$refdir/$name.stats.exr" "$tmp/mean.png" || exit 2
    "$imgdiff" --machine "$refdir/$name.stats.exr" "$tmp/mean.png" >"$tmp/figures" 2>&1
    w=$(sed -n 's/^reason \([a-z]*\):.*/\1/p' "$tmp/figures")
    [ -n "$w" ] || w=PASS
    row="$row $w |"
    echo "mean $name: $w"
    [ "$w" = smooth ] || { echo "FAIL the mean of $name, as a PNG: judged $w, not smooth"; failed=$((failed + 1)); }
done <"$tmp/scenes"
echo "$row" >>"$tmp/table"

# raytra's own reference images, its renders with the default seed, through imgdiff.
row="| raytra, default seed (imgdiff) |"
while read -r name scene options; do
    if "$imgdiff" -q "$refdir/$name.stats.exr" "$refdir/$name.png" >"$tmp/out" 2>&1; then
        row="$row PASS |"
    else
        row="$row FAIL |"
        echo "FAIL raytra's $name.png: $(cat "$tmp/out")"
        failed=$((failed + 1))
    fi
done <"$tmp/scenes"
echo "$row" >>"$tmp/table"

[ -z "$table" ] || cp "$tmp/table" "$table"
cat "$tmp/table"
if [ "$failed" -eq 0 ]; then
    echo "check-statistics: right renders pass, wrong ones fail by the test they should"
else
    echo "check-statistics: $failed unexpected verdicts"
    exit 1
fi
