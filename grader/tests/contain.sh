#!/bin/sh
# contain.sh: hostile submissions try to reach past their folder, in both sandboxes; none does.
#
# Usage: grader/tests/contain.sh GRADE [MODE...]   (make check-contain; GRADE is grader/build/grade,
#        with imgdiff beside it; MODE: namespaces, fallback, or both by default)
#
# Each part runs once a sandbox (grade --sandbox MODE, run_autograder's AUTOGRADER_SANDBOX):
#   1. grader/grade as a user who is not root, --jobs 1 and 2, on a class of part 1.1 whose
#      raytra, on the scene spheres-three, leaves behind: a chain of 1,500 processes each
#      the parent of the next, each in a session of its own and sharing its memory
#      (CLONE_VM); a chain of 100 of plain fork; a setsid daemon; a double fork; a CLONE_VM
#      child; a fork loop; a daemon that kills the grader's worker. Every process left
#      behind copies the reference over the image, again and again, 0.5 s after it starts,
#      and the chains' deepest also writes a results.json with 99 points wherever it may;
#   2. as root with --run-as, two students' uids and a grader's, --jobs 2;
#   3. by run_autograder as root, which also gets submissions that put a link to a file
#      only root may read, or a FIFO, where the grader's log would be, and one whose
#      grader is killed from outside after 2 s;
#   4. one submission (or two) for each way a submission once reached past its folder
#      (grader/docs/containment.md): a program that pushes a command into the grader's
#      terminal (TIOCSTI), one that keeps stopping every process of its user (SIGSTOP), a
#      classmate's build that puts folders at another's image paths, a program that copies
#      a classmate's images, one that fills the disk, one that leaves System V shared
#      memory, one that prints its environment, a class graded under umask 077, and
#      programs that copy the references from the grader's checkout or carry them in
#      files only they may read.
# After each: no process of the class runs (their executables are in this test's folder;
# their users' uids run nothing), no scene passes that should not, no 99 points, nothing
# of the root-only file in results.json, no hang. Parts 2, 3 and most of 4 need root, and
# 1 runs there as a spare uid, the fork loop capped by the limit grade sets (its user's
# processes and 256 more), then the 1,500-level chain alone as root, which no such limit
# holds; run as another user, 1 runs as that user without the fork loop or the chain as
# root, 2 and 3 are skipped, and 4 tries what needs no other user, which the test says.
# Each part's time is printed.
set -u
[ $# -ge 1 ] || { echo "usage: $0 GRADE [namespaces|fallback...]" >&2; exit 2; }
command -v jq >/dev/null 2>&1 ||
    { echo "contain.sh: jq is missing (common/deps.sh gradescope-test)" >&2; exit 2; }
case $1 in /*) grade=$1 ;; *) grade=$(pwd)/$1 ;; esac
shift
modes=${*:-namespaces fallback}
top=$(cd "$(dirname "$0")/../.." && pwd)
imgdiff=$top/compare/$(basename "$(dirname "$grade")")/imgdiff
part=1.1-spheres-red
refs=$top/milestones/$part/references
# How many scenes the part grades (renders.txt's lines but comments and illustrations).
n=$(grep -c '^[^#![:space:]]' "$refs/renders.txt")
model=$top/milestones/$part/raytra
[ -x "$model" ] || { echo "contain.sh: $model is not built" >&2; exit 2; }
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

cat >"$tmp/hostile.c" <<'EOF'
#define _GNU_SOURCE
#include <fcntl.h>
#include <sched.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/shm.h>
#include <sys/wait.h>
#include <termios.h>
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
    /* The classes of what a submission must not reach (part 4 below). */
    if (strcmp(MODE, "tty") == 0) {
        int fd = open("/dev/tty", O_RDWR | O_NOCTTY);
        printf("tty: %s\n", fd < 0 ? "no terminal" : "a terminal");
        for (const char *c = "touch " PWNED "\n"; fd >= 0 && *c != '\0'; c++)
            ioctl(fd, TIOCSTI, c);
    }
    if (strcmp(MODE, "stopper") == 0 && fork() == 0) {
        setsid();
        for (int k = 0; k < 3000; k++) {
            kill(-1, SIGSTOP);
            usleep(10000);
        }
        _exit(0);
    }
    for (int k = 0; strcmp(MODE, "shm") == 0 && k < 10; k++)
        if (shmget(IPC_PRIVATE, 64 << 20, IPC_CREAT | 0600) < 0)
            printf("shm: refused\n");
    extern char **environ;
    for (char **e = environ; strcmp(MODE, "env") == 0 && *e != NULL; e++)
        printf("env: %s\n", *e);
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
    printf 'raytra: main.c\n\tcc -O1 -o raytra main.c -DMODE=%s -DREF_DIR=%s -DFORGE_AT=%s -DPWNED=%s\n' \
        "'\"$3\"'" "'\"$refs\"'" "'\"$tmp/ag/results/results.json\"'" "'\"$tmp/pwned\"'" \
        >"$tmp/$1/$2/Makefile"
}

