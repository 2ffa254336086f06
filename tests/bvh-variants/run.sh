#!/bin/sh
# run.sh: shows that grading part 1.4 passes every correct BVH and fails wrong ones.
#
# Usage: tests/bvh-variants/run.sh GRADE VARIANTS
#   GRADE     the grader, grader/build/grade
#   VARIANTS  the folder of the programs raytra-NAME (make -C tests/bvh-variants)
# Grades a class of one submission a variant (its program and a Makefile that copies it) with
# grader/grade, two at a time, and checks grades.csv: every scene of a right variant
# passes; each wrong one fails the scenes listed below, each with the words that say
# what is wrong, and passes the others. Prints each variant's verdicts; exit status 0
# when everything is as expected, 1 otherwise.
set -u
[ $# -eq 2 ] || { echo "usage: $0 GRADE VARIANTS" >&2; exit 2; }
case $1 in /*) grade=$1 ;; *) grade=$(pwd)/$1 ;; esac
case $2 in /*) variants=$2 ;; *) variants=$(pwd)/$2 ;; esac
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

# Each variant: pass, or SCENE:WORDS for each scene it must fail, WORDS (_ for a space) in
# the message that says why; every other scene it must pass.
#   ties-first and ties-last break ties between surfaces at the same t otherwise than
#   leaf_closest's contract says (by the traversal's order; the larger surface number):
#   correct BVHs all the same, which pass. Only degenerate-geometry, whose mesh has
#   coincident faces of opposite normals, shows the difference (2.9 % of its pixels), and
#   part 1.4 does not grade it (part 1.3 does). That ties-last passes demo-mode-0 and
#   torus-mode-0 shows that no two surfaces tie for a pixel of those scenes.
#   partition-le and no-depth-cap draw every image right: they fail by their trees' shape,
#   from the line the program prints about its BVH (grader/grade_bvh.c).
#   no-swap fails demo-mode-2 with the words of its #? line (renders.txt) that say the
#   boxes are drawn wrong (box_hit_face).
expectations="median-one:pass sah-ties:pass bins-8:pass ties-first:pass ties-last:pass
first-hit:demo-mode-0:does_not_find_the_closest_hit first-hit:torus:pixels_differ
first-hit:torus-mode-0:does_not_find_the_closest_hit
centroid-boxes:demo:pixels_differ centroid-boxes:demo-mode-2:leaf_box
centroid-boxes:demo-mode-0:does_not_find_the_closest_hit centroid-boxes:torus:pixels_differ
centroid-boxes:torus-mode-0:does_not_find_the_closest_hit centroid-boxes:chain:pixels_differ
partition-le:torus:empty_leaves no-depth-cap:chain:levels_deep
no-swap:demo-mode-1:pixels_differ no-swap:torus-mode-1:pixels_differ
no-swap:demo-mode-2:draws_boxes_wrong
unpadded:torus-mode-1:pixels_differ
two-corners:demo:differ two-corners:demo-mode-1:differ two-corners:demo-mode-0:differ
two-corners:torus:differ two-corners:torus-mode-1:differ two-corners:torus-mode-0:differ
two-corners:chain:differ"

mkdir "$tmp/class"
for program in "$variants"/raytra-*; do
    name=${program##*/raytra-}
    mkdir "$tmp/class/$name"
    # The submission carries its program: the sandbox shows a build nothing but its folder.
    cp "$program" "$tmp/class/$name/model" || exit 2
    printf "raytra: model\n\tcp model raytra\n" >"$tmp/class/$name/Makefile"
done
# The time limit is generous: what is tested is the verdicts, on a machine maybe busy.
"$grade" -q --jobs 2 --time-limit 600 --out "$tmp/out" 1.4 "$tmp/class" ||
    { echo "run.sh: grade failed" >&2; exit 1; }
csv=$tmp/out/grades.csv
failed=0
for program in "$variants"/raytra-*; do
    name=${program##*/raytra-}
    rules=$(echo "$expectations" | tr ' ' '\n' | grep "^$name:")
    [ -n "$rules" ] || { echo "FAIL $name: run.sh expects nothing of it"; failed=1; continue; }
    echo "== $name"
    # Each row: SCENE VERDICT and the CSV's line (submission,scene,verdict,...,message,...).
    awk -F, -v name="$name" '$1 == name { print $2, $3, $0 }' "$csv" >"$tmp/rows"
    [ -s "$tmp/rows" ] || { echo "FAIL $name: not in grades.csv"; failed=1; continue; }
    while read -r scene verdict message; do
        words=$(echo "$rules" | sed -n "s/^$name:$scene:\\(.*\\)/\\1/p" | tr _ ' ')
        if [ -z "$words" ] && [ "$verdict" = PASS ]; then
            echo "ok   $scene: PASS"
        elif [ -n "$words" ] && [ "$verdict" = FAIL ] && echo "$message" | grep -qF "$words"; then
            # The message: the CSV's field before the seconds and the flag, quoted or not.
            echo "ok   $scene: FAIL, as it must: $(echo "$message" |
                sed -E 's/.*,"([^"]*)",[0-9.]*,[a-z]*$/\1/; t; s/.*,([^,]*),[0-9.]*,[a-z]*$/\1/')"
        else
            echo "FAIL $scene: $verdict${words:+ (it must fail, saying \"$words\")}: $message"
            failed=1
        fi
    done <"$tmp/rows"
    for scene in $(echo "$rules" | sed -n "s/^$name:\([^:]*\):.*/\1/p"); do
        awk -v s="$scene" '$1 == s { found = 1 } END { exit !found }' "$tmp/rows" ||
            { echo "FAIL $scene: not graded (run.sh expects it)"; failed=1; }
    done
done
exit $failed
