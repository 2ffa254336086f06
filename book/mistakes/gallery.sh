#!/bin/sh
# gallery.sh: renders the gallery of common mistakes and writes docs/mistakes.md (make mistakes).
#
# Usage: book/mistakes/gallery.sh   (make mistakes: builds the variants first)
#
# Each mistake is rendered by part 1.3's raytra with one option (shadow acne), or by a
# variant of it with one function wrapped (book/mistakes/mistakes.c), next to the
# right image; imgdiff draws the heat map of the differences, and --trace-pixel tells
# what happened at one telling pixel. Nothing here is drawn or written by hand.
case ${1:-} in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
set -eu
top=$(cd "$(dirname "$0")/../.." && pwd)
cd "$top"
right=milestones/1.3-shadows-mirror/raytra
variants=book/mistakes/build
imgdiff=compare/build/imgdiff
figures=docs/figures/mistakes
doc=docs/mistakes.md
mkdir -p "$figures"

cat >"$doc" <<'EOF'
# A gallery of common mistakes

Every ray tracer written for the course goes wrong in some of the same ways. Each
section below shows one mistake: the picture it makes, the right picture, the
heat map of their differences as `compare/build/imgdiff --diff` draws it (black
where they agree; blue, purple, red, yellow to white as the difference grows),
what `raytra --trace-pixel` prints at a pixel that tells (its column and row
from the top-left), and the fix.

