#!/bin/sh
# figure.sh: draws the figures of grader/docs/statistics.md and of chapter 1.6's section on
# grading by statistics.
#
# Usage: tests/mc-variants/figure.sh RAYTRA VARIANTS IMGDIFF REFDIR OUTDIR
#
# Renders soft-shadow at P S = 3 1 with raytra (seed 7) and with two wrong variants
# (variants.c: the light's samples without the cosine; the jitter half a pixel off), and
# writes each render and imgdiff's z-score heat map against the statistical reference into
# OUTDIR, and prints imgdiff's verdicts (make statistics-figure).
set -eu
[ $# -eq 5 ] || { echo "usage: $0 RAYTRA VARIANTS IMGDIFF REFDIR OUTDIR" >&2; exit 2; }
raytra=$1 variants=$2 imgdiff=$3 refdir=$4 out=$5
top=$(cd "$(dirname "$0")/../.." && pwd)
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# draw NAME PROGRAM: one render, its heat map, imgdiff's words.
draw()
{
    "$2" -q -j 2 "$top/scenes/soft-shadow.scn" "$out/stats-$1.png" --samples 3 --light-samples 1 \
        --seed 7
    "$imgdiff" "$refdir/soft-shadow-3-1.stats.exr" "$out/stats-$1.png" \
        --diff "$out/stats-$1-z.png" >"$tmp/words" || true
    echo "figure: $out/stats-$1.png, $out/stats-$1-z.png: $(tail -n 1 "$tmp/words")"
}
draw right "$raytra"
draw no-cosine "$variants/raytra-no-cosine"
draw half-pixel "$variants/raytra-half-pixel"
