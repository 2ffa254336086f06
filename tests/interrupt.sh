#!/bin/sh
# interrupt.sh: an interrupted or failed render leaves no image, no temporary and the old image as it was.
#
# Usage: tests/interrupt.sh RAYTRA [LATEST]
#
# RAYTRA should be part 1.1's program: it tests every sphere for every pixel, so a scene
# of many spheres that no ray hits makes a render that lasts minutes on any machine.
# The scene is fed through a named pipe: raytra opens it only after it has checked the
# output and installed its signal handlers, so each step below happens at a known point
# of the run, whatever the load of the machine.
#   1. SIGINT (1 thread), then SIGTERM (2 threads), during a long render: raytra stops
#      within 2 s with exit status 130 or 143, says the image was not written, and leaves
#      the old image byte for byte as it was and no temporary file beside it.
#   2. SIGINT while the scene is still being read (an endless stream of lines, then one
#      endless line, through the pipe): raytra stops within 1 s with exit status 130.
#   3. The output's folder removed while raytra runs: it says it cannot write, exits 1.
#   4. Writing fails (a file-size limit smaller than the image, as a full disk would): it
#      says so, exits 1, and the old image and the folder are as they were.
# LATEST, the latest part's program, adds what one pixel can cost:
#   5. SIGINT and SIGTERM while every pixel takes seconds (part 1.6 at P = S = 64: 4096
#      samples of 4096 shadow rays each): raytra gives up the pixels under way and ends
#      within 1 s, as in 1; under valgrind's memcheck (when installed) too, with no
#      memory error, and, where the workers finish their pixel in time (RAYTRA's scene),
#      with no leak either.
#   6. SIGINT while --trace-pixel is stuck writing to a pipe nobody reads: it ends within
#      1 s with 130; a trace of more than a million lines is refused, pointing to @K.
#   7. The largest --max-depth, 1000, on a path that bounces inside glass (total internal
#      reflection) all the way, rendered and traced with a stack limit of 256 KiB.
set -u
if [ $# -lt 1 ] || [ $# -gt 2 ]; then
    echo "usage: $0 RAYTRA [LATEST]" >&2
    exit 2
fi
raytra=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
latest=
[ $# -eq 2 ] && latest=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
tmp=$(mktemp -d /tmp/raytra-interrupt.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
cd "$tmp" || exit 2

# 1000 x 1000 pixels and 20000 spheres behind the camera: 2e10 ray-sphere tests.
awk 'BEGIN {
    print "c 0 0 0  0 0 -1  35 35 35  1000 1000"
    print "m 0.8 0.1 0.1  0.5 0.5 0.5  50  0 0 0"
    for (k = 0; k < 20000; k++) print "s", k, 0, 100, 1
}' >long.scn
printf 'c 0 0 0  0 0 -1  35 35 35  16 16\nm 1 0 0  0 0 0  1  0 0 0\ns 0 0 -50 10\n' >small.scn

failed=0 passed=0
fail() { echo "FAIL $*"; failed=$((failed + 1)); }
ok() { echo "ok   $*"; passed=$((passed + 1)); }

# Starts $program (raytra unless set) with $2 threads (default 1) and the options
# $options on the pipe "scene", writing $1, in the background, under $wrapper if set
# (valgrind); sets pid.
program='' options='' wrapper=''
start() {
    rm -f scene
    mkfifo scene
    # shellcheck disable=SC2086 # options and wrapper are words by design
    $wrapper "${program:-$raytra}" -q -j "${2:-1}" $options scene "$1" 2>err &
    pid=$!
}

# Feeds scene file $1 through the pipe, running command $2 (if any) once raytra has opened
# it; false when raytra ends or 60 s pass before it does.
feed() {
    rm -f opened go
    (
        exec 3>scene
        : >opened
        while [ ! -e go ]; do sleep 0.05; done
        cat "$1" >&3
    ) &
    feeder=$!
    n=0
    while [ ! -e opened ]; do
        if ! kill -0 "$pid" 2>/dev/null || [ "$n" -ge 600 ]; then
            kill "$feeder"
            return 1
        fi
        sleep 0.1
        n=$((n + 1))
    done
    ${2:+$2}
    : >go
    wait "$feeder"
}

# Waits up to $1 tenths of a second for raytra to end; false if it is still running.
ends_within() {
    n=0
    while kill -0 "$pid" 2>/dev/null; do
        [ "$n" -ge "$1" ] && return 1
        sleep 0.1
        n=$((n + 1))
    done
}

# Tells whether the folder holds exactly the files named (sorted), no temporaries.
only_files() {
    # shellcheck disable=SC2012 # the names are the test's own
    [ "$(ls -A "$1" | tr '\n' ' ')" = "$2" ]
}

"$raytra" -q small.scn old.png 2>err || { echo "interrupt: cannot render small.scn:"; cat err; exit 1; }
# Renders scene $1 with $3 threads over a copy of the old image, sends SIG$2 once the
# render is under way ($7 seconds after it read the scene, default 0.5), and checks that
# raytra ends within $4 tenths of a second with 128 + the signal, the message, the old
# image untouched and no temporary beside it; $5 names the case. $6, yes or no, says
# whether raytra must have given up pixels under way (a note says so) or waited for them.
interrupt_render() {
    signal=$2 within=$4 what=$5 given_up=${6:-} delay=${7:-0.5}
    case $signal in INT) expected=130 ;; TERM) expected=143 ;; esac
    mkdir -p out
    cp old.png out/image.png
    start out/image.png "$3"
    if ! feed "$1"; then
        kill -KILL "$pid" 2>/dev/null
        fail "$what: raytra never read its scene:"
        sed 's/^/    /' err
        return
    fi
    sleep "$delay"
    if ! kill -0 "$pid" 2>/dev/null; then
        wait "$pid"
        fail "$what: the render ended by itself (exit status $?) before the signal"
        sed 's/^/    /' err
        return
    fi
    kill -"$signal" "$pid"
    if ! ends_within "$within"; then
        kill -KILL "$pid"
        wait "$pid"
        fail "$what: raytra was still running $((within / 10)) s after the signal"
        return
    fi
    wait "$pid"
    status=$?
    if [ "$status" -ne "$expected" ]; then
        fail "$what: exit status $status, expected $expected"
    elif ! grep -q "interrupted; 'out/image.png' was not written" err; then
        fail "$what: no 'interrupted' message"
    elif ! cmp -s old.png out/image.png; then
        fail "$what: the existing image was changed"
    elif ! only_files out "image.png "; then
        fail "$what: files left beside the image: $(ls -A out)"
    elif [ "$given_up" = yes ] && ! grep -q "stopped without waiting for the pixels" err; then
        fail "$what: the pixels under way were not given up"
    elif [ "$given_up" = no ] && grep -q "stopped without waiting" err; then
        fail "$what: pixels were given up instead of finished"
    else
        ok "$what: stopped within $((within / 10)) s, exit status $status, old image untouched"
        return
    fi
    sed 's/^/    /' err
}

