#!/bin/sh
# render-times.sh: render times of part 1.3 (brute force) and part 1.4 (modes 0 and 3), as a table.
#
# Usage: bench/render-times.sh [--update CHAPTER]
#   Renders each scene below with one thread and prints a Markdown table of the times.
#   With --update, writes the table into CHAPTER between the lines
#   <!-- render-times --> and <!-- end render-times --> (docs/1.4-bvh.md).
# The course scenes are read from ../shared/course-scenes, at a tenth of their size (brute force takes minutes on the bigger ones);
# those that are not there are left out, saying so. Times depend on the machine and
# on what else runs on it.
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
corpus=$top/../shared/course-scenes
old=$top/milestones/1.3-shadows-mirror/raytra
new=$top/milestones/1.4-bvh/raytra
make -s -C "$top/milestones/1.3-shadows-mirror" >/dev/null && make -s -C "$top/milestones/1.4-bvh" >/dev/null || exit 1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Prints the seconds of one run of program $1 on scene $2 with the extra words $3
# (a MODE, or nothing) and options $4: the whole run, reading the scene, building the
# boxes or the BVH, rendering and writing the image.
seconds() {
    start=$(date +%s%N)
    # shellcheck disable=SC2086 # options are words by design
    "$1" -q -j 1 $4 "$2" "$tmp/out.pfm" $3 || echo "render-times: $1 failed on $2" >&2
    echo "$start $(date +%s%N)" | awk '{ printf "%.3f", ($2 - $1) / 1e9 }'
}

# Prints the table row of scene $1 (shown as $2) rendered with the options $3.
row() {
    scene=$1 shown=$2 options=$3
    [ -f "$scene" ] || { echo "render-times: SKIPPED $shown: $scene does not exist" >&2; return; }
    info=$("$new" --check $options "$scene" 2>/dev/null | sed -n 's/.*pixels; \([0-9]*\) spheres*, \([0-9]*\) planes*, \([0-9]*\) triangles*.*/\1 \2 \3/p')
    set -- $info
    a=$(seconds "$old" "$scene" "" "$options") b=$(seconds "$new" "$scene" 0 "$options")
    c=$(seconds "$new" "$scene" 3 "$options")
    # No ">" in a printf's arguments: some awks read it as a redirection into a file "0".
    speedup=$(echo "$a $c" | awk '{ s = 0; if ($2 > 0) s = $1 / $2; printf "%.0f", s }')
    echo "| $shown | $1 | $2 | $3 | $a | $b | $c | ${speedup}× |"
}

# The load before the renders says how much else the machine was doing.
load=$(cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo unknown)
{
    echo "| scene | spheres | planes | triangles | 1.3 brute force (s) | 1.4 mode 0 (s) | 1.4 mode 3, BVH (s) | BVH speed-up |"
    echo "|---|---:|---:|---:|---:|---:|---:|---:|"
    row "$top/scenes/demo.scn" "scenes/demo.scn" ""
    row "$top/scenes/bvh-torus.scn" "scenes/bvh-torus.scn" ""
    row "$top/scenes/mirrors-facing.scn" "scenes/mirrors-facing.scn" ""
    for scene in fall2016-a/sceneFiles/spiral.scn fall2016-a/sceneFiles/test_scene_5.scn \
        fall2016-a/sceneFiles/teapot.scn fall2016-a/legoScene/lego.scn \
        fall2016-a/sceneFiles/bunny.scn fall2016-a/newSceneFiles/scenes/trophy.txt; do
        row "$corpus/$scene" "course: $scene (scale 0.1)" "--scale 0.1"
    done
} >"$tmp/table"
echo >>"$tmp/table"
echo "*Seconds of a whole run (reading the scene, building, rendering, writing), one thread, on $(nproc) cores with a load average of $load before the run, $(date -u +%Y-%m-%d); made by bench/render-times.sh.*" >>"$tmp/table"

if [ "${1:-}" = --update ]; then
    chapter=$2
    awk -v table="$tmp/table" '
        /<!-- end render-times -->/ { skip = 0 }
        !skip { print }
        /<!-- render-times -->/ { while ((getline line < table) > 0) print line; skip = 1 }
    ' "$chapter" >"$tmp/chapter" && cp "$tmp/chapter" "$chapter"
fi
cat "$tmp/table"
