#!/usr/bin/env bash
# beside.sh: runs two commands at once, the second's output as it comes and the first's after it.
#
# Usage: tests/beside.sh 'COMMAND A' 'COMMAND B'
#
# make test runs the grader's tests (A: make -C grader test) beside all the others (B):
# neither keeps two cores busy for long, so together they take little more than B alone.
# A's output is held in a file and printed whole when both are done, so that the two
# never mix. Exits 0 when both succeed; otherwise says which failed and exits with B's
# status, or A's. An interrupt (Ctrl-C) stops both.
#
# bash, not sh: A runs in a process group of its own (set -m), which dash cannot make
# without a terminal. A command put in the background without one ignores interrupts;
# a group is what the trap below can stop whole.
set -u
[ $# -eq 2 ] || { echo "usage: $0 'COMMAND A' 'COMMAND B'" >&2; exit 2; }
log=$(mktemp) || exit 2
set -m
sh -c "$1" </dev/null >"$log" 2>&1 &
a=$!
set +m
trap 'kill -TERM -- -"$a" 2>/dev/null; rm -f "$log"; exit 130' INT TERM
trap 'rm -f "$log"' EXIT

sh -c "$2"
status_b=$?
wait "$a"
status_a=$?
cat "$log"
[ $status_a -eq 0 ] || echo "beside.sh: FAILED (exit status $status_a): $1; its output is above"
[ $status_b -eq 0 ] || echo "beside.sh: FAILED (exit status $status_b): $2; its output is above $1's"
[ $status_b -ne 0 ] && exit $status_b
exit $status_a