interrupt_render long.scn INT 1 20 "SIGINT (-j 1)" no
interrupt_render long.scn TERM 2 20 "SIGTERM (-j 2)" no

# Sends SIGINT to raytra, which must end within 1 s with exit status 130 and a standard
# error that holds each of the patterns after $1, which names the case.
sigint_ends() {
    what=$1
    shift
    kill -INT "$pid"
    if ! ends_within 10; then
        kill -KILL "$pid"
        wait "$pid"
        fail "$what: raytra was still running 1 s after SIGINT"
        return
    fi
    wait "$pid"
    status=$?
    for pattern; do
        grep -q -- "$pattern" err || status="$status, without '$pattern'"
    done
    if [ "$status" = 130 ]; then
        ok "$what: stopped within 1 s, exit status 130"
    else
        fail "$what: exit status $status; expected 130 and the messages:"
        sed 's/^/    /' err
    fi
}

# SIGINT while loading: the pipe never ends, so only the signal can stop the reading.
for kind in lines line; do
    start out/image.png
    rm -f opened
    (
        exec 3>scene
        : >opened
        case $kind in
        lines) yes '/ an endless scene, one comment line after another' ;;
        line) yes x | tr -d '\n' ;;
        esac >&3 2>/dev/null
    ) &
    feeder=$!
    n=0
    while [ ! -e opened ] && [ "$n" -lt 600 ]; do sleep 0.1; n=$((n + 1)); done
    sleep 0.5
    sigint_ends "SIGINT while reading endless $kind" "interrupted; 'out/image.png' was not written"
    kill "$feeder" 2>/dev/null
    wait "$feeder" 2>/dev/null
