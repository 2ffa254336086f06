#!/bin/sh
# grade.sh: tests grader/grade on a made-up class for part 1.1, one submission for each verdict.
#
# Usage: grader/tests/grade.sh GRADE RAYTRA   (make -C grader test runs it)
#   GRADE   the grader, grader/build/grade, with imgdiff beside it
#   RAYTRA  part 1.1's program: it renders the class's images and plays a correct student
#
# Every fixture is made here, in a temporary folder: images rendered by RAYTRA or copied
# from the references, and tiny Makefiles, shell scripts and C programs. Exit status 0
# when every check passes.
set -u
[ $# -eq 2 ] || { echo "usage: $0 GRADE RAYTRA" >&2; exit 2; }
case $1 in /*) grade=$1 ;; *) grade=$(pwd)/$1 ;; esac
case $2 in /*) raytra=$2 ;; *) raytra=$(pwd)/$2 ;; esac
top=$(cd "$(dirname "$0")/../.." && pwd)
refs=$top/milestones/1.1-spheres-red/references
# The graded scenes, as renders.txt lists them (a name with ! is an illustration), and how many.
scenes=$(awk '$1 !~ /^[#!]/ && NF >= 2 { sub(/[.][a-z]+$/, "", $1); print $1 }' "$refs/renders.txt")
scene_count=$(echo "$scenes" | wc -l)
tmp=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
cd "$tmp" || exit 2

. "$top/tests/checks.sh"

# Renders scene $1 of the repository into image $2 with RAYTRA's options $3...
render() {
    scene=$1 image=$2
    shift 2
    "$raytra" -q "$@" "$scene" "$image" 2>/dev/null || { echo "grade.sh: cannot render $scene" >&2; exit 2; }
}

# Checks that the CSV has the line $1, or a line starting so.
has() {
    checks=$((checks + 1))
    grep -qF -- "$1" "$csv" || fail "no '$1' in the CSV"
}

# Makes submission $1 a folder of images: the references, as they are.
copy_references() {
    mkdir -p "class/$1"
    cp "$refs"/*.png "class/$1/"
}

# Makes submission $1 a program: make copies the shell script read from stdin to raytra.
# The submission carries the program $2 (default: part 1.1's raytra) and moved.scn, which
# the script runs as $model and reads as $moved: a student's program sees nothing outside
# its folder but the toolchain and its scene (the sandbox, grader/docs/containment.md).
script_submission() {
    mkdir -p "class/$1"
    cat >"class/$1/raytra.sh"
    cp "${2:-$raytra}" "class/$1/model" && cp "$tmp/moved.scn" "class/$1/" || exit 2
    printf 'raytra: raytra.sh\n\tcp raytra.sh raytra\n\tchmod +x raytra\n' >"class/$1/Makefile"
}
# shellcheck disable=SC2016 # the students' scripts run and read what they carry
model='"$(dirname "$0")/model"' moved='"$(dirname "$0")/moved.scn"'

# Makes submission $1 a program: make compiles the C program read from stdin to raytra.
c_submission() {
    mkdir -p "class/$1"
    cat >"class/$1/main.c"
    printf 'raytra: main.c\n\tcc -o raytra main.c\n' >"class/$1/Makefile"
}

# Prints the pids of the processes the class's programs must not leave running: their
# command lines are "sleep", NUL, "$nap1" or "$nap2", NUL; numbers of this run's own, so
# that a test running beside it (another checkout's) is not taken for a leftover of it.
nap1=3141$$ nap2=2718$$
leftovers() {
    grep -lasx -e "sleep.$nap1." -e "sleep.$nap2." /proc/[0-9]*/cmdline | sed 's|/proc/\([0-9]*\)/.*|\1|'
}

# Checks that no such process runs, ending any that does ($1 names the moment). A sandbox's
# processes die with its PID namespace, which the kernel tears down a few milliseconds after
# the grader has ended its first process: 2 s are given.
check_no_leftovers() {
    for _ in 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20; do
        [ -z "$(leftovers)" ] && break
        sleep 0.1
    done
    pids=$(leftovers)
    check "$1: processes left running: $pids" test -z "$pids"
    for pid in $pids; do kill -9 "$pid" 2>/dev/null; done
}

# The class. Images: right, a little wrong, as PFMs, one missing, one of the wrong size,
# one that is no image; and a name that HTML and CSV must escape.
copy_references correct
copy_references slightly-wrong
sed 's/^s 25 -5 -90   10$/s 25.5 -5 -90   10/' "$top/scenes/spheres-three.scn" >moved.scn
render moved.scn class/slightly-wrong/spheres-three.png
mkdir -p class/pfm
for s in $scenes; do render "$top/scenes/$s.scn" "class/pfm/$s.pfm"; done
copy_references missing-one
rm class/missing-one/demo.png
copy_references wrong-size
render "$top/scenes/spheres-three.scn" class/wrong-size/spheres-three.png --scale 0.5
copy_references unreadable
echo "not an image" >class/unreadable/spheres-three.png
strange="o'brien, \"jo\" <b>&amp;"
copy_references "$strange"
# Names a spreadsheet would run as formulas.
copy_references '=HYPERLINK("x","y")'
copy_references '@SUM(1+1)'
# Links are not images handed in: to a reference, to a classmate's; nor is a FIFO; and a
# PNG whose header says 8192 x 8192 (of 16 bits) is told apart without being decoded.
copy_references links
ln -sf "$refs/spheres-three.png" class/links/spheres-three.png
ln -sf ../correct/demo.png class/links/demo.png
ln -s correct class/copycat
copy_references fifo
rm class/fifo/demo.png
mkfifo class/fifo/demo.png
copy_references bomb
{
    printf '\211PNG\r\n\032\n\000\000\000\015IHDR\000\000\040\000\000\000\040\000'
    printf '\020\002\000\000\000\000\000\000\000'
} >class/bomb/spheres-three.png

