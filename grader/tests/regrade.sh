#!/bin/sh
# regrade.sh: tests regrading some students into a class's grading (--only) and the progress lines.
#
# Usage: grader/tests/regrade.sh GRADE RAYTRA   (make -C grader test runs it)
#   GRADE   the grader, grader/build/grade, with imgdiff beside it
#   RAYTRA  part 1.1's program: it plays a correct student
#
# A made-up class of part 1.1 is graded; then a student's submission is fixed and regraded
# with --only: only that student's verdicts change, every other row of grades.csv stays
# byte for byte, the report lists the whole class and is the one a new grading of the whole
# class writes (grader/tests/same-grades.sh), as into a merge of shards. Then --only's
# refusals, a regrade interrupted and taken up by the next, and the progress lines' form:
# "[k of N done, T elapsed, ETA T]". Exit status 0 when every check passes.
set -u
[ $# -eq 2 ] || { echo "usage: $0 GRADE RAYTRA" >&2; exit 2; }
case $1 in /*) grade=$1 ;; *) grade=$(pwd)/$1 ;; esac
case $2 in /*) raytra=$2 ;; *) raytra=$(pwd)/$2 ;; esac
top=$(cd "$(dirname "$0")/../.." && pwd)
same="sh $top/grader/tests/same-grades.sh"
refs=$top/milestones/1.1-spheres-red/references
# How many scenes part 1.1 grades (renders.txt's lines but comments and illustrations).
n=$(grep -c '^[^#![:space:]]' "$refs/renders.txt")
tmp=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
cd "$tmp" || exit 2

. "$top/tests/checks.sh"

# A duration as the grader writes it, and the end of a progress line.
span='[0-9]+ (s|min [0-9]+ s|h [0-9]+ min)'

# Runs grade with the arguments, expecting it to refuse (exit 2) saying $1, and to leave
# the class's output folder "one" as it was.
check_refused() {
    said=$1
    shift
    "$grade" -q "$@" 2>stderr.txt
    check "$*: exit 2" test $? -eq 2
    check "$*: says '$said'" grep -qF -- "$said" stderr.txt
    check "$*: the report and the table left as they were" \
        sh -c 'cmp -s one/report.html before.html && cmp -s one/grades.csv before.csv'
}

# The class: images right (ann, "cy o'neil", "dee,jr": a name with a comma), one missing
# (bea), a program (eli: RAYTRA behind a Makefile), a build that fails (fay).
for who in ann bea "cy o'neil" "dee,jr"; do
    mkdir -p "class/$who"
    cp "$refs"/*.png "class/$who/"
done
rm class/bea/demo.png
mkdir class/eli class/fay
cp "$raytra" class/eli/model || exit 2
printf 'raytra:\n\tcp model raytra\n' >class/eli/Makefile
printf 'raytra:\n\t@echo no compiler >&2; exit 1\n' >class/fay/Makefile

"$grade" --jobs 2 --out one 1.1 class 2>stderr.txt
check "the class graded" test -f one/report.html -a -f one/results.txt
check "progress, two at a time: a line a submission, k of N done, elapsed, ETA" \
    test "$(grep -Ec "^grading .* \[[1-5] of 6 done, $span elapsed, ETA $span\]\$" stderr.txt)" -eq 5
check "progress: the last line says the class done, without an ETA" \
    grep -Eq "^grading .* \[6 of 6 done, $span elapsed\]\$" stderr.txt
check "progress: a failed build's line too" \
    grep -Eq "^grading fay \(program\): building\.\.\. BUILD FAILED: .* \[[1-6] of 6 done, " stderr.txt
cp one/report.html before.html
cp one/grades.csv before.csv

# bea hands in the image she forgot; a marker shows which work folders are made anew.
cp "$refs/demo.png" class/bea/
touch one/work/01-ann/kept one/work/02-bea/old
"$grade" --only bea --out one 1.1 class 2>stderr.txt
check "--only bea: exit 0" test $? -eq 0
check "--only bea: says the class and that it regrades" \
    grep -q "^grade: part 1.1-spheres-red, $n scenes, 1 submission (regraded with --only, of a class of 6)$" stderr.txt
check "--only bea: its progress line" \
    grep -Eq "^grading bea \(images\): $n scenes: $n pass \[1 of 1 done, $span elapsed\]\$" stderr.txt
check "--only bea: one progress line" test "$(grep -c '^grading ' stderr.txt)" -eq 1
check "--only bea: says who was regraded and what was kept" \
    grep -q "^grade: regraded bea; the results of the other 5 of the class's 6 submissions are kept from one/results.txt$" stderr.txt
check "--only bea: her demo now passes" grep -q '^bea,demo,PASS,' one/grades.csv
check "--only bea: her other rows as they were" \
    test "$(grep '^bea,' one/grades.csv | grep -v '^bea,demo,')" = "$(grep '^bea,' before.csv | grep -v '^bea,demo,')"
check "--only bea: every other row of grades.csv byte for byte" \
    test "$(grep -v '^bea,' one/grades.csv)" = "$(grep -v '^bea,' before.csv)"
check "--only bea: the report lists the whole class" \
    test "$(grep -c '<section id="s[0-9]*">' one/report.html)" -eq 6
for who in ann bea "cy o&#39;neil" "dee,jr" eli fay; do
    check "--only bea: the report shows $who" grep -q "<span class=\"name\">$who</span>" one/report.html
done
check "--only bea: her work folder made anew" test ! -e one/work/02-bea/old
check "--only bea: the others' work folders kept" test -e one/work/01-ann/kept
check "--only bea: no mark of a regrade left" test ! -e one/.regrading
"$grade" -q --out fresh 1.1 class 2>stderr.txt
check "--only bea: the report and table of a new grading of the whole class" $same fresh one

# Two at a time, a program among them, a name that holds a quote and one a comma; --junit.
cp one/grades.csv before.csv
"$grade" --only "eli,cy o'neil,dee,jr" --jobs 2 --junit junit.xml --out one 1.1 class 2>stderr.txt
check "--only of three, two at a time: exit 0" test $? -eq 0
check "--only of three: says which, in the class's order" \
    grep -q "^grade: regraded cy o'neil, dee,jr, eli; the results of the other 3 " stderr.txt
check "--only of three: their progress lines counted" \
    test "$(grep -Ec "^grading .* \[[1-3] of 3 done, $span elapsed" stderr.txt)" -eq 3
check "--only of three: the rows of the others byte for byte" \
    test "$(grep -Ev "^(eli|cy o'neil|\"dee,jr\")," one/grades.csv)" = "$(grep -Ev "^(eli|cy o'neil|\"dee,jr\")," before.csv)"
check "--only of three: their verdicts as before (nothing changed)" \
    test "$(cut -d, -f1-3 one/grades.csv)" = "$(cut -d, -f1-3 before.csv)"
check "--only with --junit: the whole class's test cases" \
    test "$(grep -c "<testcase " junit.xml)" -eq $((6 * n))
check "--only of three: still a new grading's report and table" $same fresh one

# Into a merge of shards: the same.
rm class/bea/demo.png
for k in 1 2; do "$grade" -q --shard $k/2 --out "shard $k" 1.1 class 2>stderr.txt; done
"$grade" merge -q --out merged "shard 1" "shard 2" 2>stderr.txt
check "a merge leaves the class's results" test -f merged/results.txt
cp "$refs/demo.png" class/bea/
"$grade" -q --only bea --out merged 1.1 class 2>stderr.txt
check "--only into a merge: exit 0" test $? -eq 0
check "--only into a merge: a new grading's report and table" $same fresh merged
check "--only into a merge: her work folder no longer the shard's" \
    test -d merged/work/02-bea -a ! -L merged/work/02-bea
check "--only into a merge: the others' still the shards'" test -L merged/work/01-ann
check "--only into a merge: the report's command line runs from its folder" \
    test -f "merged/$(grep -o 'cd work/[^ ]*/run' merged/report.html | head -n 1 | cut -c 4-)/../images/demo.png"

# -q: nothing said.
"$grade" -q --only bea --out one 1.1 class 2>stderr.txt
check "--only -q: quiet" test ! -s stderr.txt

# Refusals: nothing graded, the report and the table kept.
cp one/report.html before.html
cp one/grades.csv before.csv
check_refused "--only: 'zed' is not a submission of class" --only zed --out one 1.1 class
check_refused "--only: 'zed' is not a submission of class" --only bea,zed --out one 1.1 class
check_refused "--only: no folder nowhere:" --only bea --out nowhere 1.1 class
check "... and no folder made" test ! -e nowhere
check_refused "--only: no shard 1/results.txt: shard 1 holds no grading of a class" \
    --only bea --out "shard 1" 1.1 class
check_refused "--only: one holds a grading of part 1.1-spheres-red, not of 1.2-shading" \
    --only bea --out one 1.2 class
check_refused "--only: one was graded from other tolerances" --only bea --threshold 0.1 --out one 1.1 class
check_refused "--only cannot go with --shard" --only bea --shard 1/2 --out one 1.1 class
check_refused "--only cannot go with --self" --only bea --self --out one 1.1 class/bea
mkdir class/gus
cp "$refs"/*.png class/gus/
check_refused "--only: one was graded from another class: other submissions" --only bea --out one 1.1 class
rm -rf class/gus
rm one/results.txt
check_refused "--only: no one/results.txt" --only bea --out one 1.1 class

# A regrade interrupted: the report and results kept; the next --only regrades its students.
mkdir -p slow/quick slow/slow
cp "$refs"/*.png slow/quick/
printf 'raytra:\n\tprintf "#!/bin/sh\\nexec sleep 60\\n" >raytra; chmod +x raytra\n' >slow/slow/Makefile
"$grade" -q --time-limit 1 --out two 1.1 slow 2>stderr.txt
cp two/report.html before.html
"$grade" --time-limit 1 --only slow --out two 1.1 slow 2>stderr.txt &
pid=$!
sleep 2
kill -INT $pid
wait $pid
check "--only interrupted: exit 130" test $? -eq 130
check "--only interrupted: says the earlier report stays" grep -q "^grade: interrupted: the report and results .* are still the earlier grading's" stderr.txt
check "--only interrupted: the report kept" cmp -s two/report.html before.html
"$grade" --time-limit 1 --only quick --out two 1.1 slow 2>stderr.txt
check "--only after one interrupted: exit 0" test $? -eq 0
check "--only after one interrupted: regrades its student too, saying so" \
    grep -q "^grade: slow's regrade did not finish before: regraded too$" stderr.txt
check "--only after one interrupted: both graded" test "$(grep -c '^grading ' stderr.txt)" -eq 2
check "--only after one interrupted: the mark gone" test ! -e two/.regrading

if [ "$failures" -eq 0 ]; then
    echo "regrade.sh: all $checks checks passed"
else
    echo "regrade.sh: $failures of $checks checks failed (KEEP=1 keeps $tmp)"
    exit 1
fi
