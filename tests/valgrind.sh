#!/bin/sh
# valgrind.sh: renders and broken inputs under valgrind's memcheck: no memory error, no leak.
#
# Usage: tests/valgrind.sh PART_DIR...     (make valgrind; each part's raytra built normally)
#
# For every part: the first three scenes of its references/renders.txt (with their
# options) and scenes/degenerate-geometry.scn, at a quarter of their size, on 2 threads.
# With the last part: broken inputs that take the error paths (a bad value, a missing
# mesh, a bad mesh, binary garbage, a bad output path, --check), and the fuzzing
# regression drivers on every kept input, if they are built (tests/fuzz/build/).
# Each run must end with the status it would have without valgrind, and valgrind must
# report no error and no leak of any kind (--errors-for-leak-kinds=all).
set -u
[ $# -ge 1 ] || { echo "usage: $0 PART_DIR..." >&2; exit 2; }
if ! command -v valgrind >/dev/null 2>&1; then
    echo "valgrind.sh: valgrind is not installed; install it with: sudo apt-get install -y valgrind" >&2
    exit 2
fi
top=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d /tmp/raytra-valgrind.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

# An error exit status no raytra run gives, so that valgrind's findings stand out.
VALGRIND_STATUS=99
passed=0 failed=0

# Runs "$@" under memcheck, which must exit with status $expected; named $what in messages.
memcheck() {
    valgrind -q --error-exitcode=$VALGRIND_STATUS --leak-check=full --show-leak-kinds=all \
        --errors-for-leak-kinds=all --track-origins=yes "$@" >"$tmp/out" 2>"$tmp/err"
    status=$?
    if [ "$status" -eq "$expected" ]; then
        passed=$((passed + 1))
        echo "ok   $what"
        return
    fi
    failed=$((failed + 1))
    if [ "$status" -eq $VALGRIND_STATUS ]; then
        echo "FAIL $what: valgrind found errors:"
    else
        echo "FAIL $what: exit status $status, expected $expected:"
    fi
    sed 's/^/    /' "$tmp/err" | head -n 60
}

for dir in "$@"; do
    part=$(basename "$dir")
    raytra=$top/$dir/raytra
    {
        sed -e 's/#.*//' "$top/$dir/references/renders.txt" |
            awk 'NF >= 2 { $1 = ""; print substr($0, 2) }' | head -n 3
        echo scenes/degenerate-geometry.scn
    } >"$tmp/renders"
    while read -r scene options; do
        what="$part $scene $options" expected=0
        # shellcheck disable=SC2086 # options are words by design
        memcheck "$raytra" -q -j 2 --scale 0.25 $options "$top/$scene" "$tmp/out.png"
    done <"$tmp/renders"
done

# The error paths, with the last part.
bad=$top/tests/bad-input
for case in radius-negative.scn mesh-missing.scn mesh-index-zero.scn binary-garbage.scn \
    two-cameras.scn; do
    what="$part: bad input $case" expected=1
    memcheck "$raytra" -q "$bad/$case" "$tmp/out.png"
done
what="$part: output in a missing folder" expected=1
memcheck "$raytra" -q "$top/scenes/demo.scn" "$tmp/no-such-folder/out.png"
what="$part: unknown output format" expected=2
memcheck "$raytra" -q "$top/scenes/demo.scn" "$tmp/out.jpg"
what="$part: --check" expected=0
memcheck "$raytra" --check "$top/scenes/demo.scn"

# Every input the fuzzers kept: thousands of small error paths, in two runs.
for harness in scene obj exr; do
    driver=$top/tests/fuzz/build/regress-$harness
    [ -x "$driver" ] || continue
    what="fuzzing regressions and corpus of the $harness reader" expected=0
    memcheck "$driver" "$top/tests/fuzz/regressions/$harness" "$top/tests/fuzz/corpus-$harness"
done

echo "valgrind: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
