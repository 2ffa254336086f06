#!/bin/sh
# noise-plot.sh: the figures of docs/1.6-monte-carlo.md: noise against samples, sample patterns, times.
#
# Usage: compare/noise-plot.sh RAYTRA IMGDIFF OUTDIR
#   RAYTRA is part 1.6's program, IMGDIFF compare/build/imgdiff. Writes to OUTDIR:
#   noise.csv, noise.svg  the RMSE of scenes/soft-shadow.scn at half size against a
#                         32 x 32-ray, 4 x 4-shadow-ray reference, for P = 1 .. 16 (S = 1),
#                         sampled random, jittered and correlated, on log-log axes
#   patterns.svg          16 sample points of a pixel, random and jittered, and the
#                         correlated pairs of pixel and light strata
#   times.md              render times of the full-size scene for several (P, S)
# Takes about a minute on two cores. Needs only sh, awk and the two programs.
case ${1:-} in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
set -eu
[ $# -eq 3 ] || { echo "usage: $0 RAYTRA IMGDIFF OUTDIR" >&2; exit 2; }
raytra=$1 imgdiff=$2 out=$3
top=$(cd "$(dirname "$0")/.." && pwd)
scene=$top/scenes/soft-shadow.scn
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"

# The noise: RMSE against a reference of many samples, each sampling at each P.
"$raytra" -q --scale 0.5 --sampling jittered --seed 99 "$scene" "$tmp/reference.pfm" 32 4
echo "sampling,P,rays_per_pixel,rmse" >"$out/noise.csv"
for sampling in random jittered correlated; do
    for p in 1 2 3 4 6 8 12 16; do
        "$raytra" -q --scale 0.5 --sampling $sampling "$scene" "$tmp/$sampling.pfm" $p 1
        rmse=$("$imgdiff" --machine "$tmp/reference.pfm" "$tmp/$sampling.pfm" |
            awk '$1 == "rmse" { print $2 }')
        echo "$sampling,$p,$((p * p)),$rmse" >>"$out/noise.csv"
    done
done

# The plot: log2 of the rays per pixel across, log10 of the RMSE up.
awk -F, '
NR == 1 { next }
{ s[NR] = $1; n[NR] = $3; e[NR] = $4; rows = NR
  if (lo == "" || $4 < lo) lo = $4
  if (hi == "" || $4 > hi) hi = $4 }
function px(v) { return 70 + 420 * log(v) / log(256) }
function py(v) { return 30 + 300 * (dtop - log(v) / log(10)) / (dtop - dbot) }
END {
    dbot = int(log(lo) / log(10) - 1); dtop = int(log(hi) / log(10) + 1)
    colour["random"] = "#d62728"; colour["jittered"] = "#1f77b4"; colour["correlated"] = "#2ca02c"
    print "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"620\" height=\"390\" font-family=\"sans-serif\" font-size=\"12\">"
    print "<rect width=\"620\" height=\"390\" fill=\"white\"/>"
    print "<rect x=\"70\" y=\"30\" width=\"420\" height=\"300\" fill=\"none\" stroke=\"black\"/>"
    for (k = 1; k <= 256; k *= 4) {
        printf "<line x1=\"%.1f\" y1=\"30\" x2=\"%.1f\" y2=\"330\" stroke=\"#ddd\"/>\n", px(k), px(k)
        printf "<text x=\"%.1f\" y=\"348\" text-anchor=\"middle\">%d</text>\n", px(k), k
    }
    for (d = dbot; d <= dtop; d++) {
        printf "<line x1=\"70\" y1=\"%.1f\" x2=\"490\" y2=\"%.1f\" stroke=\"#ddd\"/>\n", py(10 ^ d), py(10 ^ d)
        printf "<text x=\"64\" y=\"%.1f\" text-anchor=\"end\">1e%d</text>\n", py(10 ^ d) + 4, d
    }
    print "<text x=\"280\" y=\"372\" text-anchor=\"middle\">rays per pixel (P x P, one shadow ray each)</text>"
    print "<text x=\"18\" y=\"180\" text-anchor=\"middle\" transform=\"rotate(-90 18 180)\">RMSE against the reference</text>"
    # A line of slope -1/2 (error of a mean of N) for comparison, through random at N = 1.
    for (r = 2; r <= rows; r++) if (s[r] == "random" && n[r] == 1) start = e[r]
    printf "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#888\" stroke-dasharray=\"4 4\"/>\n", px(1), py(start), px(256), py(start / 16)
    printf "<text x=\"%.1f\" y=\"%.1f\" fill=\"#888\">N^-1/2</text>\n", px(256) - 40, py(start / 16) + 18
    y = 50
    split("random jittered correlated", order, " ")
    for (k = 1; k <= 3; k++) {
        name = order[k]; path = ""
        for (r = 2; r <= rows; r++) if (s[r] == name) {
            path = path sprintf("%s%.1f,%.1f", path == "" ? "M" : " L", px(n[r]), py(e[r]))
            printf "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3\" fill=\"%s\"/>\n", px(n[r]), py(e[r]), colour[name]
        }
        printf "<path d=\"%s\" fill=\"none\" stroke=\"%s\" stroke-width=\"2\"/>\n", path, colour[name]
        printf "<line x1=\"505\" y1=\"%d\" x2=\"525\" y2=\"%d\" stroke=\"%s\" stroke-width=\"2\"/>\n", y, y, colour[name]
        printf "<text x=\"530\" y=\"%d\">%s</text>\n", y + 4, name
        y += 20
    }
    print "</svg>"
}' "$out/noise.csv" >"$out/noise.svg"

# The sample patterns, from the "minimal standard" LCG of Park and Miller, exact in
# doubles, so that every awk draws the same points.
awk '
function rand01() { state = (state * 16807) % 2147483647; return (state - 1) / 2147483646 }
function square(x0, title) {
    printf "<rect x=\"%d\" y=\"40\" width=\"160\" height=\"160\" fill=\"#f4f4f4\" stroke=\"black\"/>\n", x0
    printf "<text x=\"%d\" y=\"28\" text-anchor=\"middle\">%s</text>\n", x0 + 80, title
}
function grid(x0,   k) {
    for (k = 1; k < 4; k++) {
        printf "<line x1=\"%d\" y1=\"40\" x2=\"%d\" y2=\"200\" stroke=\"#bbb\"/>\n", x0 + 40 * k, x0 + 40 * k
        printf "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"#bbb\"/>\n", x0, 40 + 40 * k, x0 + 160, 40 + 40 * k
    }
}
function dot(x0, u, v, fill) {
    printf "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" fill=\"%s\"/>\n", x0 + 160 * u, 200 - 160 * v, fill
}
BEGIN {
    state = 20161; n = 4
    print "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"760\" height=\"240\" font-family=\"sans-serif\" font-size=\"13\">"
    print "<rect width=\"760\" height=\"240\" fill=\"white\"/>"
    square(20, "random: 16 points"); grid(20)
    for (k = 0; k < 16; k++) dot(20, rand01(), rand01(), "black")
    square(200, "jittered: one per sub-square"); grid(200)
    for (k = 0; k < 16; k++) dot(200, (k % n + rand01()) / n, (int(k / n) + rand01()) / n, "black")
    # Correlated: pixel sub-square k (left) sends its shadow ray to light stratum pi(k) (right).
    square(400, "pixel: sub-square k"); grid(400)
    square(580, "light: stratum pi(k)"); grid(580)
    for (k = 0; k < 16; k++) perm[k] = k
    for (k = 15; k > 0; k--) { j = int(rand01() * (k + 1)); t = perm[k]; perm[k] = perm[j]; perm[j] = t }
    for (k = 0; k < 16; k++) {
        hue = int(360 * k / 16); fill = "hsl(" hue ",80%,45%)"
        dot(400, (k % n + rand01()) / n, (int(k / n) + rand01()) / n, fill)
        q = perm[k]
        dot(580, (q % n + rand01()) / n, (int(q / n) + rand01()) / n, fill)
    }
    print "<text x=\"380\" y=\"228\" text-anchor=\"middle\">the same colour: a primary ray and its shadow ray; every light stratum is used once</text>"
    print "</svg>"
}' >"$out/patterns.svg"

# Render times of the full-size scene, as the summary line reports them.
{
    echo "| P | S | rays per pixel | seconds |"
    echo "|---|---|---|---|"
    for ps in "1 1" "2 1" "3 1" "4 1" "8 1" "1 3" "3 3" "4 4" "8 8"; do
        # shellcheck disable=SC2086 # P and S are two words
        "$raytra" -j 2 "$scene" "$tmp/time.png" $ps 2>"$tmp/summary"
        set -- $ps
        awk -v p="$1" -v s="$2" '/wrote/ {
            for (k = 1; k <= NF; k++) { if ($k == "s" && $(k-2) == "in") t = $(k-1); if ($k == "rays") r = $(k-1) }
            gsub(/[^0-9]/, "", r); printf "| %s | %s | %.0f | %s |\n", p, s, r / 30000, t }' "$tmp/summary"
    done
} >"$out/times.md"
echo "noise-plot: wrote $out/noise.csv, noise.svg, patterns.svg, times.md"