# Makes submission $2 of class $1 a program: the shell script on stdin, run with the model
# answer beside it ($m in the script), which it carries as a student's starter would.
program() {
    mkdir -p "$tmp/$1/$2" && cat >"$tmp/$1/$2/raytra.sh" && cp "$model" "$tmp/$1/$2/model" ||
        exit 2
    printf 'raytra: raytra.sh\n\tcp raytra.sh raytra\n\tchmod +x raytra\n' >"$tmp/$1/$2/Makefile"
}
# shellcheck disable=SC2016 # the students' scripts
m='"$(dirname "$0")/model"'

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
        kill -CONT $pids 2>/dev/null
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

# Prints how many scenes of submission $2 the CSV $1 gives verdict $3.
count() {
    grep -c "^$2,[a-z-]*,$3," "$1"
}

for m_ in chain forkchain daemon doublefork clonevm; do hostile class "$m_" "$m_"; done
$root && hostile class forkloop forkloop
mkdir "$tmp/killers" && hostile killers daemon daemon && hostile killers killer workerkiller &&
    hostile killers doublefork doublefork

# The classes of part 4: a correct program among hostile ones.
printf '#!/bin/sh\nexec %s "$@"\n' "$m" | program tty a-good
hostile tty b-tty tty
hostile stopper stopper stopper
printf '#!/bin/sh\nexec %s "$@"\n' "$m" | program sabotage a-victim
mkdir -p "$tmp/sabotage/b-saboteur"
# Its make, for 15 s, puts folders where a-victim's program writes its images.
cat >"$tmp/sabotage/b-saboteur/Makefile" <<'MAKE'
raytra:
	for i in $$(seq 300); do for n in spheres-three spheres-behind-camera camera-straight-down \
	    camera-straight-up camera-inside-sphere spheres-grid-wide demo; do \
	    mkdir -p ../../01-a-victim/images/$$n.png 2>/dev/null; done; sleep 0.05; done
	printf '#!/bin/sh\nexit 0\n' >raytra && chmod +x raytra
MAKE
printf '#!/bin/sh\nexec %s "$@"\n' "$m" | program peek a-good
printf '#!/bin/sh\nexec cp ../../01-a-good/images/"$(basename "$2")" "$2"\n' | program peek b-peeker
# It writes 16 MiB files, 20 a second, up to 2 GiB, at every scene; then a correct one.
printf '#!/bin/sh\ni=0\nwhile [ $i -lt 128 ] && head -c 16777216 /dev/zero >fill-$i; do i=$((i + 1)); sleep 0.05; done\n' |
    program filler a-filler
