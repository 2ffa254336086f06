#!/bin/sh
# grade.sh: tests tools/grade on a made-up class for part 1.1, one submission for each verdict.
#
# Usage: tests/grade.sh GRADE RAYTRA   (make -C tools test runs it)
#   GRADE   the grader, tools/build/grade, with imgdiff beside it
#   RAYTRA  part 1.1's program: it renders the class's images and plays a correct student
#
# Every fixture is made here, in a temporary folder: images rendered by RAYTRA or copied
# from the references, and tiny Makefiles, shell scripts and C programs. Exit status 0
# when every check passes.
set -u
[ $# -eq 2 ] || { echo "usage: $0 GRADE RAYTRA" >&2; exit 2; }
case $1 in /*) grade=$1 ;; *) grade=$(pwd)/$1 ;; esac
case $2 in /*) raytra=$2 ;; *) raytra=$(pwd)/$2 ;; esac
top=$(cd "$(dirname "$0")/.." && pwd)
refs=$top/milestones/1.1-spheres-red/references
scenes="spheres-three spheres-behind-camera camera-straight-down spheres-grid-wide demo"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
cd "$tmp" || exit 2

checks=0
failures=0

# Reports a failed check.
fail() {
    failures=$((failures + 1))
    echo "FAIL: $1"
}

# Counts a check, failing it with message $1 unless the rest of the line succeeds.
check() {
    message=$1
    shift
    checks=$((checks + 1))
    "$@" || fail "$message"
}

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
script_submission() {
    mkdir -p "class/$1"
    cat >"class/$1/raytra.sh"
    printf 'raytra: raytra.sh\n\tcp raytra.sh raytra\n\tchmod +x raytra\n' >"class/$1/Makefile"
}

# Makes submission $1 a program: make compiles the C program read from stdin to raytra.
c_submission() {
    mkdir -p "class/$1"
    cat >"class/$1/main.c"
    printf 'raytra: main.c\n\tcc -o raytra main.c\n' >"class/$1/Makefile"
}

# Prints the pids of the processes the class's programs must not leave running: their
# command lines are "sleep", NUL, "3141" or "2718", NUL.
leftovers() {
    grep -lasx -e 'sleep.3141.' -e 'sleep.2718.' /proc/[0-9]*/cmdline | sed 's|/proc/\([0-9]*\)/.*|\1|'
}

# Checks that no such process runs, ending any that does ($1 names the moment).
check_no_leftovers() {
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

# Programs: correct (our raytra behind a script), one that hangs on the demo scene (and
# forks, and leaves a daemon after another scene), one that crashes, one that asks for
# more memory than the limit, one that writes nothing, and one that does not build.
script_submission correct-program <<EOF
#!/bin/sh
exec "$raytra" "\$@"
EOF
script_submission hanging <<EOF
#!/bin/sh
case \$1 in
*demo*) sleep 3141 & exec sleep 3141 ;;
*spheres-three*) setsid sleep 2718 >/dev/null 2>&1 & ;;
esac
exec "$raytra" "\$@"
EOF
c_submission crashing <<'EOF'
#include <signal.h>
int main(void) { raise(SIGSEGV); return 0; }
EOF
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
    for s in $scenes; do echo "build-fails,$s,BUILD FAILED"; done
    for s in $scenes; do echo "correct,$s,PASS"; done
    for s in $scenes; do echo "correct-program,$s,PASS"; done
    for s in $scenes; do echo "crashing,$s,CRASHED"; done
    for s in $scenes; do echo "greedy,$s,OUT OF MEMORY"; done
    for s in $scenes; do
        case $s in demo) echo "hanging,$s,TIMEOUT" ;; *) echo "hanging,$s,PASS" ;; esac
    done
    for s in $scenes; do
        case $s in demo) echo "missing-one,$s,MISSING" ;; *) echo "missing-one,$s,PASS" ;; esac
    done
    for s in $scenes; do echo "pfm,$s,PASS"; done
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
check "the CSV's header" grep -qx 'submission,scene,verdict,max_diff_r,max_diff_g,max_diff_b,mean_abs_diff,rmse,psnr_db,differing_pixels,differing_fraction,bbox,message,seconds' "$csv"
check "the strange name's rows, quoted" \
    test "$(grep -c "^\"o'brien, \"\"jo\"\" <b>&amp;\",[a-z-]*,PASS," "$csv")" -eq 5

