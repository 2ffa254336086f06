#!/bin/sh
# contain.sh: hostile submissions leave processes behind, forge results, plant links and FIFOs; none outlives its run.
#
# Usage: tests/contain.sh GRADE   (make check-contain; GRADE is tools/build/grade, with
#        imgdiff beside it)
#
# A class of part 1.1 whose raytra, on the scene spheres-three, leaves behind: a chain of
# 1,500 processes each the parent of the next, each in a session of its own and sharing
# its memory (CLONE_VM); a chain of 100 of plain fork; a setsid daemon; a double fork; a
# CLONE_VM child; a fork loop; a daemon that kills the grader's worker. Every process left
# behind copies the reference over the image, again and again, 0.5 s after it starts, and
# the chains' deepest also writes a results.json with 99 points wherever it may. Graded:
#   1. by tools/grade as a user who is not root (its subreaper's sweep), --jobs 1 and 2;
#   2. as root with --run-as, two students' uids and a grader's, --jobs 2;
#   3. by run_autograder as root, which also gets submissions that put a link to a file
#      only root may read, or a FIFO, where the grader's log would be, and one whose
#      grader is killed from outside after 2 s.
# After each: no process of the class runs (their executables are in this test's folder;
# their users' uids run nothing), no scene passes (a straggler's copy would), no 99 points,
# nothing of the root-only file in results.json, no hang. Parts 2 and 3 need root, and 1
# runs there as a spare uid, the fork loop capped by the limit grade sets (its user's
# processes and 256 more), then the 1,500-level chain alone as root, which no such limit
# holds; run as another user, 1 runs as that user without the fork loop or the chain as
# root, and 2 and 3 are skipped, which the test says. Each part's time is printed.
set -u
[ $# -eq 1 ] || { echo "usage: $0 GRADE" >&2; exit 2; }
command -v jq >/dev/null 2>&1 ||
    { echo "contain.sh: jq is missing (tools/deps.sh gradescope-test)" >&2; exit 2; }
case $1 in /*) grade=$1 ;; *) grade=$(pwd)/$1 ;; esac
top=$(cd "$(dirname "$0")/.." && pwd)
part=1.1-spheres-red
refs=$top/milestones/$part/references
tmp=$(mktemp -d) || exit 2
chmod 755 "$tmp" || exit 2
trap '[ -n "${KEEP:-}" ] || rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
. "$top/tests/checks.sh"
root=false
[ "$(id -u)" -eq 0 ] && root=true
# Uids of this run's own (no user has them), so that a test running beside it has others.
base=$((62000 + $$ % 1000 * 4))
sweeper=$base student1=$((base + 1)) student2=$((base + 2)) graderuid=$((base + 3))

# The hostile program: what it leaves behind is MODE, a word compiled in.
cat >"$tmp/hostile.c" <<'EOF'
#define _GNU_SOURCE
#include <fcntl.h>
#include <sched.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

static char out[4096], ref[4096];
static int depth, use_vm, ready[2];
static char stacks[1501][1 << 17];

/* Copies file `from` to `to`, through a temporary renamed over it. */
static void copy(const char *from, const char *to)
{
    char tmp[4200], buf[1 << 12];
    snprintf(tmp, sizeof tmp, "%s.%d", to, (int)getpid());
    int in = open(from, O_RDONLY), o = open(tmp, O_WRONLY | O_CREAT | O_TRUNC, 0666);
    for (ssize_t n; in >= 0 && o >= 0 && (n = read(in, buf, sizeof buf)) > 0;)
        if (write(o, buf, (size_t)n) != n)
            break;
    if (in >= 0)
        close(in);
    if (o >= 0)
        close(o);
    rename(tmp, to);
}

/* Left behind: 0.5 s on (the program has ended), for 60 s, forges the image and results. */
static int forge(void *unused)
{
    (void)unused;
    setsid();
    usleep(500000);
    int fd = open("forged.json", O_WRONLY | O_CREAT | O_TRUNC, 0666);
    if (fd >= 0 && write(fd, "{\"score\": 99, \"tests\": []}\n", 27) != 27)
        return 1;
    for (int k = 0; k < 1200; k++) {
        copy(ref, out);
        copy("forged.json", "../../../results.json");
        copy("forged.json", FORGE_AT);
        usleep(50000);
    }
    return 0;
}

static int level(void *arg);

/* Starts level k of the chain, a child of the caller; returns its pid, or -1. */
static pid_t start_level(long k)
{
    if (use_vm)
        return clone(level, stacks[k] + sizeof stacks[k], CLONE_VM | SIGCHLD, (void *)k);
    pid_t p = fork();
    if (p == 0)
        _exit(level((void *)k));
    return p;
}

/* A level of the chain, in a session of its own: starts the next and waits; the deepest
 * (or the last that could start) says so and forges. */
static int level(void *arg)
{
    long k = (long)arg;
    setsid();
    if (k < depth && start_level(k + 1) > 0)
        for (;;)
            pause();
    if (write(ready[1], k == depth ? "x" : "f", 1) != 1)
        return 1;
    close(ready[1]);
    return forge(NULL);
}

int main(int argc, char **argv)
{
    if (argc < 3)
        return 2;
    const char *base = strrchr(argv[2], '/') ? strrchr(argv[2], '/') + 1 : argv[2];
    snprintf(out, sizeof out, "%s", argv[2]);
    snprintf(ref, sizeof ref, "%s/%s", REF_DIR, base);
    if (strstr(argv[1], "spheres-three") == NULL)
        return 0;
    if (strcmp(MODE, "chain") == 0 || strcmp(MODE, "forkchain") == 0) {
        if (pipe(ready) != 0)
            return 1;
        depth = strcmp(MODE, "chain") == 0 ? 1500 : 100;
        use_vm = strcmp(MODE, "chain") == 0;
        if (start_level(1) < 0)
            return 1;
        close(ready[1]);
        char c = 0;
        if (read(ready[0], &c, 1) != 1 || c != 'x')
            printf("chain: a level could not start (a limit on processes)\n");
        else
            printf("chain: all %d levels are there\n", depth);
        return 0;
    }
    if (strcmp(MODE, "daemon") == 0 && fork() == 0) {
        setsid();
        if (fork() == 0)
            forge(NULL);
        _exit(0);
    }
    if (strcmp(MODE, "doublefork") == 0 && fork() == 0) {
        if (fork() == 0)
            forge(NULL);
        _exit(0);
    }
    if (strcmp(MODE, "clonevm") == 0)
        clone(forge, stacks[0] + sizeof stacks[0], CLONE_VM | SIGCHLD, NULL);
    if (strcmp(MODE, "forkloop") == 0 && fork() == 0)
        for (;;)
            if (fork() == 0)
                setsid();
    if (strcmp(MODE, "workerkiller") == 0) {
        if (fork() == 0)
            forge(NULL);
        usleep(100000);
        kill(getppid(), SIGKILL); /* the grader, or its worker */
    }
    usleep(300000);
    return 0;
}
EOF

# Makes submission $2 of class $1: the hostile program in MODE $3.
hostile() {
    mkdir -p "$tmp/$1/$2" || exit 2
    cp "$tmp/hostile.c" "$tmp/$1/$2/main.c"
    printf 'raytra: main.c\n\tcc -O1 -o raytra main.c -DMODE=%s -DREF_DIR=%s -DFORGE_AT=%s\n' \
        "'\"$3\"'" "'\"$refs\"'" "'\"$tmp/ag/results/results.json\"'" >"$tmp/$1/$2/Makefile"
}

# Prints the processes of the class still there: those whose executable is in this
# test's folder or whose real user is a student's uid of this test.
survivors() {
    for p in /proc/[0-9]*; do
        case $(readlink "$p/exe" 2>/dev/null) in "$tmp"/*) echo "${p#/proc/}"; continue ;; esac
        if $root && grep -qs -e "^Uid:[[:space:]]*${student1}[[:space:]]" \
            -e "^Uid:[[:space:]]*${student2}[[:space:]]" -e "^Uid:[[:space:]]*${sweeper}[[:space:]]" \
            "$p/status" 2>/dev/null && ! grep -qs '^State:[[:space:]]*Z' "$p/status"; then
            echo "${p#/proc/}"
        fi
    done
}

# Checks that nothing of the class runs after $1, ending what does so that the next part
# starts clean; and that no scene of the CSV $2 passed.
contained() {
    left=$(survivors | wc -l)
    check "$1: $left processes of the class outlived grade" test "$left" -eq 0
    for _ in 1 2 3 4 5; do
        pids=$(survivors)
        [ -z "$pids" ] && break
        # shellcheck disable=SC2086
        kill -9 $pids 2>/dev/null
        sleep 0.2
    done
    if [ -n "${2:-}" ]; then
        passed=$(grep -c ',PASS,' "$2")
        check "$1: $passed scenes passed: a process outlived its program and forged" \
            test "$passed" -eq 0
    fi
}

for m in chain forkchain daemon doublefork clonevm; do hostile class "$m" "$m"; done
$root && hostile class forkloop forkloop
mkdir "$tmp/killers" && hostile killers daemon daemon && hostile killers killer workerkiller &&
    hostile killers doublefork doublefork
chmod -R a+rX "$tmp" || exit 2

# 1. tools/grade as a user who is not root: the subreaper's sweep.
as_user=""
if $root; then
    mkdir "$tmp/out1" && chown "$sweeper:$sweeper" "$tmp/out1" || exit 2
    as_user="setpriv --reuid=$sweeper --regid=$sweeper --clear-groups --"
    echo "contain.sh: 1. grade as uid $sweeper, not root"
else
    mkdir "$tmp/out1" || exit 2
    echo "contain.sh: 1. grade as $(id -un) (not root: no fork loop, and parts 2 and 3 skipped)"
fi
start=$(date +%s)
# shellcheck disable=SC2086
$as_user "$grade" -q --time-limit 30 --out "$tmp/out1/one" 1.1 "$tmp/class" >"$tmp/one.log" 2>&1
check "1. grade exited with $? ($(tail -n 2 "$tmp/one.log"))" test $? -eq 0
contained "1. --jobs 1" "$tmp/out1/one/grades.csv"
check "1. the chain of 1,500 did not grow whole, nor stop at a limit" \
    grep -q 'chain: ' "$tmp/out1/one/work/01-chain/spheres-three.log"
echo "contain.sh: 1. $(sed -n 's/^chain: //p' "$tmp/out1/one/work/01-chain/spheres-three.log")"
# shellcheck disable=SC2086
$as_user "$grade" -q --jobs 2 --time-limit 30 --out "$tmp/out1/two" 1.1 "$tmp/killers" \
    >"$tmp/two.log" 2>&1
check "1. grade --jobs 2 exited with $? ($(tail -n 2 "$tmp/two.log"))" test $? -eq 0
contained "1. --jobs 2, a worker killed" "$tmp/out1/two/grades.csv"
check "1. the killed worker's scenes are not ERRORs" \
    test "$(grep -c '^killer,.*,ERROR,' "$tmp/out1/two/grades.csv")" -eq 5
if $root; then
    # As root, no limit holds the number of processes: the chain grows its 1,500 levels.
    mkdir "$tmp/deep" && cp -R "$tmp/class/chain" "$tmp/deep/" || exit 2
    "$grade" -q --time-limit 60 --out "$tmp/out1/deep" 1.1 "$tmp/deep" >"$tmp/deep.log" 2>&1
    check "1. grade as root exited with $? ($(tail -n 2 "$tmp/deep.log"))" test $? -eq 0
    contained "1. as root, a chain of 1,500" "$tmp/out1/deep/grades.csv"
    check "1. as root, the chain did not grow its 1,500 levels" \
        grep -q 'all 1500 levels' "$tmp/out1/deep/work/01-chain/spheres-three.log"
fi
echo "contain.sh: 1. took $(($(date +%s) - start)) s"

if ! $root; then
    echo "contain.sh: not root: --run-as and run_autograder not tested"
else
    # 2. As root, --run-as: students' uids, one a job, and a grader's; refused first with
    # no grader's user, a grader who is a student, fewer users than jobs, a user who runs
    # something already.
    start=$(date +%s)
    setpriv --reuid="$student2" --regid="$student2" --clear-groups sleep 30 &
    busy=$!
    sleep 0.2
    for bad in "--run-as $student1" "--run-as $student1 --grader-user $student1" \
        "--run-as $student1 --grader-user $graderuid --jobs 2" \
        "--run-as $student2 --grader-user $graderuid" "--run-as nosuchuser$$ --grader-user 1"; do
        # shellcheck disable=SC2086
        "$grade" $bad --out "$tmp/refused" 1.1 "$tmp/class" >"$tmp/refused.log" 2>&1
        check "2. grade $bad: exit status $?, not 2" test $? -eq 2
        check "2. grade $bad: graded ($(head -n 1 "$tmp/refused.log"))" test ! -e "$tmp/refused"
    done
    kill "$busy"
    wait "$busy" 2>/dev/null
    mkdir "$tmp/out2" && chown "$graderuid:$graderuid" "$tmp/out2" || exit 2
    mkdir "$tmp/both" && cp -R "$tmp/class/." "$tmp/killers/." "$tmp/both/" &&
        chmod -R a+rX "$tmp/both" || exit 2
    "$grade" -q --jobs 2 --run-as "$student1,$student2" --grader-user "$graderuid" \
        --time-limit 30 --out "$tmp/out2/g" 1.1 "$tmp/both" >"$tmp/run-as.log" 2>&1
    check "2. grade --run-as exited with $? ($(tail -n 2 "$tmp/run-as.log"))" test $? -eq 0
    contained "2. --run-as, --jobs 2" "$tmp/out2/g/grades.csv"
    check "2. a student's program could write in the grader's folder" \
        test ! -e "$tmp/out2/g/results.json"
    check "2. the report was not the grader's user's" \
        test "$(stat -c %u "$tmp/out2/g/report.html")" = "$graderuid"
    echo "contain.sh: 2. $(sed -n 's/^chain: //p' "$tmp/out2/g/work/01-chain/spheres-three.log")"
    echo "contain.sh: 2. took $(($(date +%s) - start)) s"

    # 3. run_autograder as root: its grader in a source folder of its own.
    start=$(date +%s)
    ag=$tmp/ag src=$tmp/ag/source
    mkdir -p "$src/tools/build" "$src/milestones/$part" "$ag/results" || exit 2
    cp "$grade" "$(dirname "$grade")/imgdiff" "$src/tools/build/" &&
        cp -R "$refs" "$src/milestones/$part/" && cp -R "$top/scenes" "$src/" &&
        cp "$top/tools/gradescope/setup.sh" "$top/tools/gradescope/run_autograder" "$src/" &&
        printf 'PART=%s\nBUDGET=240\nBUILD_TIME_LIMIT=60\n' "$part" >"$src/gradescope.conf" ||
        exit 2
    echo "SECRET-$$-root-only" >"$tmp/secret" && chmod 600 "$tmp/secret"
    mkdir "$tmp/planters"
    for how in link fifo; do
        mkdir -p "$tmp/planters/$how" || exit 2
        cat >"$tmp/planters/$how/raytra.sh" <<EOF
#!/bin/sh
# Where the grader's log was, and any other grade.log it can reach: a $how; then every
# process of this user is killed, the grader too were it the same.
for log in ../../../../grade.log ../../../grade.log /tmp/raytra-grade.*/grade.log; do
    rm -f "\$log" 2>/dev/null
    if [ $how = link ]; then ln -s "$tmp/secret" "\$log" 2>/dev/null; else mkfifo "\$log" 2>/dev/null; fi
done
kill -9 -1
EOF
        printf 'raytra: raytra.sh\n\tcp raytra.sh raytra\n\tchmod +x raytra\n' \
            >"$tmp/planters/$how/Makefile"
    done
    mkdir "$tmp/planters/sleeper"
    printf '#!/bin/sh\nsetsid sleep 300 &\nexec sleep 300\n' >"$tmp/planters/sleeper/raytra.sh"
    cp "$tmp/planters/link/Makefile" "$tmp/planters/sleeper/"
    chmod -R a+rX "$tmp/planters" "$ag"
    export AUTOGRADER_USER=$student1 AUTOGRADER_GRADER_USER=$graderuid
    # Runs the autograder on submission $1 (under 300 s, or it hung); $2: kill its grader then.
    autograde() {
        rm -rf "$ag/submission" "$ag/results/results.json"
        cp -R "$1" "$ag/submission" && chmod -R a+rX "$ag/submission"
        if [ -n "${2:-}" ]; then
            (sleep "$2" && for p in /proc/[0-9]*; do
                [ "$(readlink "$p/exe")" = "$src/tools/build/grade" ] && kill -9 "${p#/proc/}"
            done) 2>/dev/null &
        fi
        AUTOGRADER_ROOT=$ag timeout 300 sh "$src/run_autograder" >"$tmp/ag.log" 2>&1
        check "3. $(basename "$1"): run_autograder exited with $? ($(tail -n 2 "$tmp/ag.log"))" \
            test $? -eq 0
        wait
        check "3. $(basename "$1"): results.json is not JSON" \
            jq -e . "$ag/results/results.json" >/dev/null
    }
    for sub in chain daemon forkchain; do
        autograde "$tmp/class/$sub"
        contained "3. $sub"
        check "3. $sub: the score is not 0" test "$(jq .score "$ag/results/results.json")" = 0
    done
    for how in link fifo; do
        autograde "$tmp/planters/$how"
        contained "3. $how"
        check "3. $how: root read the root-only file into results.json" \
            test "$(grep -c "SECRET-$$" "$ag/results/results.json")" -eq 0
        check "3. $how: the grading was not finished" \
            test "$(jq '.tests | length' "$ag/results/results.json")" -eq 5
    done
    autograde "$tmp/planters/sleeper" 3
    contained "3. grader killed"
    check "3. a grader killed after a few seconds is told as the budget's end" \
        test "$(jq '.output | test("killed after [0-9]+ s")' "$ag/results/results.json")" = true
    echo "contain.sh: 3. took $(($(date +%s) - start)) s"
fi

if [ $failures -eq 0 ]; then
    echo "contain.sh: all $checks checks passed"
else
    echo "contain.sh: $failures of $checks checks failed (KEEP=1 keeps $tmp)"
    exit 1
fi
