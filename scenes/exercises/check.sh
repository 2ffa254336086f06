#!/bin/sh
# check.sh: renders every exercise scene with the part it belongs to and compares the pixels
# the exercises ask about with the answers worked out by hand in docs/exercises-answers.md,
# and, for the answers that are words raytra prints, its output with those words.
#
# Usage: scenes/exercises/check.sh   (after make; POSIX sh, od and awk)
# Pixels are (column, row) as an image viewer counts them: row 0 is the top of the image.
set -u
top=$(cd "$(dirname "$0")/../.." && pwd)
cd "$top" || exit 1
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
bad=0
checked=0
# Where make leaves each part's program: raytra, or build-sanitize/raytra with SANITIZE=1.
program=${RAYTRA_PROGRAM:-raytra}

# Prints the linear RGB of pixel (column $2, row $3) of PFM $1, which raytra writes
# little-endian with its rows from the bottom up (read with od on a little-endian machine).
pfm_pixel() {
    header=$(head -c 64 "$1" | awk 'NR <= 3 { n += length($0) + 1 } NR == 2 { print $1, $2 } END { print n }')
    set -- "$1" "$2" "$3" $header
    od -A n -t f4 -j $(($6 + 12 * (($5 - 1 - $3) * $4 + $2))) -N 12 "$1"
}

# One line an answer: part, scene, options (words joined by commas), column, row, and the
# expected red, green, blue.
while read -r part scene opts col row r g b; do
    case "$part" in '' | '#'*) continue ;; esac
    [ "$opts" = - ] && opts=
    opts=$(echo "$opts" | tr ',' ' ')
    out="$tmp/$(basename "$scene" .scn)$(echo "$opts" | tr -dc 'a-z0-9').pfm"
    checked=$((checked + 1))
    if [ ! -f "$out" ] && ! milestones/"$part"/"$program" -q $opts "$scene" "$out" 2>"$tmp/err"; then
        echo "check: $part could not render $scene:"
        cat "$tmp/err"
        bad=$((bad + 1))
        continue
    fi
    got=$(echo $(pfm_pixel "$out" "$col" "$row"))
    if echo "$got $r $g $b" | awk '{ for (k = 1; k <= 3; k++) { d = $k - $(k + 3); if (d < 0) d = -d; if (d > 5e-6) exit 1 } }'; then
        echo "ok    $scene $opts ($col, $row): $got"
    else
        echo "WRONG $scene $opts ($col, $row): $got, the answer says $r $g $b"
        bad=$((bad + 1))
    fi