# Programs: correct (our raytra behind a script), one that hangs on the demo scene (and
# forks, and leaves a daemon after another scene), one that crashes, one that asks for
# more memory than the limit, one that writes nothing, and one that does not build.
script_submission correct-program <<EOF
#!/bin/sh
exec $model "\$@"
EOF
script_submission hanging <<EOF
#!/bin/sh
case \$1 in
*demo*) echo "hanging on purpose"; sleep $nap1 & exec sleep $nap1 ;;
*spheres-three*) setsid sleep $nap2 >/dev/null 2>&1 & ;;
esac
exec $model "\$@"
EOF
script_submission fifo-program <<EOF
#!/bin/sh
case \$1 in *demo*) exec mkfifo "\$2" ;; esac
exec $model "\$@"
EOF
script_submission link-program <<EOF
#!/bin/sh
case \$1 in *demo*) exec ln -s "$refs/demo.png" "\$2" ;; esac
exec $model "\$@"
EOF
script_submission planter <<EOF
#!/bin/sh
case \$1 in *spheres-three*) ln -s "$tmp/precious.txt" "\$(dirname "\$2")/../spheres-behind-camera.log" ;; esac
exec $model "\$@"
EOF
echo "precious" >precious.txt
c_submission crashing <<'EOF'
#include <signal.h>
#include <stdio.h>
int main(void)
{
    fprintf(stderr, "about to crash\n");
    raise(SIGSEGV);
    return 0;
}
EOF
# One that prints 3 MB before it renders, and prints for ever on the demo scene; one that
# copies the reference image rather than render it.
script_submission chatty <<EOF
#!/bin/sh
case \$1 in *demo*) exec yes "chatty for ever" ;; esac
echo "FIRST LINE"
yes "chatty" | head -c 3000000
printf '\nLAST LINE\n'
exec $model "\$@"
EOF
# The copier copies the references it carries, as a starter carries them, beside its
# program; correct-program carries them too, and writes the same bytes by rendering.
script_submission copier <<EOF
#!/bin/sh
exec cp "\$(dirname "\$0")/milestones/1.1-spheres-red/references/\$(basename "\$2")" "\$2"
EOF
for who in copier correct-program; do
    mkdir -p "class/$who/milestones/1.1-spheres-red" &&
        cp -R "$refs" "class/$who/milestones/1.1-spheres-red/" || exit 2
done
c_submission greedy <<'EOF'
#include <stdio.h>
#include <stdlib.h>
/* 3 GiB: more than the grader's default limit of 2 GiB, but no more than the system gives. */
int main(void)
{
    if (malloc((size_t)3 << 30) == NULL) {
        fprintf(stderr, "raytra: out of memory\n");
        return 1;
    }
    return 0;
}
EOF
c_submission quitter <<'EOF'
#include <string.h>
int main(int argc, char **argv) { return argc > 1 && strstr(argv[1], "demo") != NULL ? 3 : 0; }
EOF
c_submission build-fails <<'EOF'
int main(void) { return undefined_name; }
EOF
echo "not a submission" >class/notes.txt
mkdir class/.hidden

# One run grades them all.
checks=$((checks + 1))
"$grade" --time-limit 1 --out "out dir" 1.1 class >stdout.txt 2>stderr.txt
status=$?
[ "$status" -eq 0 ] || { fail "grade exited with $status"; sed 's/^/    | /' stderr.txt; }