done

# The output's folder disappears after raytra checked it and before it writes.
mkdir gone
start gone/image.png
if ! feed small.scn "rmdir gone"; then
    kill -KILL "$pid" 2>/dev/null
    fail "removed folder: raytra never read its scene:"
    sed 's/^/    /' err
else
    wait "$pid"
    status=$?
    if [ "$status" -eq 1 ] && grep -q "cannot write 'gone/image.png'" err && [ ! -e gone ]; then
        ok "removed folder: exit status 1: $(grep 'cannot write' err)"
    else
        fail "removed folder: exit status $status (expected 1 and a 'cannot write' message):"
        sed 's/^/    /' err
    fi
fi

# Writing fails: past a file-size limit (with SIGXFSZ ignored) a write is refused with
# EFBIG, as a full disk refuses it with ENOSPC. The limit, one block of 512 bytes, leaves
# room for the messages (standard error is a file too) but not for a 3 KB PFM image.
"$raytra" -q small.scn old.pfm 2>err || { echo "interrupt: cannot render small.scn:"; cat err; exit 1; }
mkdir -p full
cp old.pfm full/image.pfm
(
    trap '' XFSZ
    ulimit -f 1
    exec "$raytra" -q -j 1 small.scn full/image.pfm
) 2>err
status=$?
if [ "$status" -eq 1 ] && grep -q "cannot write 'full/image.pfm'" err &&
    cmp -s old.pfm full/image.pfm && only_files full "image.pfm "; then
    ok "write error: exit status 1, old image untouched: $(grep 'cannot write' err)"
else
    fail "write error: exit status $status (expected 1, a 'cannot write' message, the old image" \
        "untouched and no temporary); the folder holds: $(ls -A full)"
    sed 's/^/    /' err
fi

# What one pixel can cost: with the latest part, pixels of seconds, traces that block,
# and paths as deep as --max-depth allows.
if [ -n "$latest" ]; then
    # Part 1.6 at P = S = 64 over a mirror floor under a square light: a pixel is 4096
    # samples, each with 4096 shadow rays at its hit and as many after the mirror.
    cat >slow.scn <<'EOF'
c 0 10 30  0 -0.3 -1  35  35 35  8 8
l s 0 20 0  0 -1 0  1 0 0  10  1 1 1
m 0.3 0.3 0.3  0 0 0  1  0.7 0.7 0.7
p 0 1 0 0
m 0.8 0.2 0.1  0 0 0  1  0 0 0
s 0 4 -5  4
EOF
    # The same looking down at the floor, so that every pixel is one of seconds, the first
    # ones too: the pixels under way are given up, however fast the machine.
    sed 's/^c 0 10 30  0 -0.3 -1 /c 0 10 30  0 -1 -0.3 /' slow.scn >steep.scn
    program=$latest options="--samples 64 --light-samples 64"
    interrupt_render steep.scn INT 1 10 "SIGINT in a pixel of seconds (-j 1)" yes
    interrupt_render steep.scn TERM 2 10 "SIGTERM in a pixel of seconds (-j 2)" yes
    if grep -q __asan_init "$latest" "$raytra"; then
        echo "skip memcheck: a sanitized build, which AddressSanitizer checks instead"
    elif command -v valgrind >/dev/null 2>&1; then
        # Given up mid-pixel (every pixel of steep.scn takes seconds, so that the pixels
        # under way are given up however fast the machine), the workers still hold the
        # scene and the image when the process ends: no memory error may come of it (what
        # they hold is not freed, on purpose, so leaks are not counted here). valgrind runs
        # one thread at a time, and its default lock lets a busy worker take it back at
        # once: --fair-sched=yes queues the waiting thread, so that the one that polls for
        # the signal runs at all (without it, it can wait for minutes on two cores).
        wrapper="valgrind -q --fair-sched=yes --error-exitcode=99 --leak-check=no"
        interrupt_render steep.scn INT 2 600 "SIGINT in a pixel of seconds, under memcheck" yes 5
        # Workers that finish their pixel within the grace leave nothing behind at all.
        program='' options=''
        wrapper="valgrind -q --fair-sched=yes --error-exitcode=99 --leak-check=full"
        wrapper="$wrapper --show-leak-kinds=all"
        wrapper="$wrapper --errors-for-leak-kinds=all"
        interrupt_render long.scn INT 2 100 "SIGINT in a long render, under memcheck" no 3
        wrapper=
    else
        echo "skip memcheck: valgrind is not installed (sudo apt-get install -y valgrind)"
    fi
    program='' options=''

    # Inside a slab of glass, looking along it: every ray meets the glass beyond the
    # critical angle and bounces between its faces until --max-depth ends it, with
    # nothing pruned (R = 1).
    cat >slab.scn <<'EOF'
