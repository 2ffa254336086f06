#!/bin/sh
# grade-judges.sh: tests grader/grade's other judgements of renders.txt: IMAGE=OTHER and IMAGE>MASK.
#
# Usage: grader/tests/grade-judges.sh GRADE   (make -C grader test runs it)
#   GRADE   the grader, grader/build/grade, with imgdiff beside it
#
# A made-up part in a temporary folder, with part 1.4's demo references and a renders.txt
# of both kinds, grades a class of folders of images (no program is run): images equal
# where they must be, a mode 0 image unlike the reference, one like the reference (with
# --allow 1) but unlike the program's own mode 3, a mode 2 image that leaves black what
# mode 1 draws, a missing image to be equal to; in one run and in two shards merged
# (the judgements go through shard.txt), which must give the same report and CSV. Then renders.txt lines that
# name nothing are refused, and programs whose image passes are judged by the BVH they report
# (empty leaves, too many nodes, too deep). Exit status 0 when every check passes.
set -u
[ $# -eq 1 ] || { echo "usage: $0 GRADE" >&2; exit 2; }
case $1 in /*) grade=$1 ;; *) grade=$(pwd)/$1 ;; esac
top=$(cd "$(dirname "$0")/../.." && pwd)
refs=$top/milestones/1.4-bvh/references
tmp=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
cd "$tmp" || exit 2

. "$top/tests/checks.sh"

part=$tmp/1.4-bvh
mkdir -p "$part/references" class
cp "$refs/demo.png" "$refs/demo-mode-1.png" "$refs/demo-mode-2.png" "$part/references/"
cat >"$part/references/renders.txt" <<'END'
demo.png                          scenes/demo.scn
demo-mode-1.png                   scenes/demo.scn   --mode 1
#? a leaf box leaves out a primitive
demo-mode-2.png>demo-mode-1.png   scenes/demo.scn   --mode 2
#? mode 3 misses the closest hit
demo-mode-0.png=demo.png          scenes/demo.scn   --mode 0
END

# Makes submission $1 a folder of the four images, each copied from the file named after it.
images() {
    mkdir "class/$1"
    cp "$refs/$2" "class/$1/demo.png"
    cp "$refs/$3" "class/$1/demo-mode-1.png"
    cp "$refs/$4" "class/$1/demo-mode-2.png"
    cp "$refs/$5" "class/$1/demo-mode-0.png"
}
images right demo.png demo-mode-1.png demo-mode-2.png demo.png
# One box around everything is what a BVH of one leaf draws: it covers mode 1.
images one-leaf demo.png demo-mode-1.png demo-mode-1.png demo.png
images mode-0-differs demo.png demo-mode-1.png demo-mode-2.png demo-mode-1.png
# Wrong alike in modes 0 and 3 (a program that draws nothing, say): no scene passes.
images wrong-alike demo-mode-1.png demo-mode-1.png demo-mode-2.png demo-mode-1.png
images surfaces-in-mode-2 demo.png demo-mode-1.png demo.png demo.png
mkdir class/no-mode-3
cp "$refs/demo.png" class/no-mode-3/demo-mode-0.png

"$grade" -q --out one "$part" class || fail "grade failed"
csv=one/grades.csv
# Checks that the CSV has a line starting with $1 and holding $2.
has() {
    checks=$((checks + 1))
    grep "^$1" "$csv" | grep -qF -- "$2" || fail "no line '$1...$2...' in the CSV"
}
for s in right one-leaf; do
    for scene in demo demo-mode-1 demo-mode-2 demo-mode-0; do has "$s,$scene,PASS," ""; done
done
has right,demo-mode-0,PASS, "matches the reference, and equals this program's own demo.png pixel for pixel"
has right,demo-mode-2,PASS, "0% of the pixels are black here and drawn in demo-mode-1.png"
has mode-0-differs,demo-mode-0,FAIL, "of the pixels differ by more than 2/255, more than the 0.1% allowed"
has mode-0-differs,demo,PASS, ""
has wrong-alike,demo,FAIL, ""
has wrong-alike,demo-mode-0,FAIL, "of the pixels differ by more than 2/255"
has surfaces-in-mode-2,demo-mode-2,FAIL, "1.11% of the pixels are black here and drawn in demo-mode-1.png, more than the 0.1% allowed: a leaf box leaves out a primitive"
has surfaces-in-mode-2,demo-mode-0,PASS, ""
has no-mode-3,demo,MISSING, ""
has no-mode-3,demo-mode-0,ERROR, "not judged: it must equal this program's own demo.png, which could not be compared (MISSING)"

# With --allow 1 every image matches its reference: mode 0 must still equal mode 3.
mkdir class2
mv class/right class/mode-0-differs class2/
"$grade" -q --allow 1 --out allow "$part" class2 || fail "grade --allow 1 failed"
csv=allow/grades.csv
has mode-0-differs,demo-mode-0,FAIL, "differ from this program's own demo.png; the two must be equal pixel for pixel: mode 3 misses the closest hit"
has right,demo-mode-0,PASS, "equals this program's own demo.png"

# The same grading in two shards merged.
mv class2/* class/
if ! { "$grade" -q --shard 1/2 --out shard1 "$part" class &&
    "$grade" -q --shard 2/2 --out shard2 "$part" class &&
    "$grade" merge -q --out merged shard1 shard2; }; then
    fail "grade --shard or merge failed"
fi
check "two shards merged grade as one run does" sh "$top/grader/tests/same-grades.sh" one merged

# renders.txt lines that name nothing to judge against are refused, saying which.
refused() { # LINE WORDS
    printf 'demo.png scenes/demo.scn\n%s\n' "$1" >"$part/references/renders.txt"
    checks=$((checks + 1))
    if "$grade" -q --out refused "$part" class 2>err; then
        fail "grade took the line '$1'"
    elif ! grep -qF -- "$2" err; then
        fail "grade refused '$1' without saying '$2': $(cat err)"
    fi
}
refused "demo-mode-0.png=nothing.png scenes/demo.scn" "no earlier line renders nothing.png"
refused "demo-mode-2.png>nothing.png scenes/demo.scn" "no reference image $part/references/nothing.png"
refused "demo-mode-0.png=demo-mode-0.png scenes/demo.scn" "no earlier line renders demo-mode-0.png"

# A program whose image passes is judged by what it reports of its BVH (grade_bvh.c): each
# submission a script that writes the reference and prints the report line it is given.
printf 'demo.png scenes/demo.scn\n' >"$part/references/renders.txt"
mkdir trees
tree() { # NAME REPORT: a program that prints REPORT (no BVH line when empty)
    mkdir "trees/$1"
    cp "$refs/demo.png" "trees/$1/image.png"
    printf '#!/bin/sh\ncat "$(dirname "$0")/image.png" >"$2"\n%s\n' \
        "${2:+echo \"raytra: mode 3: BVH of $2, 62.4 bytes per primitive\" >&2}" >"trees/$1/program"
    printf 'raytra: program\n\tcp program raytra\n\tchmod +x raytra\n' >"trees/$1/Makefile"
}
tree right "25 primitives: 13 interior nodes, 14 leaves (0 empty), depth 7"
tree no-line ""
tree empty "25 primitives: 13 interior nodes, 14 leaves (3 empty), depth 7"
tree nodes "25 primitives: 30 interior nodes, 31 leaves (0 empty), depth 7"
tree deep "25 primitives: 13 interior nodes, 14 leaves (0 empty), depth 38"
"$grade" -q --out trees-out "$part" trees || fail "grade of programs failed"
csv=trees-out/grades.csv
has right,demo,PASS, ""
has no-line,demo,PASS, ""
has empty,demo,FAIL, "the BVH has 3 empty leaves"
has nodes,demo,FAIL, "the BVH has 30 interior nodes over 25 primitives, more than the n - 1 = 24"
has deep,demo,FAIL, "the BVH is 38 levels deep, more than the 37"

echo "grade-judges.sh: $((checks - failures)) of $checks checks pass"
[ "$failures" -eq 0 ]
