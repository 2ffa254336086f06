#!/bin/sh
# gradebook.sh: tests gradebook.csv, the report's summary and late work on a made-up class of part 1.1.
#
# Usage: grader/tests/gradebook.sh GRADE   (make -C grader test runs it)
#   GRADE   the grader, grader/build/grade, with imgdiff beside it
#
# The class, made here in a temporary folder, with a grading.conf of known points (4 for
# each of five scenes, none for the others: 20 in all) and a late policy (due 2026-03-01T23:59:00-05:00, a grace of
# 15 min, 10% a day up to 30%, nothing after 5 days late): folders of the references,
# handed in on time, 2 days late, within the grace, 9 days late (their files' times set
# with touch -d); a git repository whose files are late but whose last commit, backdated
# with GIT_COMMITTER_DATE, is 1 day late; a program that crashes on every scene; one that
# does not build. Checks gradebook.csv byte for byte, the report's points, pass rates,
# late sentences and the crashes collapsed into one block; that --jobs 2 and two shards
# merged write the same gradebook; and that each bad line of grading.conf's late work stops
# the grader with FILE:LINE: what is wrong.
set -u
[ $# -eq 1 ] || { echo "usage: $0 GRADE" >&2; exit 2; }
case $1 in /*) grade=$1 ;; *) grade=$(pwd)/$1 ;; esac
top=$(cd "$(dirname "$0")/../.." && pwd)
refs=$top/milestones/1.1-spheres-red/references
tmp=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
cd "$tmp" || exit 2

. "$top/tests/checks.sh"

# Makes submission $1 a folder of the references, its files last changed at time $2.
images() {
    mkdir -p "class/$1" && cp "$refs"/*.png "class/$1/" && touch -d "$2" "class/$1"/* || exit 2
}
# Makes submission $1 a program whose make writes the shell script read from stdin as
# raytra, its files last changed at time $2.
program() {
    mkdir -p "class/$1" && cat >"class/$1/raytra.sh" &&
        printf 'raytra: raytra.sh\n\tcp raytra.sh raytra\n\tchmod +x raytra\n' >"class/$1/Makefile" &&
        touch -d "$2" "class/$1"/* || exit 2
}

images ada 2026-03-01T20:00:00-05:00
images bob 2026-03-03T10:00:00-05:00
rm class/bob/demo.png
images 'o,brien' 2026-03-02T00:09:00-05:00
images eve 2026-03-10T10:00:00-05:00
# A repository: its files say 19 days late, its last commit 12 h late.
images cy 2026-03-20T10:00:00-05:00
if command -v git >/dev/null 2>&1; then
    (cd class/cy && git init -q && git add . &&
        GIT_COMMITTER_DATE=2026-03-02T12:00:00-05:00 GIT_AUTHOR_DATE=2026-03-02T12:00:00-05:00 \
            git -c user.name=Cy -c user.email=cy@example.edu commit -q -m work) || exit 2
    touch -d 2026-03-20T10:00:00-05:00 class/cy/*.png
    cy_row='cy,,,cy,,20.00,20.00,100.00,2026-03-02T12:00:00-05:00,git,1,10.00,18.00,copy late'
else
    echo "gradebook.sh: no git here: the git submission is graded by its files' time"
    cy_row='cy,,,cy,,20.00,20.00,100.00,2026-03-20T10:00:00-05:00,files,19,30.00,0.00,copy late too-late'
fi
program dee 2026-03-01T12:00:00-05:00 <<'EOF'
#!/bin/sh
kill -SEGV $$
EOF
mkdir class/fay && printf 'raytra:\n\tfalse\n' >class/fay/Makefile &&
    touch -d 2026-03-01T12:00:00-05:00 class/fay/Makefile || exit 2

cat >grading.conf <<'EOF'
# what part 1.1's scenes are worth, and when they are due
*                      0
spheres-three          4
spheres-behind-camera  4
camera-straight-down   4
spheres-grid-wide      4
demo                   4
due              2026-03-01T23:59:00-05:00
grace            15m
penalty_per_day  10%
max_penalty      30%
max_late_days    5
EOF

checks=$((checks + 1))
if ! "$grade" --grading-conf grading.conf --time-limit 10 --out out 1.1 class >grade.log 2>&1; then
    failures=$((failures + 1))
    echo "FAIL: grade failed:"
    cat grade.log
fi
check "grade does not say it wrote gradebook.csv" \
    grep -q "^grade: wrote out/report.html, out/grades.csv and out/gradebook.csv$" grade.log

# The gradebook, byte for byte: a student a line, in the report's order.
cat >expected.csv <<EOF
Student,ID,SIS User ID,SIS Login ID,Section,points,maximum,percent,submitted,time_source,late_days,penalty_percent,final_points,flags
ada,,,ada,,20.00,20.00,100.00,2026-03-01T20:00:00-05:00,files,0,0.00,20.00,copy
bob,,,bob,,16.00,20.00,80.00,2026-03-03T10:00:00-05:00,files,2,20.00,12.80,copy late
$cy_row
dee,,,dee,,0.00,20.00,0.00,2026-03-01T12:00:00-05:00,files,0,0.00,0.00,
eve,,,eve,,20.00,20.00,100.00,2026-03-10T10:00:00-05:00,files,9,100.00,0.00,copy late too-late
fay,,,fay,,0.00,20.00,0.00,2026-03-01T12:00:00-05:00,files,0,0.00,0.00,build-failed
"o,brien",,,"o,brien",,20.00,20.00,100.00,2026-03-02T00:09:00-05:00,files,0,0.00,20.00,copy
EOF
check "gradebook.csv is not as expected: $(diff expected.csv out/gradebook.csv)" \
    cmp -s expected.csv out/gradebook.csv

# The report: points and percent, days late and final points, each scene's pass rate.
report=out/report.html
has() {
    checks=$((checks + 1))
    grep -qF -- "$1" "$report" || fail "no '$1' in the report"
}
has '<th class="n">Points</th><th class="n">%</th><th class="n">Days late</th><th class="n">Final</th>'
has '<td class="n">16.00</td><td class="n">80%</td>'
has '>2</td><td class="n">12.80</td>'
has '>9 (too late)</td><td class="n">0.00</td>'
has '<tr><td>demo</td><td>passed by 4 of 7</td><td class="n">57%</td></tr>'
has '<tr><td>spheres-three</td><td>passed by 5 of 7</td><td class="n">71%</td></tr>'
has 'Handed in 2026-03-03T10:00:00-05:00 (the time of its newest file), 2 days late (due 2026-03-01T23:59:00-05:00, a grace of 15 min): a penalty of 20% of its points: 16.00 of 20.00 points become 12.80.'
has 'Handed in 2026-03-02T00:09:00-05:00 (the time of its newest file), 10 min after the due date, 2026-03-01T23:59:00-05:00, within the grace of 15 min: on time.'
has 'Handed in 2026-03-10T10:00:00-05:00 (the time of its newest file), 9 days late (due 2026-03-01T23:59:00-05:00, a grace of 15 min): more than the 5 days late work is taken, the work gets 0 (20.00 of 20.00 points before).'
if command -v git >/dev/null 2>&1; then
    has 'Handed in 2026-03-02T12:00:00-05:00 (its last git commit), 1 day late'
fi
# The crashes: one open block for the seven scenes, each scene's own block closed.
has '<span class="badge error">CRASHED</span><span class="message">on 7 scenes: spheres-three, spheres-behind-camera, camera-straight-down, camera-straight-up, camera-inside-sphere, spheres-grid-wide, demo: killed by signal 11 (Segmentation fault)</span>'
dee=$(sed -n '/<section id="s4">/,/<\/section>/p' "$report")
check "dee's section has more than the one open block" \
    test "$(printf '%s\n' "$dee" | grep -c '<details class="scene" open>')" = 1
check "dee's scenes have no block of their own" \
    test "$(printf '%s\n' "$dee" | grep -c '<details class="scene">')" = 7

# The same gradebook from two jobs, and from two shards merged.
checks=$((checks + 1))
if "$grade" -q -j 2 --grading-conf grading.conf --time-limit 10 --out jobs 1.1 class >jobs.log 2>&1; then
    check "--jobs 2 writes another gradebook: $(diff expected.csv jobs/gradebook.csv)" \
        cmp -s expected.csv jobs/gradebook.csv
else
    fail "grade -j 2 failed: $(cat jobs.log)"
fi
checks=$((checks + 1))
if "$grade" -q --shard 1/2 --grading-conf grading.conf --time-limit 10 --out shard1 1.1 class \
    >shards.log 2>&1 &&
    "$grade" -q --shard 2/2 --grading-conf grading.conf --time-limit 10 --out shard2 1.1 class \
        >>shards.log 2>&1 &&
    "$grade" merge -q --out merged shard1 shard2 >>shards.log 2>&1; then
    check "two shards merged write another gradebook: $(diff expected.csv merged/gradebook.csv)" \
        cmp -s expected.csv merged/gradebook.csv
else
    fail "grading in shards failed: $(cat shards.log)"
fi

# Without a due date nothing is late, and no time is looked for (here 4 points a scene).
printf '* 4\ndemo 4\n' >no-due.conf
"$grade" -q --grading-conf no-due.conf --time-limit 10 --out no-due 1.1 class >/dev/null 2>&1
check "without a due date, a row counts lateness: $(sed -n 3p no-due/gradebook.csv)" \
    test "$(sed -n 3p no-due/gradebook.csv)" = 'bob,,,bob,,24.00,28.00,85.71,,,0,0.00,24.00,copy'
check "without a due date, the summary has columns of lateness" \
    sh -c '! grep -q "Days late" no-due/report.html'

# Each bad line of late work stops the grader before any grading, with its file and line.
bad() {
    printf '* 1\n%s\n' "$1" >bad.conf
    checks=$((checks + 1))
    "$grade" -q --grading-conf bad.conf --out bad 1.1 class >bad.log 2>&1
    status=$?
    if [ $status -ne 2 ] || ! grep -qxF "grade: bad.conf:2: $2" bad.log; then
        fail "'$1': exit status $status, not 2 with 'bad.conf:2: $2': $(cat bad.log)"
    fi
}
time_words="a time in ISO 8601 with its time zone (2026-03-01T23:59:00-05:00, or Z for UTC)"
bad 'due 2026-03-01T23:59:00' "'2026-03-01T23:59:00' is not $time_words"
bad 'due 2026-02-29T12:00:00Z' "'2026-02-29T12:00:00Z' is not $time_words"
bad 'due tomorrow' "'tomorrow' is not $time_words"
bad 'due' "expected 'due TIME', once"
bad 'grace 15' "'15' is not a duration: 0, or a number followed by s, m, h or d (15m, 2h, 1d)"
bad 'penalty_per_day 120%' "'120%' is not a percentage of the points, from 0 to 100 (10%)"
bad 'max_penalty 10% a day' "expected 'max_penalty PERCENT', once"
bad 'max_late_days 1.5' "'1.5' is not a whole number of days, from 0 to 3650"
printf '* 1\ndue 2026-03-01T23:59:00Z\nlate_until 2026-02-01T00:00:00Z\n' >bad.conf
"$grade" -q --grading-conf bad.conf --out bad 1.1 class >bad.log 2>&1
check "late_until before the due date: $(cat bad.log)" grep -qxF "grade: bad.conf:3: the end of \
late work (late_until, 2026-02-01T00:00:00Z) is before the due date (2026-03-01T23:59:00Z)" bad.log
printf '* 1\ngrace 1h\ngrace 2h\n' >bad.conf
"$grade" -q --grading-conf bad.conf --out bad 1.1 class >bad.log 2>&1
check "grace twice: $(cat bad.log)" grep -qxF "grade: bad.conf:3: expected 'grace DURATION', once" \
    bad.log
"$grade" -q --submitted-at 2026-03-01T10:00:00Z --out bad 1.1 class >bad.log 2>&1
check "--submitted-at without --self: $(cat bad.log)" grep -q "^grade: --submitted-at goes with --self" \
    bad.log

if [ $failures -eq 0 ]; then
    echo "gradebook.sh: all $checks checks passed"
else
    echo "gradebook.sh: $failures of $checks checks failed (KEEP=1 keeps $tmp)"
    exit 1
fi