# The reasons and the figures.
has 'wrong-size,spheres-three,WRONG SIZE,,,,,,,,,,"the image is 160 x 120 pixels, the reference 320 x 240",'
has 'unreadable,spheres-three,UNREADABLE,,,,,,,,,,"the file cannot be read as an image: not a PNG, PFM or OpenEXR image",'
has 'hanging,demo,TIMEOUT,,,,,,,,,,did not finish within 1 s,'
has 'crashing,demo,CRASHED,,,,,,,,,,killed by signal 11 (Segmentation fault),'
has 'greedy,demo,OUT OF MEMORY,,,,,,,,,,ran out of memory (exit status 1; memory limit 2 GiB),'
has 'quitter,demo,ERROR,,,,,,,,,,ended with exit status 3 and wrote no image,'
has 'quitter,spheres-three,MISSING,,,,,,,,,,ended normally but wrote no spheres-three.png,'
has 'missing-one,demo,MISSING,,,,,,,,,,no demo.png (nor demo.pfm) in the submission,'
has 'build-fails,demo,BUILD FAILED,,,,,,,,,,make failed (exit status 2),'
# The moved sphere's figures, in their form: their last digits may change with the compiler.
number='[0-9.e-]+'
check "the figures of a failed image" grep -qE "^slightly-wrong,spheres-three,FAIL,1,0,0,$number,$number,$number,[0-9]+,$number,\"\\([0-9]+,[0-9]+\\)-\\([0-9]+,[0-9]+\\)\",\"$number% of the pixels differ by more than 2/255, more than the 0.1% allowed\",\$" "$csv"
has 'correct,demo,PASS,0,0,0,0,0,inf,0,0,,identical to the reference,'

# The report: there, whole, self-contained, escaped.
html="out dir/report.html"
check "no report" test -s "$html"
check "the report is not whole" grep -q '</html>' "$html"
check "a link or source outside the page" \
    test -z "$(grep -o '\(src\|href\)="[^"]*' "$html" | grep -v '="\(data:image/png;base64,\|#\)')"
check "a url() outside the page" \
    test -z "$(grep -o 'url([^)]\{0,26\}' "$html" | grep -v '^url(data:image/png;base64,')"
check "a section a submission" test "$(grep -c '<section id="s[0-9]*">' "$html")" -eq 13
check "the strange name escaped" grep -qF "o&#39;brien, &quot;jo&quot; &lt;b&gt;&amp;amp;" "$html"
check "the strange name unescaped" test "$(grep -cF '<b>&amp;' "$html")" -eq 0
check "a picture of each image" test "$(grep -o '\(alt\|aria-label\)="submitted image"' "$html" | wc -l)" -eq 42
check "the crash's output" grep -q 'Segmentation fault' "$html"
check "a temporary left in the output folder" \
    test -z "$(find "out dir" -mindepth 1 -maxdepth 1 ! -name report.html ! -name grades.csv ! -name work)"

# The grader leaves no process behind and does not touch the students' folders.
check_no_leftovers "after grading"
check "a student's folder was built in" test ! -e class/crashing/raytra
check "progress lines" grep -q '^grading hanging (program): building... 5 scenes: 4 pass, 1 timeout$' stderr.txt
check "no progress line for a file or a hidden folder" test "$(grep -c '^grading ' stderr.txt)" -eq 13

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
kill -INT $pid
wait $pid
status=$?
check "interrupted: exit status $status, expected 130" test "$status" -eq 130
check "interrupted: a report" test ! -e interrupted/report.html
check_no_leftovers "interrupted"

# A part given by its folder; students' programs get the positional words of renders.txt,
# not raytra's options.
mkdir -p part/references
cp "$refs/spheres-three.png" part/references/
echo 'spheres-three.png scenes/spheres-three.scn --convention lecture 7 -j 2 --scale=1 last' \
    >part/references/renders.txt
script_submission arguments <<EOF
#!/bin/sh
echo "\$#" "\$3" "\$4" >"$tmp/arguments.txt"
exec "$raytra" "\$1" "\$2"
EOF
mkdir words
mv class/arguments words/
checks=$((checks + 1))
"$grade" --out "out dir" ./part words >stdout.txt 2>stderr.txt || fail "grade ./part failed"
check "a part given by its folder" grep -q '^arguments,spheres-three,PASS,' "$csv"
check "the arguments a program gets" test "$(cat arguments.txt)" = "4 7 last"
check "the note on raytra's options" grep -qF \
    "grade: note: spheres-three.png: raytra's option --convention lecture is not given to students' programs" stderr.txt

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
