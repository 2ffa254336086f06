#!/bin/sh
# progress.sh: tests the progress lines of calibrate.sh, with stand-ins for its programs.
#
# Usage: tests/mc-variants/progress.sh   (make check-statistics runs it first)
#
# calibrate.sh runs every right program of part 1.6 and judges its renders with mcjudge;
# here each is a script that writes nothing but the file named, and judges every render a
# pass, so that the lines calibrate.sh writes on stderr, "k of N renders (...), T elapsed,
# ETA T", are checked in a second: their form (the times are the clock's), k counted up to
# N, and no ETA after the last. Exit status 0 when every check passes.
set -u
top=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
. "$top/tests/checks.sh"

# The stand-ins: a program renders by touching its image (the 5th word: -q -j 2 SCENE
# IMAGE), a little slowly; mcjudge passes every image, in PFM.
mkdir "$tmp/variants" "$tmp/refs"
printf '#!/bin/sh\nsleep 0.1\n: >"$5"\n' >"$tmp/raytra"
printf '#!/bin/sh\nfor f; do case $f in *.pfm) echo "$f pfm PASS" ;; esac; done\n' \
    >"$tmp/variants/mcjudge"
# calibrate.sh's own list of programs: raytra's and its VARIANTS/raytra-NAME.
sed -n 's|^[a-z0-9-]* $variants/raytra-\([a-z0-9-]*\) .*|\1|p' "$top/tests/mc-variants/calibrate.sh" \
    >"$tmp/names"
for v in $(cat "$tmp/names"); do
    cp "$tmp/raytra" "$tmp/variants/raytra-$v"
done
n=$(($(wc -l <"$tmp/names") + 1)) last=$(tail -n 1 "$tmp/names")
chmod +x "$tmp/raytra" "$tmp/variants"/*
printf '~one.png scenes/one.scn\n~two.png scenes/two.scn\n' >"$tmp/refs/renders.txt"

MC_BATCH=2 sh "$top/tests/mc-variants/calibrate.sh" "$tmp/raytra" "$tmp/variants" "$tmp/refs" 3 \
    >"$tmp/stdout" 2>"$tmp/stderr"
check "calibrate.sh with stand-ins: exit 0" test $? -eq 0
span='[0-9]+ (s|min [0-9]+ s|h [0-9]+ min)'
# n programs, 2 scenes, 3 seeds: 6n renders, a line a program and batch (seeds 0-1, 2).
all=$((6 * n))
check "a line a program and batch, with an ETA but the last" \
    test "$(grep -Ec "^calibrate\.sh: [0-9]+ of $all renders \([a-z0-9-]+, seeds [0-9]+ to [0-9]+ of 3\), $span elapsed, ETA $span\$" "$tmp/stderr")" -eq $((2 * n - 1))
check "the last: every render done, no ETA" \
    grep -Eqx "calibrate\.sh: $all of $all renders \($last, seeds 2 to 2 of 3\), $span elapsed" "$tmp/stderr"
# k counted up: 4 a program in the first batch (2 seeds, 2 scenes), 2 in the second.
want=$(k=0; for b in 4 2; do for _ in $(seq "$n"); do k=$((k + b)); printf '%d ' "$k"; done; done)
check "k counted up: 4 a program in the first batch, 2 in the second" \
    test "$(sed -En "s/^calibrate\.sh: ([0-9]+) of $all renders.*/\1/p" "$tmp/stderr" | tr '\n' ' ')" = "$want"
check "the table counts every render" grep -q "^all: 0 of $((3 * n)) submissions fail" "$tmp/stdout"

if [ "$failures" -eq 0 ]; then
    echo "progress.sh: all $checks checks passed"
else
    echo "progress.sh: $failures of $checks checks failed"
    cat "$tmp/stderr"
    exit 1
fi
