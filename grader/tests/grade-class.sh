#!/bin/sh
# grade-class.sh: tests grading a class at scale: --jobs, --shard K/N and grade merge.
#
# Usage: grader/tests/grade-class.sh GRADE RAYTRA   (make -C grader test runs it)
#   GRADE   the grader, grader/build/grade, with imgdiff beside it
#   RAYTRA  part 1.1's program: it renders the class's images and plays a correct student
#
# A made-up class of part 1.1 (images right and wrong, a program, a build that fails, a name
# that needs quoting) is graded one at a time, two at a time, and in three shards merged:
# the three reports and tables must be the same apart from times (grader/tests/same-grades.sh).
# Then shards that do not belong together are given to grade merge, which must refuse each
# with its reason and write nothing. Exit status 0 when every check passes.
set -u
[ $# -eq 2 ] || { echo "usage: $0 GRADE RAYTRA" >&2; exit 2; }
case $1 in /*) grade=$1 ;; *) grade=$(pwd)/$1 ;; esac
case $2 in /*) raytra=$2 ;; *) raytra=$(pwd)/$2 ;; esac
top=$(cd "$(dirname "$0")/../.." && pwd)
same="sh $top/grader/tests/same-grades.sh"
refs=$top/milestones/1.1-spheres-red/references
tmp=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
cd "$tmp" || exit 2

. "$top/tests/checks.sh"

# Runs grade merge with the arguments, expecting it to refuse (exit 2) saying $1, and to
# leave the output folder "refused" as it was.
check_refused() {
    said=$1
    shift
    "$grade" merge -q --out refused "$@" 2>stderr.txt
    check "merge $*: exit 2" test $? -eq 2
    check "merge $*: says '$said'" grep -qF -- "$said" stderr.txt
    check "merge $*: the earlier report left as it was" cmp -s refused/report.html before.html
}

# The class: four folders of images (right; one scene missing; one scene another's image,
# of another size; one a little wrong, with a name to quote), a program (RAYTRA behind a
# Makefile), a build that fails.
for who in ann bea "cy o'neil" dee; do
    mkdir -p "class/$who"
    cp "$refs"/*.png "class/$who/"
done
rm class/bea/demo.png
cp "$refs/spheres-three.png" class/dee/demo.png
sed 's/^s 25 -5 -90   10$/s 25.5 -5 -90   10/' "$top/scenes/spheres-three.scn" >moved.scn
"$raytra" -q moved.scn "class/cy o'neil/spheres-three.png" 2>/dev/null || exit 2
mkdir class/eli class/fay
# eli carries the model answer (the sandbox shows a build nothing outside its folder).
cp "$raytra" class/eli/model || exit 2
printf 'raytra:\n\tcp model raytra\n' >class/eli/Makefile
printf 'raytra:\n\t@echo no compiler in $(CURDIR) >&2; exit 1\n' >class/fay/Makefile
# Build outputs eli carries from elsewhere, removed before make: a stale raytra among them.
mkdir class/eli/build
printf '#!/bin/sh\nexit 3\n' >class/eli/raytra
chmod +x class/eli/raytra
touch class/eli/main.o class/eli/build/main.o
# The instructor's controls: points, visibilities and a hidden scene of their own, all of
# which the workers and the shards must hand on to the report as one run makes it.
mkdir hidden
sed 's/^s 25 -5 -90   10$/s 20 -5 -90   12/' "$top/scenes/spheres-three.scn" >hidden/own.scn
printf 'own.png own.scn\n' >hidden/renders.txt
printf 'part 20\nhidden hidden\n* 1\ndemo 3 after_due_date\nown 4 hidden\n' >grading.conf
set -- --grading-conf grading.conf

# One at a time, two at a time, and three shards (one of them two at a time) merged.
"$grade" -q "$@" --out one 1.1 class 2>stderr.txt
check "--jobs 1 writes a report" test -f one/report.html
check "the work folder's path written work/ in the report" \
    grep -q "<pre>no compiler in work/06-fay/build$" one/report.html
check "the class's verdicts" test "$(cut -d, -f3 one/grades.csv | sort | uniq -c | tr -s ' ' | tr '\n' ';')" \
    = " 8 BUILD FAILED; 1 FAIL; 5 MISSING; 33 PASS; 1 WRONG SIZE; 1 verdict;"
check "the hidden scene: the images handed in have none" \
    test "$(grep -c '^[a-z'"'"' ]*,own,MISSING,' one/grades.csv)" -eq 4
check "the hidden scene: the program passes it" grep -q '^eli,own,PASS,' one/grades.csv
check "eli's build outputs: not said removed" grep -q \
    "removed before make: <code>build/$(printf '\nmain.o\nraytra')</code>" one/report.html
check "eli's points: not 20 of 20" grep -q "8 of 8 scenes pass: 20 of 20 points" one/report.html
check "ann's points: not 13.8462 of 20 (9 of the scenes' 13, scaled to 20)" \
    grep -q "7 of 8 scenes pass: 13.8462 of 20 points" one/report.html
"$grade" -q "$@" --jobs 2 --out two 1.1 class 2>stderr.txt
check "--jobs 2: the same report and table as --jobs 1" $same one two
check "--jobs 2: no results file left behind" test -z "$(ls -A two/work | grep results)"
for k in 1 2 3; do
    "$grade" -q "$@" --shard $k/3 --jobs $((k % 2 + 1)) --out "shard $k" 1.1 class 2>stderr.txt
    check "shard $k of 3 written" test -f "shard $k/shard.txt" -a ! -e "shard $k/report.html"
done
check "shard 1 holds every third submission from the first" \
    test "$(ls "shard 1/work" | tr '\n' ' ')" = "01-ann 04-dee canaries hidden-scenes references "
"$grade" merge -q --out merged "shard 3" "shard 1" "shard 2" 2>stderr.txt
check "merge: exit 0" test $? -eq 0
check "merge: the same report and table as one run" $same one merged
check "merge: the report's command line runs from its folder" \
    test -f "merged/$(grep -o 'cd work/[^ ]*/run' merged/report.html | head -n 1 | cut -c 4-)/../images/demo.png"

# Merges that are refused: nothing written, the earlier report kept.
cp merged/report.html before.html
"$grade" merge -q --out refused "shard 1" "shard 2" "shard 3" 2>stderr.txt
cp refused/report.html before.html
check_refused "shard 2 of 3 is missing" "shard 1" "shard 3"
check_refused "shard 1 of 3 is given twice" "shard 1" "shard 1" "shard 2" "shard 3"
# Shards made otherwise, of a class of images alone (quick): each refused beside the others.
mkdir mini
cp -R class/ann class/bea class/dee mini/
for k in 1 3; do "$grade" -q --shard $k/3 --out "mini $k" 1.1 mini 2>stderr.txt; done
"$grade" -q --shard 2/3 --out mini-2 1.1 mini 2>stderr.txt
check "mini: the shards merge" "$grade" merge -q --out mini-merged "mini 1" mini-2 "mini 3"
"$grade" -q --shard 2/2 --out half 1.1 mini 2>stderr.txt
check_refused "half is shard 2 of 2, mini 1 of 3" "mini 1" half "mini 3"
"$grade" -q --shard 2/3 --out strict --threshold 0.001 1.1 mini 2>stderr.txt
check_refused "other tolerances" "mini 1" strict "mini 3"
"$grade" -q --shard 2/3 --out lenient --standard ok 1.1 mini 2>stderr.txt
check "a shard notes its --standard" grep -q '^tolerances .* =ok$' lenient/shard.txt
check_refused "other tolerances or another --standard" "mini 1" lenient "mini 3"
mkdir -p other/1.1-spheres-red
cp -R "$refs" other/1.1-spheres-red/
cp "$refs/demo.png" other/1.1-spheres-red/references/spheres-three.png
"$grade" -q --shard 2/3 --out moved other/1.1-spheres-red mini 2>stderr.txt
check_refused "other references or scenes (render spheres-three.png)" "mini 1" moved "mini 3"
printf 'spheres-three 2\n' >other.conf
"$grade" -q --shard 2/3 --out pointed --grading-conf other.conf 1.1 mini 2>stderr.txt
check_refused "other references or scenes (render spheres-three.png)" "mini 1" pointed "mini 3"
printf 'part 7\n' >other.conf
"$grade" -q --shard 2/3 --out pointed --grading-conf other.conf 1.1 mini 2>stderr.txt
check_refused "another grading.conf (points" "mini 1" pointed "mini 3"
"$grade" -q --shard 2/3 --out shaded 1.2 mini 2>stderr.txt
check_refused "another part" "mini 1" shaded "mini 3"
cp -R mini smaller
rm -rf smaller/dee
"$grade" -q --shard 2/3 --out fewer 1.1 smaller 2>stderr.txt
check_refused "another class folder" "mini 1" fewer "mini 3"
mv mini mini-moved
cp -R mini-moved mini
mkdir mini/abe
"$grade" -q --shard 2/3 --out grown 1.1 mini 2>stderr.txt
check_refused "another class: other submissions" "mini 1" grown "mini 3"
rm "shard 2/shard.txt"
check_refused "did not finish" "shard 1" "shard 2" "shard 3"
check_refused "no shard folder nowhere" "shard 1" nowhere "shard 3"
# A shard.txt that is a FIFO, or a link: refused at once, never waited on nor followed; a
# lock that is a FIFO: not waited on either.
mkfifo "shard 2/shard.txt"
timeout 10 "$grade" merge -q --out refused "shard 1" "shard 2" "shard 3" 2>stderr.txt
check "a shard.txt that is a FIFO: exit 2 at once" test $? -eq 2
check "a shard.txt that is a FIFO: says so" \
    grep -qxF "grade: shard 2/shard.txt is not a regular file (a FIFO): not the results of grade --shard" stderr.txt
rm "shard 2/shard.txt"
ln -s "../shard 1/shard.txt" "shard 2/shard.txt"
check_refused "shard 2/shard.txt is not a regular file (a symbolic link)" "shard 1" "shard 2" "shard 3"
rm "shard 2/shard.txt"
cp -R "mini 3" "mini 3 fifo"
rm -f "mini 3 fifo/.grade-lock"
mkfifo "mini 3 fifo/.grade-lock"
check "a lock that is a FIFO: not waited on" \
    timeout 10 "$grade" merge -q --out fifo-merged "mini 1" mini-2 "mini 3 fifo"
if command -v flock >/dev/null 2>&1; then
    # -o: the lock is flock's own, and goes with it when it is killed.
    flock -o "mini 3/.grade-lock" sleep 5 &
    locker=$!
    sleep 1
    check_refused "mini 3 is still being graded" "mini 1" mini-2 "mini 3"
    kill $locker
    wait $locker 2>/dev/null
else
    echo "grade-class.sh: no flock(1): a shard still being graded is not tried"
fi
"$grade" merge -q --out "mini 1" "mini 1" mini-2 "mini 3" 2>stderr.txt
check "merge into a shard's folder: exit 2" test $? -eq 2
check "merge into a shard's folder: says why" grep -q "would replace the work of the shard" stderr.txt
check "merge into a shard's folder: its work kept" test -d "mini 1/work/01-ann"
check "no report in a refused merge's new folder" sh -c \
    '! "$0" merge -q --out new "shard 1" "shard 3" 2>/dev/null && test ! -e new/report.html' "$grade"

# A shard.txt damaged: cut anywhere, a word changed, bytes of nothing: refused, never a crash.
cp -R "mini 1" damaged
lines=$(wc -l <"mini 1/shard.txt")
for damage in "head -n 1" "head -n 9" "head -n $((lines - 1))" "head -c 700" \
    "sed s/^scene.0/scene.99/" "sed s/^sub.=/sub.%%/" "sed s/^shard.1.3/shard.4.3/" "sed s/=ann/-/" \
    "head -c 300 /dev/urandom"; do
    $damage "mini 1/shard.txt" >damaged/shard.txt 2>/dev/null
    "$grade" merge -q --out refused damaged mini-2 "mini 3" 2>stderr.txt
    check "a shard.txt damaged ($damage): refused" test $? -eq 2
    check "a shard.txt damaged ($damage): says where" grep -q "damaged/shard.txt" stderr.txt
done

# A shard's bad K/N, and a shard whose output would be listed by the others as a student.
for bad in 0/2 3/2 1/0 x 1/2/3; do
    "$grade" -q --shard "$bad" 1.1 class 2>stderr.txt
    check "--shard $bad refused" test $? -eq 2
    check "--shard $bad: says why" grep -q "^grade: --shard takes K/N" stderr.txt
done
"$grade" -q --shard 1/2 --out class/out 1.1 class 2>stderr.txt
check "a shard's --out inside the class refused" grep -q "inside the class" stderr.txt
check "... and not made" test ! -e class/out
"$grade" -q --shard 1/2 --self 1.1 class/ann 2>stderr.txt
check "--shard with --self refused" grep -q "^grade: --shard cannot go with --self" stderr.txt

# Interrupted with two at a time: every worker ends, and no report is written.
mkdir -p slow/a slow/b
for who in a b; do
    printf 'raytra:\n\tprintf "#!/bin/sh\\nexec sleep 60\\n" >raytra; chmod +x raytra\n' >slow/$who/Makefile
done
"$grade" -q --jobs 2 --out stopped 1.1 slow 2>stderr.txt &
pid=$!
sleep 2
kill -INT $pid
wait $pid
check "--jobs 2 interrupted: exit 130" test $? -eq 130
check "--jobs 2 interrupted: no report" test ! -e stopped/report.html
# A sandbox's processes die with its PID namespace, which the kernel tears down a few
# milliseconds after the grader has ended its first process (longer on a loaded machine): 5 s are given.
for _ in $(seq 50); do
    [ -z "$(ps -eo args | grep -x 'sleep 60')" ] && break
    sleep 0.1
done
check "--jobs 2 interrupted: no program left running" \
    test -z "$(ps -eo args | grep -x 'sleep 60')"
"$grade" --shard 1/2 --out stopped-shard 1.1 slow 2>stderr.txt &
pid=$!
sleep 2
kill -INT $pid
wait $pid
check "a shard interrupted: exit 130" test $? -eq 130
check "a shard interrupted: says no report, or not that its shard.txt was not written" \
    sh -c '! grep -q "no report" stderr.txt && grep -q "the shard.s results (shard.txt) were not written" stderr.txt'

if [ "$failures" -eq 0 ]; then
    echo "grade-class.sh: all $checks checks passed"
else
    echo "grade-class.sh: $failures of $checks checks failed (KEEP=1 keeps $tmp)"
    exit 1
fi
