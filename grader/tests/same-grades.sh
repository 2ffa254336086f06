#!/bin/sh
# same-grades.sh: tells whether two gradings of a class came out the same apart from times.
#
# Usage: grader/tests/same-grades.sh OUT1 OUT2
#   OUT1, OUT2  output folders of grader/grade or grade merge (report.html, grades.csv)
#
# Times are what may differ: the CSV's seconds, the report's "graded" date and run times,
# and the durations and speeds a program prints ("in 0.01 s", "15.1 M rays/s"), each made
# T before the files are compared. Exit status 0 when the same, 1 (with a diff) when not,
# 2 when a file is missing.
set -u
[ $# -eq 2 ] || { echo "usage: $0 OUT1 OUT2" >&2; exit 2; }

# Prints file $1 with its times made T.
untimed() {
    case $1 in
    *.csv) sed -E 's/,[0-9]+\.[0-9]{3},(copy)?,([0-9.e+-]*)$/,T,\1,\2/' "$1" ;;
    *) sed -E 's/graded [0-9]{4}-[0-9]{2}-[0-9]{2} [0-9]{2}:[0-9]{2}/graded T/g
               s/[0-9]+(\.[0-9]+)? ([kMG] )?rays\/s/T rays\/s/g
               s/[0-9]+(\.[0-9]+)? m?s([^a-zA-Z0-9]|$)/T s\2/g' "$1" ;;
    esac
}

status=0
for file in grades.csv report.html; do
    for out in "$1" "$2"; do
        [ -f "$out/$file" ] || { echo "same-grades.sh: no $out/$file" >&2; exit 2; }
    done
    untimed "$1/$file" >"${TMPDIR:-/tmp}/same-grades.$$.1" &&
        untimed "$2/$file" >"${TMPDIR:-/tmp}/same-grades.$$.2" || exit 2
    if ! diff "${TMPDIR:-/tmp}/same-grades.$$.1" "${TMPDIR:-/tmp}/same-grades.$$.2" >"${TMPDIR:-/tmp}/same-grades.$$.d"; then
        echo "same-grades.sh: $1/$file and $2/$file differ:"
        head -n 20 "${TMPDIR:-/tmp}/same-grades.$$.d"
        status=1
    fi
    rm -f "${TMPDIR:-/tmp}/same-grades.$$".*
done
exit $status