c 0 0 0  0 0 -1  35  35 35  8 8
l p 0 0 -50  1 1 1
m 0.1 0.1 0.1  0 0 0  1  0 0 0  1.5
p 0 1 0 -1
p 0 -1 0 -1
EOF

    # --trace-pixel writing into a pipe that nobody reads blocks once the pipe is full,
    # however the trace itself goes.
    rm -f tree
    mkfifo tree
    (
        exec 4<tree
        sleep 60
    ) &
    reader=$!
    rm -f scene
    mkfifo scene
    "$latest" -q --max-depth 1000 --trace-pixel 4,4 scene >tree 2>err &
    pid=$!
    if ! feed slab.scn; then
        kill -KILL "$pid" 2>/dev/null
        fail "--trace-pixel: raytra never read its scene:"
        sed 's/^/    /' err
    else
        sleep 0.5
        sigint_ends "--trace-pixel into a full pipe" "^raytra: interrupted$" \
            "stopped without waiting for the trace"
    fi
    kill "$reader" 2>/dev/null
    wait "$reader" 2>/dev/null
    rm -f tree

    # A trace of 4096 samples of 4096 shadow rays is refused; one sample of it is not.
    "$latest" --samples 64 --light-samples 64 --trace-pixel 4,4 slow.scn >tree 2>err
    status=$?
    if [ "$status" -eq 2 ] && grep -q "at least 83.9 million lines" err &&
        grep -q -- "--trace-pixel 4,4@K (K from 0 to 4095)" err && [ ! -s tree ]; then
        ok "--trace-pixel of 84 million lines: refused, exit status 2, pointing to @K"
    else
        fail "--trace-pixel of 84 million lines: exit status $status (expected 2 and the @K hint):"
        sed 's/^/    /' err
    fi
    if "$latest" --samples 64 --light-samples 64 --trace-pixel 4,4@100 slow.scn >tree 2>err &&
        grep -q "^sample 100: colour" tree; then
        ok "--trace-pixel of one of its samples, 4,4@100: $(wc -l <tree) lines"
    else
        fail "--trace-pixel 4,4@100 failed:"
        sed 's/^/    /' err
    fi

    # The deepest path with a small stack: render threads ask for their own.
    (
        # shellcheck disable=SC3045 # every sh raytra runs on (dash, bash) has ulimit -s
        ulimit -s 256
        "$latest" -q -j 2 --max-depth 1000 --min-weight 0 slab.scn slab.png &&
            "$latest" -q --max-depth 1000 --min-weight 0 --trace-pixel 4,4 slab.scn >tree
    ) 2>err
    status=$?
    if [ "$status" -eq 0 ] && [ -s slab.png ] &&
        [ "$(grep -c 'total internal reflection' tree)" -eq 1000 ]; then
        ok "--max-depth 1000 inside glass under 'ulimit -s 256': rendered and traced, 1000 reflections"
    else
        fail "--max-depth 1000 inside glass under 'ulimit -s 256': exit status $status" \
            "($(grep -c 'total internal reflection' tree) reflections traced):"
        sed 's/^/    /' err
    fi
fi

echo "interrupt: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