done <<'ANSWERS'
# 1.1.2: the only red pixel, and its neighbours black
1.1-spheres-red      scenes/exercises/1.1-one-pixel.scn       -                 6 1  1 0 0
1.1-spheres-red      scenes/exercises/1.1-one-pixel.scn       -                 5 1  0 0 0
1.1-spheres-red      scenes/exercises/1.1-one-pixel.scn       -                 6 0  0 0 0
1.1-spheres-red      scenes/exercises/1.1-one-pixel.scn       -                 6 2  0 0 0
1.1-spheres-red      scenes/exercises/1.1-one-pixel.scn       -                 7 1  0 0 0
# 1.2.1 and 1.2.2: the centre pixel and a corner pixel of the wall
1.2-shading          scenes/exercises/1.2-wall.scn            -                 2 2  0.9 0.65 0.5
1.2-shading          scenes/exercises/1.2-wall.scn            -                 4 0  0.459504 0.255380 0.132905
# 1.2.3: the same wall with a 16 times stronger light falling off as 1/r^2
1.2-shading          scenes/exercises/1.2-wall-fall2016.scn   -                 2 2  0.9 0.65 0.5
1.2-shading          scenes/exercises/1.2-wall-fall2016.scn   -                 4 0  0.306336 0.170253 0.088604
# 1.2.4: the back of the triangle: lit yellow, or its own colour with --two-sided; a pixel beside it
1.2-shading          scenes/exercises/1.2-winding.scn         -                 1 2  1 1 0
1.2-shading          scenes/exercises/1.2-winding.scn         --two-sided       1 2  0.2 0.6 0.9
1.2-shading          scenes/exercises/1.2-winding.scn         -                 1 0  0 0 0
# 1.2.5: the plane that carries the disc, at a pixel inside the disc
1.2-shading          scenes/exercises/1.2-disc-plane.scn      -                 7 8  1.093827 0.994076 0.495321
# 1.3.1: a pixel of the wall in the sphere's shadow, and one in the light
1.3-shadows-mirror   scenes/exercises/1.3-shadow.scn          -                 7 5  0.12 0.08 0.04
1.3-shadows-mirror   scenes/exercises/1.3-shadow.scn          -                 2 5  0.544264 0.362843 0.181421
# 1.3.2: the wall behind the camera, seen in the mirror, in both conventions
1.3-shadows-mirror   scenes/exercises/1.3-mirror.scn          -                 2 2  0.495 0.33 0.165
1.3-shadows-mirror   scenes/exercises/1.3-mirror-fall2016.scn -                 2 2  0.018 0.012 0.006
# 1.3.4: the corridor of mirrors at three depth limits
1.3-shadows-mirror   scenes/exercises/1.3-corridor.scn        --max-depth=0     2 2  0.2 0.2 0.2
1.3-shadows-mirror   scenes/exercises/1.3-corridor.scn        --max-depth=2     2 2  0.35 0.35 0.35
1.3-shadows-mirror   scenes/exercises/1.3-corridor.scn        -                 2 2  0.39999981 0.39999981 0.39999981
# 1.4.1: box tests of the camera rays, as --view box-tests draws them: the heat of
# n tests out of at most 6 is heat(n/6); in mode 0 all 4 of 4, white
1.4-bvh              scenes/exercises/1.4-four-spheres.scn    --view=box-tests  0 1  1 1 1
1.4-bvh              scenes/exercises/1.4-four-spheres.scn    --view=box-tests  1 1  1 1 0.5
1.4-bvh              scenes/exercises/1.4-four-spheres.scn    --view=box-tests  3 1  1 0.5 0
1.4-bvh              scenes/exercises/1.4-four-spheres.scn    --view=box-tests  5 1  1 1 0.5
1.4-bvh              scenes/exercises/1.4-four-spheres.scn    --view=box-tests  2 0  0.5 0 0
1.4-bvh              scenes/exercises/1.4-four-spheres.scn    --view=box-tests  4 2  0.5 0 0
1.4-bvh              scenes/exercises/1.4-four-spheres.scn    --mode=0,--view=box-tests 3 2 1 1 1
# 1.5.2: the slab at 45 degrees, with every internal reflection (--min-weight 0)
1.5-refraction       scenes/exercises/1.5-slab.scn            --min-weight=0    0 0  0.9192582 0.9192582 0.9192582
# 1.5.3: total internal reflection beyond tan 0.8944 (columns 0 and 9), 1 - R within
1.5-refraction       scenes/exercises/1.5-critical.scn        -                 0 0  0 0 0
1.5-refraction       scenes/exercises/1.5-critical.scn        -                 1 0  0.9328735 0.9328735 0.9328735
1.5-refraction       scenes/exercises/1.5-critical.scn        -                 4 0  0.96 0.96 0.96
1.5-refraction       scenes/exercises/1.5-critical.scn        -                 9 0  0 0 0
# 1.5.4: Beer's law through coloured glass 1 thick, every internal reflection counted
1.5-refraction       scenes/exercises/1.5-beer.scn            --min-weight=0    0 0  0.46098439 0.73803575 0.92307692
# 1.6.1: the edge down the middle of column 1: with P = 1 the ray on the edge; P = 2
1.6-monte-carlo      scenes/exercises/1.6-edges.scn           -                 1 0  1 1 1
1.6-monte-carlo      scenes/exercises/1.6-edges.scn           --samples=2       1 0  0.5 0.5 0.5
1.6-monte-carlo      scenes/exercises/1.6-edges.scn           --samples=2       0 0  1 1 1
1.6-monte-carlo      scenes/exercises/1.6-edges.scn           --samples=2       2 0  0 0 0
# 1.6.2: the edge a quarter of the way across column 1: P = 1 and P = 4
1.6-monte-carlo      scenes/exercises/1.6-edges.scn           -                 1 3  0 0 0
1.6-monte-carlo      scenes/exercises/1.6-edges.scn           --samples=4       1 3  0.25 0.25 0.25
# 1.6.3 and 1.6.4: half and a quarter of the light hidden, with P S = 1 2, 2 1 and 4 1
1.6-monte-carlo      scenes/exercises/1.6-half-blocked.scn    --light-samples=2 0 0  0.5 0.5 0.5
1.6-monte-carlo      scenes/exercises/1.6-half-blocked.scn    --samples=2       0 0  0.5 0.5 0.5
1.6-monte-carlo      scenes/exercises/1.6-half-blocked.scn    --samples=4       0 0  0.5 0.5 0.5
1.6-monte-carlo      scenes/exercises/1.6-quarter-blocked.scn --light-samples=2 0 0  0.75 0.75 0.75
1.6-monte-carlo      scenes/exercises/1.6-quarter-blocked.scn --samples=2       0 0  0.75 0.75 0.75
ANSWERS

# Prints $1 without its leading and trailing blanks.
trim() {
    echo "$1" | sed 's/^ *//; s/ *$//'
}