# The verdicts, exactly; the strange name is quoted, so checked apart.
{
    echo "submission,scene,verdict"
    for s in $scenes; do
        case $s in spheres-three) echo "bomb,$s,WRONG SIZE" ;; *) echo "bomb,$s,PASS" ;; esac
    done
    for s in $scenes; do echo "build-fails,$s,BUILD FAILED"; done
    for s in $scenes; do
        case $s in demo) echo "chatty,$s,TIMEOUT" ;; *) echo "chatty,$s,PASS" ;; esac
    done
    for s in $scenes; do echo "copier,$s,PASS"; done
    for s in $scenes; do echo "copycat,$s,LINK"; done
    for s in $scenes; do echo "correct,$s,PASS"; done
    for s in $scenes; do echo "correct-program,$s,PASS"; done
    for s in $scenes; do echo "crashing,$s,CRASHED"; done
    for s in $scenes; do
        case $s in demo) echo "fifo,$s,UNREADABLE" ;; *) echo "fifo,$s,PASS" ;; esac
    done
    for s in $scenes; do
        case $s in demo) echo "fifo-program,$s,UNREADABLE" ;; *) echo "fifo-program,$s,PASS" ;; esac
    done
    for s in $scenes; do echo "greedy,$s,OUT OF MEMORY"; done
    for s in $scenes; do
        case $s in demo) echo "hanging,$s,TIMEOUT" ;; *) echo "hanging,$s,PASS" ;; esac
    done
    for s in $scenes; do
        case $s in demo) echo "link-program,$s,LINK" ;; *) echo "link-program,$s,PASS" ;; esac
    done
    for s in $scenes; do
        case $s in demo | spheres-three) echo "links,$s,LINK" ;; *) echo "links,$s,PASS" ;; esac
    done
    for s in $scenes; do
        case $s in demo) echo "missing-one,$s,MISSING" ;; *) echo "missing-one,$s,PASS" ;; esac
    done
    for s in $scenes; do echo "pfm,$s,PASS"; done
    for s in $scenes; do echo "planter,$s,PASS"; done
    for s in $scenes; do
        case $s in demo) echo "quitter,$s,ERROR" ;; *) echo "quitter,$s,MISSING" ;; esac
    done
    for s in $scenes; do
        case $s in spheres-three) echo "slightly-wrong,$s,FAIL" ;; *) echo "slightly-wrong,$s,PASS" ;; esac
    done
    for s in $scenes; do
        case $s in spheres-three) echo "unreadable,$s,UNREADABLE" ;; *) echo "unreadable,$s,PASS" ;; esac
    done
    for s in $scenes; do
        case $s in spheres-three) echo "wrong-size,$s,WRONG SIZE" ;; *) echo "wrong-size,$s,PASS" ;; esac
    done
} >expected.txt
csv="out dir/grades.csv"
grep -v '^"' "$csv" | cut -d, -f1-3 >verdicts.txt
check "the verdicts differ from those expected" cmp -s expected.txt verdicts.txt ||
    diff expected.txt verdicts.txt | sed 's/^/    | /'
check "the CSV's header" grep -qx 'submission,scene,verdict,max_diff_r,max_diff_g,max_diff_b,mean_abs_diff,rmse,psnr_db,differing_pixels,differing_fraction,bbox,message,seconds,flag,points' "$csv"
check "the strange name's rows, quoted" \
    test "$(grep -c "^\"o'brien, \"\"jo\"\" <b>&amp;\",[a-z-]*,PASS," "$csv")" -eq "$scene_count"

check "a formula's name neutralised" \
    test "$(grep -c '^"'"'"'=HYPERLINK(""x"",""y"")",[a-z-]*,PASS,' "$csv")" -eq "$scene_count"
check "a name starting with @ neutralised" \
    test "$(grep -c '^"'"'"'@SUM(1+1)",[a-z-]*,PASS,' "$csv")" -eq "$scene_count"
check "a field starting with = or @ unquoted" test -z "$(grep -E '(^|,)[=@+]' "$csv")"

# The reasons and the figures.
has 'links,spheres-three,LINK,,,,,,,,,,'"spheres-three.png is a symbolic link to $refs/spheres-three.png: not an image handed in,"
has 'links,demo,LINK,,,,,,,,,,demo.png is a symbolic link to ../correct/demo.png: not an image handed in,'
has 'link-program,demo,LINK,,,,,,,,,,'"demo.png is a symbolic link to $refs/demo.png: not an image handed in,"
has "copycat,demo,LINK,,,,,,,,,,the submission's folder is a symbolic link to correct,"
has 'fifo,demo,UNREADABLE,,,,,,,,,,demo.png is not a regular file (a FIFO),'
has 'fifo-program,demo,UNREADABLE,,,,,,,,,,demo.png is not a regular file (a FIFO),'
has 'bomb,spheres-three,WRONG SIZE,,,,,,,,,,"the image is 8192 x 8192 pixels, the reference 320 x 240",'
has 'wrong-size,spheres-three,WRONG SIZE,,,,,,,,,,"the image is 160 x 120 pixels, the reference 320 x 240",'
has 'unreadable,spheres-three,UNREADABLE,,,,,,,,,,"the file cannot be read as an image: not a PNG, PFM or OpenEXR image",'
has 'hanging,demo,TIMEOUT,,,,,,,,,,did not finish within 1 s,'
has 'crashing,demo,CRASHED,,,,,,,,,,killed by signal 11 (Segmentation fault),'
has 'greedy,demo,OUT OF MEMORY,,,,,,,,,,ran out of memory (exit status 1; memory limit 2 GiB),'
has 'quitter,demo,ERROR,,,,,,,,,,ended with exit status 3 and wrote no image,'
has 'quitter,spheres-three,MISSING,,,,,,,,,,ended normally but wrote no spheres-three.png,'
has 'missing-one,demo,MISSING,,,,,,,,,,"no demo.png, .pfm or .exr in the submission",'
has 'build-fails,demo,BUILD FAILED,,,,,,,,,,make failed (exit status 2),'
# The moved sphere's figures, in their form: their last digits may change with the compiler.
number='[0-9.e-]+'
check "the figures of a failed image" grep -qE "^slightly-wrong,spheres-three,FAIL,1,0,0,$number,$number,$number,[0-9]+,$number,\"\\([0-9]+,[0-9]+\\)-\\([0-9]+,[0-9]+\\)\",\"$number% of the pixels differ by more than 2/255, more than the 0.1% allowed\",,,0\$" "$csv"
has 'correct,demo,PASS,0,0,0,0,0,inf,0,0,,identical to the reference,'
# A byte-for-byte copy of a reference file is flagged, handed in or written; an image equal
# in its pixels but written otherwise (a PFM) is not.
has 'correct,demo,PASS,0,0,0,0,0,inf,0,0,,identical to the reference,,copy,1'
# The copier copies the canaries the grader put in the place of the references it carries:
# one channel of a pixel in 32 a code off, within the tolerance, and flagged.
check "a program's copy of a reference flagged" \
    test "$(grep -c '^copier,[a-z-]*,PASS,.*,no pixel differs by more than 2/255,[0-9.]*,copy,1$' "$csv")" -eq "$scene_count"
