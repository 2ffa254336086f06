#!/bin/sh
# interrupt.sh: an interrupted or failed render leaves no image, no temporary and the old image as it was.
#
# Usage: tests/interrupt.sh RAYTRA
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
set -u
[ $# -eq 1 ] || { echo "usage: $0 RAYTRA" >&2; exit 2; }
raytra=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
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

# Starts raytra with $2 threads (default 1) on the pipe "scene", writing $1, in the
# background; sets pid.
start() {
    rm -f scene
    mkfifo scene
    "$raytra" -q -j "${2:-1}" scene "$1" 2>err &
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
for signal in INT TERM; do
    case $signal in INT) expected=130 threads=1 ;; TERM) expected=143 threads=2 ;; esac
    mkdir -p out
    cp old.png out/image.png
    start out/image.png "$threads"
    if ! feed long.scn; then
        kill -KILL "$pid" 2>/dev/null
        fail "SIG$signal: raytra never read its scene:"
        sed 's/^/    /' err
        continue
    fi
    sleep 0.5
    if ! kill -0 "$pid" 2>/dev/null; then
        wait "$pid"
        fail "SIG$signal: the render ended by itself (exit status $?) before the signal"
        sed 's/^/    /' err
        continue
    fi
    kill -"$signal" "$pid"
    if ! ends_within 20; then
        kill -KILL "$pid"
        wait "$pid"
        fail "SIG$signal: raytra was still running 2 s after the signal"
        continue
    fi
    wait "$pid"
    status=$?
    if [ "$status" -ne "$expected" ]; then
        fail "SIG$signal: exit status $status, expected $expected"
    elif ! grep -q "interrupted; 'out/image.png' was not written" err; then
        fail "SIG$signal: no 'interrupted' message"
    elif ! cmp -s old.png out/image.png; then
        fail "SIG$signal: the existing image was changed"
    elif ! only_files out "image.png "; then
        fail "SIG$signal: files left beside the image: $(ls -A out)"
    else
        ok "SIG$signal (-j $threads): stopped within 2 s, exit status $status, old image untouched"
        continue
    fi
    sed 's/^/    /' err
done

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
    kill -INT "$pid"
    if ! ends_within 10; then
        kill -KILL "$pid"
        wait "$pid"
        fail "SIGINT while reading endless $kind: raytra was still running 1 s after it"
    else
        wait "$pid"
        status=$?
        if [ "$status" -eq 130 ] && grep -q "interrupted; 'out/image.png' was not written" err; then
            ok "SIGINT while reading endless $kind: stopped within 1 s, exit status 130"
        else
            fail "SIGINT while reading endless $kind: exit status $status, expected 130 and the message:"
            sed 's/^/    /' err
        fi
    fi
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

echo "interrupt: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