# Answers that are words raytra prints: part | scene | options | the words, which must
# stand in what it prints (standard output and error) with these options; TMP in the
# options is a scratch folder.
while IFS='|' read -r part scene opts text; do
    part=$(trim "$part") scene=$(trim "$scene") text=$(trim "$text")
    opts=$(trim "$opts" | sed "s|TMP|$tmp|g")
    case "$part" in '' | '#'*) continue ;; esac
    checked=$((checked + 1))
    # shellcheck disable=SC2086 # the options are words by design
    milestones/"$part"/"$program" -q $opts "$scene" >"$tmp/said" 2>&1
    if grep -qF -- "$text" "$tmp/said"; then
        echo "ok    $scene $opts: '$text'"
    else
        echo "WRONG $scene $opts: raytra does not say '$text'; it says:"
        sed 's/^/    /' "$tmp/said"
        bad=$((bad + 1))
    fi
done <<'ANSWERS'
# 1.4.2: mode 0 tests every sphere's and triangle's box, and every plane, for every ray
1.4-bvh         | scenes/bvh-torus.scn                     | --mode 0 --view box-tests --scale 0.05 -o TMP/torus.pfm | white 1283 tests
# 1.4.3: 16 spheres: 2 log2(16) + 2 tests with the BVH, 16 in mode 0
1.4-bvh         | scenes/exercises/1.4-sixteen-spheres.scn | --view box-tests -o TMP/sixteen.pfm                | white 10 tests
1.4-bvh         | scenes/exercises/1.4-sixteen-spheres.scn | --mode 0 --view box-tests -o TMP/sixteen.pfm       | white 16 tests
# 1.5.1: Snell's law and Schlick at 45 degrees into index 1.5, and out again
1.5-refraction  | scenes/exercises/1.5-slab.scn            | --trace-pixel 0,0 | entering it: refracted, R = 0.0420693
1.5-refraction  | scenes/exercises/1.5-slab.scn            | --trace-pixel 0,0 | along (0.471405, 0, -0.881917)
1.5-refraction  | scenes/exercises/1.5-slab.scn            | --trace-pixel 0,0 | point (0.534522, 0, -1), normal (0, 0, -1), back face
1.5-refraction  | scenes/exercises/1.5-slab.scn            | --trace-pixel 0,0 | leaving it: refracted, R = 0.0420693
# 1.5.2: out of the slab parallel to the way in, 0.329 aside: the wall at x = 4.53452
1.5-refraction  | scenes/exercises/1.5-slab.scn            | --trace-pixel 0,0 | point (4.53452, 0, -5)
# 1.5.3: the critical angle
1.5-refraction  | scenes/exercises/1.5-critical.scn        | --trace-pixel 0,0 | leaving it: total internal reflection
1.5-refraction  | scenes/exercises/1.5-critical.scn        | --trace-pixel 1,0 | leaving it: refracted, R = 0.0671265
# 1.6.1: the samples of pixel (1, 0) with P = 2: the left two on the triangle
1.6-monte-carlo | scenes/exercises/1.6-edges.scn           | --samples 2 --trace-pixel 1,0@0 | sample 0: colour (1, 1, 1)
1.6-monte-carlo | scenes/exercises/1.6-edges.scn           | --samples 2 --trace-pixel 1,0@1 | sample 1: colour (0, 0, 0)
1.6-monte-carlo | scenes/exercises/1.6-edges.scn           | --samples 2 --trace-pixel 1,0@2 | sample 2: colour (1, 1, 1)
1.6-monte-carlo | scenes/exercises/1.6-edges.scn           | --samples 2 --trace-pixel 1,0@3 | sample 3: colour (0, 0, 0)
# 1.6.3: with S = 2 each shadow ray of a sample goes to its own quarter of the light
1.6-monte-carlo | scenes/exercises/1.6-half-blocked.scn    | --light-samples 2 --trace-pixel 0,0@0 | area light sample 0 of 0 to 3 adds (0, 0, 0)
1.6-monte-carlo | scenes/exercises/1.6-half-blocked.scn    | --light-samples 2 --trace-pixel 0,0@0 | area light sample 2 of 0 to 3 adds (0, 0, 0)
# 1.6.4: the hidden quarter is the light's stratum 2
1.6-monte-carlo | scenes/exercises/1.6-quarter-blocked.scn | --light-samples 2 --trace-pixel 0,0@0 | area light sample 2 of 0 to 3 adds (0, 0, 0)
ANSWERS

if [ "$bad" -gt 0 ]; then
    echo "exercises: $bad of $checked answers disagree with the renders"
    exit 1
fi
echo "exercises: $checked answers agree with the renders"