check "an equal image written otherwise flagged" test -z "$(grep '^pfm,.*,copy,[0-9.]*$' "$csv")"
check "a program that renders the references' bytes flagged" \
    test -z "$(grep '^correct-program,.*,copy,[0-9.]*$' "$csv")"
check "a FAIL flagged" test -z "$(grep ',FAIL,.*,copy,[0-9.]*$' "$csv")"
check "the copies flagged in the report" grep -q 'class="badge flag"[^>]*>COPY<' "out dir/report.html"

# The report: there, whole, self-contained, escaped.
html="out dir/report.html"
check "no report" test -s "$html"
check "the report is not whole" grep -q '</html>' "$html"
check "a link or source outside the page" \
    test -z "$(grep -o '\(src\|href\)="[^"]*' "$html" | grep -v '="\(data:image/png;base64,\|#\)')"
check "a url() outside the page" \
    test -z "$(grep -o 'url([^)]\{0,26\}' "$html" | grep -v '^url(data:image/png;base64,')"
check "a section a submission" test "$(grep -c '<section id="s[0-9]*">' "$html")" -eq 24
check "the strange name escaped" grep -qF "o&#39;brien, &quot;jo&quot; &lt;b&gt;&amp;amp;" "$html"
check "the strange name unescaped" test "$(grep -cF '<b>&amp;' "$html")" -eq 0
# An image of each scene from 19 submissions, less 10 of spheres-three and demo that are
# missing, unreadable, links or of the wrong size.
check "a picture of each image" \
    test "$(grep -o '\(alt\|aria-label\)="submitted image"' "$html" | wc -l)" -eq $((19 * scene_count - 10))
check "the crash's output" grep -q 'Segmentation fault' "$html"

# A crash and a timeout: the command line that was run, in its folder, shell-quoted, and
# the last lines of the output, in the report and at the top of the scene's log; the
# command, run again from the log, crashes again.
work="$tmp/out dir/work"
for case in crashing:CRASHED:'about to crash' hanging:TIMEOUT:'hanging on purpose'; do
    who=${case%%:*} said=${case##*:} verdict=${case#*:}
    verdict=${verdict%%:*}
    dir=$(ls -d "$work"/*-"$who")
    command="../build/raytra $top/scenes/demo.scn ../images/demo.png"
    expected="cd '$dir/run' && $command"
    check "$who: the command line at the top of its log" test "$(head -n 1 "$dir/demo.log")" = "\$ $expected"
    check "$who: its output in its log" grep -qx "$said" "$dir/demo.log"
    # The submission's section, then its scene demo.
    awk -v who="$who" 'index($0, "<h2><span class=\"name\">" who "</span>") { p = 1 }
                       p && index($0, "scene-name\">demo<") { q = 1 }
                       q { print } q && /<\/details>/ { exit }' "$html" >scene.html
    check "$who: $verdict in the report" grep -q ">$verdict<" scene.html
    check "$who: the command line in the report" grep -qF \
        "Command <code>cd work/${dir##*/}/run &amp;&amp; $command</code>" scene.html
    check "$who: its last lines in the report" grep -qF "$said" scene.html
done
crash=$(ls -d "$work"/*-crashing)
(sh -c "$(head -n 1 "$crash/demo.log" | cut -c 3-)") >/dev/null 2>&1
check "the crash's command line crashes again" test $? -eq 139

# A program that prints without end: its log keeps the first and the last 64 KiB, with a
# line saying how much was cut, however much it printed.
chatty=$(ls -d "$work"/*-chatty)
check "a long output kept bounded" test "$(wc -c <"$chatty/spheres-three.log")" -lt 140000
check "a long output's head kept" grep -qx 'FIRST LINE' "$chatty/spheres-three.log"
check "a long output's tail kept" grep -qx 'LAST LINE' "$chatty/spheres-three.log"
check "a long output's cut said" grep -q '^\[grade: [0-9]* bytes cut here: of the 3000[0-9]* bytes printed' "$chatty/spheres-three.log"
check "an endless output kept bounded" test "$(wc -c <"$chatty/demo.log")" -lt 140000
check "the logs' total" test "$(du -sk "$chatty" | cut -f1)" -lt 2000
check "a temporary left in the output folder" \
    test -z "$(find "out dir" -mindepth 1 -maxdepth 1 ! -name report.html ! -name grades.csv ! -name gradebook.csv ! -name results.txt ! -name work ! -name .grade-lock)"

# The grader leaves no process behind and does not touch the students' folders.
check_no_leftovers "after grading"
check "a link a program planted at a log's path was followed" test "$(cat precious.txt)" = precious
planter=$(ls -d "$work"/*-planter)
check "a link planted at a log's path replaced by the log" \
    test -f "$planter/spheres-behind-camera.log" -a ! -L "$planter/spheres-behind-camera.log"
check "a student's folder was built in" test ! -e class/crashing/raytra
# A line a submission, ending with how far the class is: k of N done, the time elapsed, an
# ETA (but after the last); the times are the clock's, checked for their form alone.
span='[0-9]+ (s|min [0-9]+ s|h [0-9]+ min)'
check "progress lines" grep -Eq "^grading hanging \(program\): building\.\.\. $scene_count scenes: $((scene_count - 1)) pass, 1 timeout \[[0-9]+ of 24 done, $span elapsed, ETA $span\]\$" stderr.txt
check "progress lines: k of N counted from 1 to N" \
    test "$(sed -En 's/^grading .* \[([0-9]+) of 24 done, .*/\1/p' stderr.txt | tr '\n' ' ')" = "$(seq 24 | tr '\n' ' ')"
check "progress lines: the last has no ETA" \
    grep -Eq "^grading .* \[24 of 24 done, $span elapsed\]\$" stderr.txt
check "no progress line for a file or a hidden folder" test "$(grep -c '^grading ' stderr.txt)" -eq 24

# Tolerances from the command line reach imgdiff; a second run replaces the first.
mkdir small
mv class/slightly-wrong small/
checks=$((checks + 1))
"$grade" -q --allow 0.01 --out "out dir" 1.1-spheres-red small >stdout.txt 2>stderr.txt ||
    fail "grade --allow failed"
check "--allow 0.01 passes the moved sphere" grep -q '^slightly-wrong,spheres-three,PASS,' "$csv"
check "-q prints nothing" test ! -s stderr.txt
check "the old work folder stays" test ! -e "out dir/work/01-build-fails"

# Interrupted: no report, no process left.
mkdir slow
mv class/hanging slow/
"$grade" -q --time-limit 100 --out interrupted 1.1 slow >stdout.txt 2>stderr.txt &
pid=$!
tries=0
while [ -z "$(leftovers)" ] && [ $tries -lt 100 ]; do
    sleep 0.1
    tries=$((tries + 1))
done
# While it runs, a second run on the same output folder refuses, and leaves it alone.
checks=$((checks + 1))
"$grade" -q --out interrupted 1.1 small >stdout.txt 2>second.txt
second=$?
[ "$second" -eq 2 ] || fail "a second run on a locked --out: exit status $second, expected 2"
check "a second run on a locked --out says why" \
    grep -qF "grade: interrupted is in use: another grade is writing into it" second.txt
check "a second run left the first one's work" test -d interrupted/work/01-hanging/run
kill -INT $pid
wait $pid
status=$?
check "interrupted: exit status $status, expected 130" test "$status" -eq 130
check "interrupted: a report" test ! -e interrupted/report.html
check_no_leftovers "interrupted"

# A program that makes a classmate's work folder before grade does, or plants a link there:
# in namespaces it cannot; in the fallback, the classmate is graded all the same, in a
# folder made fresh, the planted one moved aside.
mkdir -p trespass elsewhere
script_submission a-trespasser <<EOF
#!/bin/sh
[ -e ../../02-b-victim ] || { mkdir -p ../../02-b-victim/run && ln -s "$tmp/elsewhere" ../../02-b-victim/images; }
[ -L ../../03-c-victim ] || ln -s "$tmp/elsewhere" ../../03-c-victim
exec $model "\$@"
EOF
script_submission b-victim <<EOF
#!/bin/sh
exec $model "\$@"
EOF
cp -R class/b-victim class/c-victim
mv class/a-trespasser class/b-victim class/c-victim trespass/
# In namespaces, the trespasser reaches nothing outside its sandbox: nothing to move aside.
checks=$((checks + 1))
"$grade" --sandbox namespaces --out trespassed 1.1 trespass >stdout.txt 2>stderr.txt ||
    fail "grade of a trespassed class failed (namespaces)"
check "namespaces: the trespasser's classmates graded" \
    test "$(grep -c '^[bc]-victim,[a-z-]*,PASS,' trespassed/grades.csv)" -eq $((2 * scene_count))
check "namespaces: the trespasser reached no classmate's work folder" \
    test -z "$(ls -A trespassed/work | grep moved)$(ls elsewhere)"
# The fallback's walls: a folder or a link made before the grader's is moved aside.
checks=$((checks + 1))
"$grade" --sandbox fallback --out trespassed 1.1 trespass >stdout.txt 2>stderr.txt ||
    fail "grade of a trespassed class failed (fallback)"
check "a classmate whose work folder was made before graded" \
    test "$(grep -c '^[bc]-victim,[a-z-]*,PASS,' trespassed/grades.csv)" -eq $((2 * scene_count))
check "a work folder made before moved aside, said" \
    grep -q "^grade: note: .*/work/02-b-victim was there before grade made it" stderr.txt
check "a link planted at a work folder moved aside, not followed" \
    test -L trespassed/work/.moved-1-03-c-victim -a -z "$(ls elsewhere)"

# The output folder: not the submissions folder, nor inside a submission, which is copied
# to be built (with --self, the folder graded); an output folder of grade's in a class
# folder, this run's or another's, is not a submission.
refuse_out() {
    checks=$((checks + 1))
    "$grade" "$@" >stdout.txt 2>stderr.txt
    status=$?
    [ "$status" -eq 2 ] || fail "grade $*: exit status $status, expected 2"
}
refuse_out -q --out small 1.1 small
check "--out the submissions folder refused" grep -qF \
    "grade: the output folder small is the submissions folder: its work folder would be graded" stderr.txt
refuse_out -q --out small/slightly-wrong/o 1.1 small
check "--out inside a submission refused" grep -qF \
    "grade: the output folder small/slightly-wrong/o is inside the submission slightly-wrong" stderr.txt
check "a refused --out not made" test ! -e small/slightly-wrong/o
(cd trespass/b-victim && "$grade" --self -q 1.1 . >../../stdout.txt 2>../../stderr.txt)
check "--self: the default --out inside the folder refused" grep -qF \
    "grade: the output folder grading-1.1-spheres-red is inside the submission ." stderr.txt
"$grade" -q --out small/earlier 1.1 small >stdout.txt 2>stderr.txt
"$grade" --out small/later 1.1 small >stdout.txt 2>stderr.txt
check "an output folder in the class not graded" \
    test "$(cut -d, -f1 small/later/grades.csv | sort -u | tr '\n' ' ')" = "slightly-wrong submission "
check "another run's output folder named" \
    grep -qx "grade: note: small/earlier is an output folder of grade: not graded" stderr.txt
rm -rf small/earlier small/later

# A part given by its folder; students' programs get the positional words of renders.txt
# and the value of an option the course gives as a positional argument (1.4's MODE, for a
# part numbered 1.4), not raytra's own options, nor their values.
mkdir -p 1.4-test/references
cp "$refs/spheres-three.png" 1.4-test/references/
echo 'spheres-three.png scenes/spheres-three.scn --convention lecture 7 -j 2 --mode 1 --max-depth 3 --two-sided --scale=1 last' \
    >1.4-test/references/renders.txt
script_submission arguments <<EOF
#!/bin/sh
echo "\$#" "\$3" "\$4" "\$5" >arguments.txt
exec $model "\$1" "\$2"
EOF
mkdir words
mv class/arguments words/
checks=$((checks + 1))
"$grade" --out "out dir" ./1.4-test words >stdout.txt 2>stderr.txt || fail "grade ./1.4-test failed"
check "a part given by its folder" grep -q '^arguments,spheres-three,PASS,' "$csv"
check "the arguments a program gets" test "$(cat "out dir/work/01-arguments/run/arguments.txt")" = "5 7 1 last"
check "the note on raytra's options" grep -qF \
    "grade: note: spheres-three.png: raytra's option --convention lecture is not given to students' programs" stderr.txt
check "the note on an option with a value" grep -qF "raytra's option --max-depth 3 is not given" stderr.txt

# Part 1.6's P and S reach a program in the course's order, raytra SCENE OUTPUT P S,
# whatever order renders.txt names their options in.
mkdir -p 1.6-test/references
cp "$refs/spheres-three.png" 1.6-test/references/
echo 'spheres-three.png scenes/spheres-three.scn --light-samples 2 --seed 4 --samples 3' \
    >1.6-test/references/renders.txt
checks=$((checks + 1))
"$grade" --out "out dir" ./1.6-test words >stdout.txt 2>stderr.txt || fail "grade ./1.6-test failed"
check "P and S in the course's order" test "$(cat "out dir/work/01-arguments/run/arguments.txt")" = "4 3 2 "

# Part 1.6's shipped files handed in: a byte copy of raytra's image of each Monte Carlo
# render (a correct render, which passes) and of a statistical reference (whose mean has
# too little noise) are flagged copy; a hard link to a shipped image is a LINK.
mc=$top/milestones/1.6-monte-carlo/references
mkdir -p mc-copies/copier
for image in $(sed -n 's/^~\([^[:space:]]*\).*/\1/p' "$mc/renders.txt"); do
    cp "$mc/$image" mc-copies/copier/
done
rm mc-copies/copier/demo.png
cp "$mc/demo.stats.exr" mc-copies/copier/demo.exr
rm mc-copies/copier/soft-shadow-1-1.png
ln "$mc/soft-shadow-1-1.png" mc-copies/copier/soft-shadow-1-1.png 2>/dev/null ||
    cp "$mc/soft-shadow-1-1.png" mc-copies/copier/soft-shadow-1-1.png
checks=$((checks + 1))
"$grade" -q --out mc-out 1.6 mc-copies >stdout.txt 2>stderr.txt
[ $? -le 1 ] || fail "grade 1.6 on copies failed: $(cat stderr.txt)"
check "copies of part 1.6's shipped images pass, flagged" \
    test "$(grep -c '^copier,[a-z0-9-]*,PASS,.*,copy,[0-9.]*$' mc-out/grades.csv)" -eq \
        $(($(grep -c '^~' "$mc/renders.txt") - 2))
check "a copy of a statistical reference fails, flagged" \
    grep -q '^copier,demo,FAIL,.*smooth: too little noise.*,copy,[0-9.]*$' mc-out/grades.csv
check "a hard link to a shipped image" grep -q '^copier,soft-shadow-1-1,\(LINK\|PASS,.*,copy,[0-9.]*$\)' mc-out/grades.csv

# Each part's own raytra, handed in as a student's program, passes every graded scene of
# its part; the illustrations (!IMAGE in renders.txt) are not graded, and say so. A part
# whose raytra is not built (make -C grader test builds them all) is skipped, told.
for dir in "$top"/milestones/*/; do
    part=$(basename "$dir")
    [ -f "$dir/references/renders.txt" ] || continue
    if [ ! -x "$dir/raytra" ]; then
        echo "grade.sh: skipping part $part: $dir/raytra is not built"
        continue
    fi
    rm -rf own && mkdir own
    script_submission "$part" "$dir/raytra" <<EOF
#!/bin/sh
exec $model "\$@"
EOF
    mv "class/$part" own/
    graded=$(grep -c '^[^#![:space:]]' "$dir/references/renders.txt")
    illustrations=$(grep -c '^!' "$dir/references/renders.txt")
    checks=$((checks + 1))
    "$grade" --out "own-out" "$part" own >stdout.txt 2>stderr.txt || fail "grade $part own failed"
    check "$part's own raytra passes its $graded graded scenes" \
        test "$(grep -c "^$part,[a-z0-9-]*,PASS," own-out/grades.csv)" -eq "$graded"
    check "$part: only graded scenes in the CSV" test "$(($(wc -l <own-out/grades.csv) - 1))" -eq "$graded"
    [ "$illustrations" -eq 0 ] ||
        check "$part: the illustrations named" grep -q '^grade: not graded (illustrations): ' stderr.txt
    [ "$illustrations" -eq 0 ] ||
        check "$part: the illustrations in the report" grep -q 'Not graded (illustrations): ' own-out/report.html
done

# A student checks their own program: --self grades one folder, prints each verdict and
# the heat map of each scene that fails, and exits 1 unless every scene passes.
script_submission self-check <<EOF
#!/bin/sh
exec $model "\$@"
EOF
checks=$((checks + 1))
"$grade" --self -q --out self-out 1.1 class/self-check >stdout.txt 2>stderr.txt ||
    fail "grade --self of a correct program failed"
check "--self: a line a scene" test "$(grep -c '^PASS  *[a-z-]*: identical to the reference$' stdout.txt)" -eq "$scene_count"
check "--self: the summary" grep -q "^$scene_count of $scene_count scenes pass; the report: self-out/report.html\$" stdout.txt
script_submission self-wrong <<EOF
#!/bin/sh
case \$1 in *spheres-three*) exec $model $moved "\$2" ;; esac
exec $model "\$@"
EOF
checks=$((checks + 1))
"$grade" --self -q --out self-out 1.1 class/self-wrong >stdout.txt 2>stderr.txt
status=$?
[ "$status" -eq 1 ] || fail "grade --self of a failing program: exit status $status, expected 1"
check "--self: the failure and its heat map" grep -qx ' *heat map: .*/self-out/work/1-self/spheres-three.heat.png' stdout.txt
"$grade" --self -q --out self-out 1.1 class/crashing >stdout.txt 2>stderr.txt
self=$tmp/self-out/work/1-self
check "--self: a crash's command line" grep -qxF \
    "             command: cd $self/run && ../build/raytra $top/scenes/demo.scn ../images/demo.png" stdout.txt

# --self of a folder whose image is a link to a name with a terminal's escape sequences in
# it (setting the window's title, and CSI in C1): told with them written \xNN, none sent.
copy_references self-link
ln -sf "$(printf 'x\033]0;pwned\007\302\233y')" class/self-link/demo.png
"$grade" --self -q --out self-out 1.1 class/self-link >stdout.txt 2>stderr.txt
check "--self: a link's target told escaped" grep -qxF \
    'LINK         demo: demo.png is a symbolic link to x\x1b]0;pwned\x07\xc2\x9by: not an image handed in' \
    stdout.txt
# Tells whether the files hold none of the bytes ESC, BEL and 0x9B (CSI in C1).
no_controls() { ! LC_ALL=C grep -q "$(printf '[\033\007\233]')" "$@"; }
check "--self: no ESC, BEL nor CSI (C1) printed" no_controls stdout.txt stderr.txt

# --self of the folder the student is in: named by the folder's own name, not ".".
(cd class/self-check && "$grade" --self -q --out ../../dot-out --junit ../../dot.xml 1.1 . \
    >../../stdout.txt 2>../../stderr.txt)
check "--self .: the CSV names the folder '.'" grep -q '^self-check,demo,PASS,' dot-out/grades.csv
check "--self .: the JUnit file names the folder '.'" grep -q '<testsuite name="self-check"' dot.xml

# Build outputs from another machine, make's targets up to date: removed, and the program
# built from its sources; the report says what was removed.
script_submission stale <<EOF
#!/bin/sh
exec $model "\$@"
EOF
mkdir class-stale && mv class/stale class-stale/ &&
    mkdir -p class-stale/stale/build-sanitize/common class-stale/stale/common || exit 2
printf '#!/bin/sh\nexit 7\n' >class-stale/stale/raytra
chmod +x class-stale/stale/raytra
printf 'not an object of this machine\n' >class-stale/stale/common/image.o
cp class-stale/stale/common/image.o class-stale/stale/build-sanitize/common/
touch class-stale/stale/common/libraytra.a class-stale/stale/common/image.d
touch -d '2030-01-01' class-stale/stale/raytra
"$grade" -q --out stale-out 1.1 class-stale 2>stderr.txt
check "stale build outputs: not every scene passes" \
    test "$(grep -c '^stale,[a-z-]*,PASS,' stale-out/grades.csv)" -eq "$scene_count"
check "stale build outputs: the report does not say what was removed" grep -qF \
    "removed before make: <code>build-sanitize/
common/image.d
common/image.o
common/libraytra.a
raytra</code>" stale-out/report.html
check "stale build outputs: the submission itself changed" test -f class-stale/stale/common/image.o

# The instructor's controls: grading.conf's errors, each said with its file and line.
conf_refused() {
    printf '%s\n' "$1" >bad.conf
    checks=$((checks + 1))
    "$grade" -q --grading-conf bad.conf --out conf-out 1.1 small >stdout.txt 2>stderr.txt
    status=$?
    [ "$status" -eq 2 ] && grep -qF -- "grade: bad.conf:$2" stderr.txt ||
        { fail "grading.conf '$1': status $status, no 'bad.conf:$2'"; sed 's/^/    | /' stderr.txt; }
}
conf_refused "demo 2 after_deadline" "1: 'after_deadline' is not a visibility"
conf_refused "$(printf '# points\ndemo two')" "2: 'two' is not a number of points"
conf_refused "demo -1" "1: '-1' is not a number of points"
conf_refused "nowhere 1" "1: no scene 'nowhere' in renders.txt"
conf_refused "$(printf 'part 10\npart 20')" "2: expected 'part POINTS', once"
conf_refused "demo 1 visible extra" "1: expected 'SCENE POINTS [VISIBILITY]'"
conf_refused "hidden" "1: expected 'hidden FOLDER'"
conf_refused "$(printf 'part 5\n* 0')" "1: the part is worth 5 points but its scenes are worth none"
printf 'hidden no-such-folder\n' >bad.conf
"$grade" -q --grading-conf bad.conf --out conf-out 1.1 small >stdout.txt 2>stderr.txt
check "grading.conf's hidden folder not there: not refused" grep -q "no folder of hidden scenes" stderr.txt
mkdir -p own
printf 'demo.png own.scn\n' >own/renders.txt
cp "$top/scenes/demo.scn" own/own.scn
"$grade" -q --hidden own --out conf-out 1.1 small >stdout.txt 2>stderr.txt
check "a hidden scene named as a shipped one: not refused" \
    grep -q "own/renders.txt:1: a scene named demo is graded already" stderr.txt

# The command line, and troubles found before any grading.
refuse() {
    expected=$1
    shift
    checks=$((checks + 1))
    "$grade" "$@" >stdout.txt 2>stderr.txt
    status=$?
    [ "$status" -eq 2 ] || fail "grade $*: exit status $status, expected 2"
    grep -qF -- "$expected" stderr.txt || { fail "grade $*: no '$expected'"; sed 's/^/    | /' stderr.txt; }
}
"$grade" --help >stdout.txt 2>&1
check "grade --help" grep -q '^Usage: grade \[options\] PART SUBMISSIONS$' stdout.txt
refuse "usage: grade [options] PART SUBMISSIONS" 1.1
refuse "grade: no part '9.9' in" 9.9 small
refuse "grade: no folder nowhere" 1.1 nowhere
refuse "grade: --memory-limit takes a size such as 512M or 2G, or 0, got '2'" --memory-limit 2 1.1 small
refuse "grade: --memory-limit takes a size such as 512M or 2G, or 0, got 'K'" --memory-limit K 1.1 small
refuse "grade: --time-limit needs a value" 1.1 small --time-limit
refuse "grade: unknown option '--frobnicate'" --frobnicate 1.1 small
refuse "grade: imgdiff: --allow takes a fraction from 0 to 1, got '2'" --allow 2 --out o 1.1 small
mkdir -p foreign/work
refuse "foreign/work exists and was not made by grade: choose another --out" --out foreign 1.1 small
mkdir empty
refuse "grade: no submissions in empty" --out o 1.1 empty

if [ "$failures" -eq 0 ]; then
    echo "grade.sh: all $checks checks passed"
else
    echo "grade.sh: $failures of $checks checks failed"
    exit 1
fi