printf '#!/bin/sh\nexec %s "$@"\n' "$m" | program filler b-good
hostile shm shm shm
hostile env env env
printf '#!/bin/sh\nexec %s "$@"\n' "$m" | program umask good
# The references: from the grader's checkout (its path in the scene's), and carried in
# files of the submission that only its user may read, copied by a program that renders
# nothing.
printf '#!/bin/sh\nexec cp %s/"$(basename "$2")" "$2"\n' "$refs" | program copiers a-checkout
printf '#!/bin/sh\nexec cp "$(dirname "$0")/refs/$(basename "$2")" "$2"\n' | program copiers b-carried
mkdir "$tmp/copiers/b-carried/refs" && cp "$refs"/*.png "$tmp/copiers/b-carried/refs/" &&
    chmod 604 "$tmp/copiers/b-carried/refs"/*.png || exit 2
chmod -R a+rX "$tmp" || exit 2
chmod 604 "$tmp/copiers/b-carried/refs"/*.png

# Runs part 1 to 4 with the sandbox $1.
parts() {
    mode=$1
    say="contain.sh: $mode:"
    # 1. grader/grade as a user who is not root: the subreaper's sweep.
    as_user=""
    if $root; then
        mkdir -p "$tmp/$mode/out1" && chown "$sweeper:$sweeper" "$tmp/$mode/out1" || exit 2
        as_user="setpriv --reuid=$sweeper --regid=$sweeper --clear-groups --"
        echo "$say 1. grade as uid $sweeper, not root"
    else
        mkdir -p "$tmp/$mode/out1" || exit 2
        echo "$say 1. grade as $(id -un) (not root: no fork loop, and parts 2 and 3 skipped)"
    fi
    start=$(date +%s)
    # shellcheck disable=SC2086
    $as_user "$grade" --sandbox "$mode" -q --time-limit 30 --out "$tmp/$mode/out1/one" 1.1 "$tmp/class" >"$tmp/one.log" 2>&1
    check "1. grade exited with $? ($(tail -n 2 "$tmp/one.log"))" test $? -eq 0
    contained "1. --jobs 1" "$tmp/$mode/out1/one/grades.csv"
    check "1. the chain of 1,500 did not grow whole, nor stop at a limit" \
        grep -q 'chain: ' "$tmp/$mode/out1/one/work/01-chain/spheres-three.log"
    echo "$say 1. $(sed -n 's/^chain: //p' "$tmp/$mode/out1/one/work/01-chain/spheres-three.log")"
    # shellcheck disable=SC2086
    $as_user "$grade" --sandbox "$mode" -q --jobs 2 --time-limit 30 --out "$tmp/$mode/out1/two" 1.1 "$tmp/killers" \
        >"$tmp/two.log" 2>&1
    check "1. grade --jobs 2 exited with $? ($(tail -n 2 "$tmp/two.log"))" test $? -eq 0
    contained "1. --jobs 2, a worker killed" "$tmp/$mode/out1/two/grades.csv"
    # In namespaces the worker is out of reach (a program's parent is its sandbox's first
    # process); in the fallback it is killed, and its scenes are ERRORs that say so.
    if [ "$mode" = namespaces ]; then
        check "1. the worker killer reached its worker" \
            test "$(grep -c 'worker ended without' "$tmp/$mode/out1/two/grades.csv")" -eq 0
    else
        check "1. the killed worker's scenes are not ERRORs" \
            test "$(grep -c '^killer,.*,ERROR,' "$tmp/$mode/out1/two/grades.csv")" -eq "$n"
    fi
    if $root; then
        # As root, no limit holds the number of processes: the chain grows its 1,500 levels.
        mkdir "$tmp/$mode/deep" && cp -R "$tmp/class/chain" "$tmp/$mode/deep/" || exit 2
        "$grade" --sandbox "$mode" -q --time-limit 60 --out "$tmp/$mode/out1/deep" 1.1 "$tmp/$mode/deep" >"$tmp/$mode/deep.log" 2>&1
        check "1. grade as root exited with $? ($(tail -n 2 "$tmp/$mode/deep.log"))" test $? -eq 0
        contained "1. as root, a chain of 1,500" "$tmp/$mode/out1/deep/grades.csv"
        check "1. as root, the chain did not grow its 1,500 levels" \
            grep -q 'all 1500 levels' "$tmp/$mode/out1/deep/work/01-chain/spheres-three.log"
    fi
    echo "$say 1. took $(($(date +%s) - start)) s"

    if ! $root; then
        echo "$say not root: --run-as and run_autograder not tested"
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
            "$grade" --sandbox "$mode" $bad --out "$tmp/refused" 1.1 "$tmp/class" >"$tmp/refused.log" 2>&1
            check "2. grade $bad: exit status $?, not 2" test $? -eq 2
            check "2. grade $bad: graded ($(head -n 1 "$tmp/refused.log"))" test ! -e "$tmp/refused"
        done
        kill "$busy"
        wait "$busy" 2>/dev/null
        mkdir "$tmp/$mode/out2" && chown "$graderuid:$graderuid" "$tmp/$mode/out2" || exit 2
        # The fork loop alone: in the fallback, a process left behind lives until the sweep,
        # which a fork loop graded beside it slows (grader/docs/containment.md).
        if [ ! -d "$tmp/both" ]; then
            mkdir "$tmp/both" "$tmp/loop" && cp -R "$tmp/class/." "$tmp/killers/." "$tmp/both/" &&
                mv "$tmp/both/forkloop" "$tmp/loop/" && chmod -R a+rX "$tmp/both" "$tmp/loop" ||
                exit 2
        fi
        "$grade" --sandbox "$mode" -q --jobs 2 --run-as "$student1,$student2" --grader-user "$graderuid" \
            --time-limit 30 --out "$tmp/$mode/out2/g" 1.1 "$tmp/both" >"$tmp/run-as.log" 2>&1
        check "2. grade --run-as exited with $? ($(tail -n 2 "$tmp/run-as.log"))" test $? -eq 0
        contained "2. --run-as, --jobs 2" "$tmp/$mode/out2/g/grades.csv"
        "$grade" --sandbox "$mode" -q --run-as "$student1" --grader-user "$graderuid" \
            --time-limit 30 --out "$tmp/$mode/out2/loop" 1.1 "$tmp/loop" >"$tmp/loop.log" 2>&1
        check "2. grade --run-as of a fork loop exited with $? ($(tail -n 2 "$tmp/loop.log"))" \
            test $? -eq 0
        contained "2. --run-as, a fork loop" "$tmp/$mode/out2/loop/grades.csv"
        check "2. a student's program could write in the grader's folder" \
            test ! -e "$tmp/$mode/out2/g/results.json"
        check "2. the report was not the grader's user's" \
            test "$(stat -c %u "$tmp/$mode/out2/g/report.html")" = "$graderuid"
        echo "$say 2. $(sed -n 's/^chain: //p' "$tmp/$mode/out2/g/work/01-chain/spheres-three.log")"
        echo "$say 2. took $(($(date +%s) - start)) s"

        # 3. run_autograder as root: its grader in a source folder of its own.
        start=$(date +%s)
        ag=$tmp/ag src=$tmp/ag/source
        rm -rf "$ag" "$tmp/planters"
        mkdir -p "$src/grader/build" "$src/compare/build" "$src/milestones/$part" "$ag/results" || exit 2
        cp "$grade" "$src/grader/build/" && cp "$imgdiff" "$src/compare/build/" &&
            cp -R "$refs" "$src/milestones/$part/" && cp -R "$top/scenes" "$src/" &&
            cp "$top/platforms/gradescope/setup.sh" "$top/platforms/gradescope/run_autograder" "$src/" &&
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
        # A program that copies the references of the autograder's own folder.
        mkdir "$tmp/planters/checkout"
        printf '#!/bin/sh\nexec cp %s/"$(basename "$2")" "$2"\n' "$src/milestones/$part/references" \
            >"$tmp/planters/checkout/raytra.sh"
        cp "$tmp/planters/link/Makefile" "$tmp/planters/checkout/"
        mkdir "$tmp/planters/sleeper"
        printf '#!/bin/sh\nsetsid sleep 300 &\nexec sleep 300\n' >"$tmp/planters/sleeper/raytra.sh"
        cp "$tmp/planters/link/Makefile" "$tmp/planters/sleeper/"
        chmod -R a+rX "$tmp/planters" "$ag"
        export AUTOGRADER_USER=$student1 AUTOGRADER_GRADER_USER=$graderuid AUTOGRADER_SANDBOX=$mode
        # Runs the autograder on submission $1 (under 300 s, or it hung); $2: kill its grader then.
        autograde() {
            rm -rf "$ag/submission" "$ag/results/results.json"
            cp -R "$1" "$ag/submission" && chmod -R a+rX "$ag/submission"
            if [ -n "${2:-}" ]; then
                (sleep "$2" && for p in /proc/[0-9]*; do
                    [ "$(readlink "$p/exe")" = "$src/grader/build/grade" ] && kill -9 "${p#/proc/}"
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
                test "$(jq '.tests | length' "$ag/results/results.json")" -eq "$n"
        done
        autograde "$tmp/planters/checkout"
        check "3. checkout: the autograder's references were copied" \
            test "$(jq .score "$ag/results/results.json")" = 0
        autograde "$tmp/planters/sleeper" 3
        contained "3. grader killed"
        check "3. a grader killed after a few seconds is told as the budget's end" \
            test "$(jq '.output | test("killed after [0-9]+ s")' "$ag/results/results.json")" = true
        echo "$say 3. took $(($(date +%s) - start)) s"
    fi


    # 4. The ways a submission once reached past its folder, one a class.
    start=$(date +%s)
    out=$tmp/$mode/out4
    mkdir -p "$out" && chmod 755 "$tmp/$mode" "$out" || exit 2
    if $root; then
        as="--run-as $student1,$student2 --grader-user $graderuid"
        [ "$(stat -c %u "$out")" = "$graderuid" ] || chown "$graderuid:$graderuid" "$out"
    else
        as=""
        echo "$say 4. as $(id -un): what needs no user of its own"
    fi
    # Grades class $1 into $out/$1 with the rest of the options, its output in $out/$1.log;
    # sets $status.
    grade4() {
        class=$1
        shift
        # shellcheck disable=SC2086 # $as is words by design
        timeout 300 "$grade" --sandbox "$mode" -q $as --time-limit 30 "$@" --out "$out/$class" \
            1.1 "$tmp/$class" >"$out/$class.log" 2>&1
        status=$?
    }
    csv() { echo "$out/$1/grades.csv"; }

    # The terminal: grade runs in one (script(1) makes it), and no program may open it.
    rm -f "$tmp/pwned"
    # shellcheck disable=SC2086
    script -qec "'$grade' --sandbox $mode -q $as --out '$out/tty' 1.1 '$tmp/tty'" /dev/null \
        >"$out/tty.log" 2>&1 </dev/null
    check "4. tty: grade failed ($(tail -n 2 "$out/tty.log"))" test -s "$(csv tty)"
    check "4. tty: the program had a terminal" \
        grep -q 'tty: no terminal' "$out/tty/work/02-b-tty/spheres-three.log"
    check "4. tty: a command was pushed into the grader's terminal" test ! -e "$tmp/pwned"
    check "4. tty: the correct program did not pass" test "$(count "$(csv tty)" a-good PASS)" -eq "$n"

    # A program that keeps stopping every process of its user: grade ends, nothing is left.
    if $root; then
        grade4 stopper
        check "4. stopper: grade did not end ($status)" test "$status" -eq 0
        contained "4. stopper"
    fi

    # Classmates graded at once: one's make puts folders at the other's image paths.
    if $root; then
        grade4 sabotage --jobs 2
        check "4. sabotage: grade exited with $status" test "$status" -eq 0
        check "4. sabotage: a classmate's make reached the victim's folder" \
            test "$(count "$(csv sabotage)" a-victim PASS)" -eq "$n"
    fi

    # A program that copies a classmate's images (as one user, then two at once).
    if $root || [ "$mode" = namespaces ]; then
        for jobs in 1 2; do
            # shellcheck disable=SC2086
            [ $jobs -eq 1 ] && $root && as1="--run-as $student1 --grader-user $graderuid" || as1=$as
            as_was=$as as=$as1
            grade4 peek --jobs "$([ -n "$as" ] && echo $jobs || echo 1)"
            as=$as_was
            check "4. peek, --jobs $jobs: the good program did not pass" \
                test "$(count "$(csv peek)" a-good PASS)" -eq "$n"
            check "4. peek, --jobs $jobs: a classmate's images were copied" \
                test "$(count "$(csv peek)" b-peeker PASS)" -eq 0
        done
    fi

    # A program that fills the disk: stopped at its limit, named; the next one graded.
    grade4 filler --disk-limit 64M
    check "4. filler: grade exited with $status" test "$status" -eq 0
    check "4. filler: no report" test -s "$out/filler/report.html"
    check "4. filler: not named with its reason" \
        test "$(grep -c '^a-filler,[a-z-]*,ERROR,.*the disk limit' "$(csv filler)")" -eq "$n"
    check "4. filler: the next submission did not pass" test "$(count "$(csv filler)" b-good PASS)" -eq "$n"
    check "4. filler: its files were left" test -z "$(ls "$out/filler/work/01-a-filler/run")"

    # System V shared memory: none of the students' is left (in namespaces, none at all).
    shm_of() { awk -v u="$1" 'NR > 1 && ($8 == u || $10 == u)' /proc/sysvipc/shm | wc -l; }
    if $root || [ "$mode" = namespaces ]; then
        before=$(shm_of "$(id -u)")
        grade4 shm --memory-limit 64M
        check "4. shm: grade exited with $status" test "$status" -eq 0
        check "4. shm: the program made none" grep -q 'exit status 0' "$out/shm/work/01-shm/spheres-three.log"
        left=$(($(shm_of "$student1") + $(shm_of "$student2") + $(shm_of "$(id -u)") - before))
        check "4. shm: $left segments outlived the grading" test "$left" -eq 0
    fi

    # The environment: nothing of the grader's.
    RAYTRA_TEST_TOKEN=secret-$$ HOME=/root grade4 env
    check "4. env: the grader's token reached the program" \
        test "$(grep -c 'RAYTRA_TEST_TOKEN\|^env: HOME=/root' "$out/env/work/01-env/spheres-three.log")" -eq 0
    check "4. env: no PATH" grep -q '^env: PATH=' "$out/env/work/01-env/spheres-three.log"

    # A class graded under umask 077, as root's may be.
    (umask 077 && grade4 umask && exit "$status")
    status=$?
    check "4. umask 077: grade exited with $status" test "$status" -eq 0
    check "4. umask 077: the program did not pass" test "$(count "$(csv umask)" good PASS)" -eq "$n"

    # The references copied: from the checkout (unseen in namespaces; in the fallback, only
    # where the checkout is readable to the students' users, told below), or carried in
    # files only the student may read, flagged.
    grade4 copiers
    check "4. copiers: grade exited with $status" test "$status" -eq 0
    [ "$mode" = fallback ] ||
        check "4. copiers: the checkout's references were copied" \
            test "$(count "$(csv copiers)" a-checkout PASS)" -eq 0
    [ "$mode" = namespaces ] ||
        echo "$say 4. the checkout's references copied: $(count "$(csv copiers)" a-checkout PASS) of $n pass"
    check "4. copiers: carried references not flagged" \
        test "$(grep '^b-carried,[a-z-]*,PASS,' "$(csv copiers)" | grep -vc ',copy,')" -eq 0
    echo "$say 4. took $(($(date +%s) - start)) s"
}

for mode in $modes; do
    parts "$mode"
done

if [ $failures -eq 0 ]; then
    echo "contain.sh: all $checks checks passed"
else
    echo "contain.sh: $failures of $checks checks failed (KEEP=1 keeps $tmp)"
    exit 1
fi
