#!/bin/sh
# check.sh: renders every exercise scene with the part it belongs to and compares the pixels
# the exercises ask about with the answers worked out by hand in docs/exercises-answers.md.
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

# One line an answer: part, scene, options, column, row, and the expected red, green, blue.
while read -r part scene opts col row r g b; do
    case "$part" in '' | '#'*) continue ;; esac
    [ "$opts" = - ] && opts=
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
ANSWERS

if [ "$bad" -gt 0 ]; then
    echo "exercises: $bad of $checked answers disagree with the renders"
    exit 1
fi
echo "exercises: $checked answers agree with the renders"