Every picture is made by `make mistakes` (book/mistakes/gallery.sh), which also
writes this page: the mistakes are a part of raytra (1.3 unless said) with one
option (`--ray-offset 0`) or with one function replaced by a wrong one
(book/mistakes/mistakes.c, linked in its place with the linker's `--wrap`).
[docs/debugging.md](debugging.md) explains `--trace-pixel` and `--view`.
EOF

# mistake NAME TITLE PROGRAM SCENE "OPTIONS" PIXEL [RIGHT]: renders and writes one section,
# the right image by RIGHT (part 1.3's raytra unless given);
# the section's text (what goes wrong, and the fix) comes on standard input.
mistake()
{
    name=$1 title=$2 program=$3 scene=$4 options=$5 pixel=$6 good=${7:-$right}
    # shellcheck disable=SC2086 # options are words by design
    "$good" -q $options "$scene" "$figures/$name-right.png"
    # shellcheck disable=SC2086
    "$program" -q $options "$scene" "$figures/$name.png" 2>/dev/null || true
    "$imgdiff" "$figures/$name-right.png" "$figures/$name.png" --diff "$figures/$name-diff.png" \
        >/dev/null || true
    {
        printf '\n## %s\n\n' "$title"
        printf '| the mistake | right | differences |\n|---|---|---|\n'
        printf '| ![](figures/mistakes/%s.png) | ![](figures/mistakes/%s-right.png) | ![](figures/mistakes/%s-diff.png) |\n\n' \
            "$name" "$name" "$name"
        printf '*`%s`%s; the right image by `%s`.*\n\n' "$scene" "${options:+ with \`$options\`}" \
            "$good"
        cat
        printf '\n<details><summary>What <code>--trace-pixel %s</code> prints with the mistake</summary>\n\n```\n' \
            "$pixel"
        # shellcheck disable=SC2086
        "$program" -q $options "$scene" --trace-pixel "$pixel" 2>/dev/null || true
        printf '```\n</details>\n'
    } >>"$doc"
    echo "gallery: $name"
}

mistake acne "Shadow acne: no ray offset" "$right" scenes/acne-grazing.scn "--ray-offset 0" 191,50 <<'EOF'
**What goes wrong.** The shadow ray starts exactly at the computed hit point,
which rounding puts a hair in front of the floor or behind it. From behind, the
ray finds the floor itself at a tiny t and the point counts as shadowed by
itself: speckles, worst where the light grazes the surface. In the trace, light
0's shadow ray is blocked by the very sphere it starts on, at t ≈ 10⁻¹⁵.

**The fix.** Start secondary rays a little off the surface, on the side they leave
by, by a distance relative to the coordinates (`secondary_ray`,
docs/1.3-shadows-mirror.md).
EOF

mistake upside-down "An upside-down image: the pixel mapping" "$variants/raytra-upside-down" \
    scenes/demo.scn "--scale 0.5" 20,20 <<'EOF'
**What goes wrong.** The lecture counts pixel rows j from the bottom of the image
(v = b + (t − b)(j + 0.5)/n<sub>y</sub>), image files from the top. Mixing the two
turns the picture upside down. In the trace, the camera ray of a pixel near the
top-left corner points down to the floor instead of up into the empty sky.

**The fix.** Keep the lecture's j for the ray and store pixel (i, j) in image row
n<sub>y</sub> − 1 − j (`render_image`, docs/1.1-spheres-red.md).
EOF

mistake no-closest-hit "The far sphere drawn over the near one: no closest hit" \
    "$variants/raytra-no-closest-hit" scenes/spheres-three.scn "" 128,99 <<'EOF'
**What goes wrong.** Every sphere is tested all the way to infinity and the last
one hit wins, so a sphere later in the file is drawn over a nearer one. Shadows
go wrong too: a sphere beyond the light now blocks it. In the trace, the camera
ray reports the green sphere at a larger t than the red one in front of it.

**The fix.** Test each surface only up to the nearest hit found so far (`tmax`
shrinks in `world_hit`, docs/1.2-shading.md).
EOF

mistake unnormalised-normal "Unnormalised normals" "$variants/raytra-unnormalised-normal" \
    scenes/spheres-three.scn "" 154,62 <<'EOF'
**What goes wrong.** The sphere's normal is taken as p − O without dividing by
the radius, so n·l and n·h are the radius times too large: the diffuse term is
far too bright and the highlight, raised to the power p, overflows. The trace
shows a normal of length 20 (the green sphere's radius) and its huge specular term.

**The fix.** Divide by the radius, (p − O)/r (slide 53 ("unit normal at intersection is")), or normalise.
EOF

mistake no-clamp "Missing clamp before encoding" "$variants/raytra-no-clamp" \
    scenes/demo.scn "--scale 0.5 --max-depth 0" 235,132 <<'EOF'
**What goes wrong.** Radiance above 1 is written to the 8-bit file without
clamping, and the code wraps round 256: the brightest highlights turn dark or
black. The last line of the trace shows the colour, the clamped colour, and the
8-bit code the broken encoder stored.

**The fix.** Clamp to [0, 1] before the sRGB curve and the 8 bits
(`image_encode_8bit`, README's section on colour).
EOF

mistake mirror-wrong-way "Mirror rays sent the wrong way" "$variants/raytra-mirror-wrong-way" \
    scenes/demo.scn "--scale 0.5" 179,95 <<'EOF'
**What goes wrong.** The reflected direction is turned round, 2(d·n)n − d
instead of d − 2(d·n)n, so the mirror ray goes into the surface: the mirror ball
shows its own inside, dark, instead of the room. In the trace, the reflected ray
meets the same sphere again at once, from its back.

**The fix.** r = d − 2(d·n)n with n the normal facing the ray
(`secondary_reflect`, docs/1.3-shadows-mirror.md).
EOF

mistake specular-behind "Specular light from behind the surface" \
    "$variants/raytra-specular-behind" scenes/specular-behind.scn "" 200,110 \
    milestones/1.2-shading/raytra <<'EOF'
**What goes wrong.** The highlight is added for a light behind the surface too:
n·l is negative, but n·h can still be positive, so a glint appears on the dark
side of an object. This one breaks part 1.2, where every light is shaded without
shadow rays (part 1.3 never shades a light behind the surface).

**The fix.** Return nothing, highlight included, when n·l ≤ 0
(`shade_blinn_phong_terms`, docs/1.2-shading.md).
EOF

mistake bvh-loses-hits "A BVH that loses hits" "$variants/raytra-bvh-loses-hits" \
    scenes/bvh-torus.scn "" 124,143 milestones/1.4-bvh/raytra <<'EOF'
**What goes wrong.** Each triangle's bounding box is made of two of its corners
instead of all three. The traversal only looks inside boxes, so wherever a
triangle sticks out of its box the ray passes through it: holes, and the
surfaces behind them show through. This one breaks part 1.4; `--mode 0` (every
surface, each behind its own box) has holes too, if not the same ones, and
`--mode 1` draws the boxes themselves, too thin. In the trace, the camera ray reaches what lies
behind the lost triangle.

**The fix.** A box must hold everything its surface can be hit at: all three
corners, padded so that rounding cannot shave off an edge (`box_of_triangle`,
docs/1.4-bvh.md). The test that catches it compares the BVH's hits with brute
force's on many random rays (`milestones/1.4-bvh/tests/test_bvh.c`).
EOF

echo "gallery: wrote $doc"
