#!/bin/sh
# help.sh: every program and script a user runs answers --help with its usage, and exit status 0.
#
# Usage: tests/help.sh [BUILD]   (make check-help; BUILD: build or build-sanitize)
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build}
cd "$top" || exit 2
failures=0 count=0
parts=milestones/*/raytra
[ "$build" = build ] || parts="milestones/*/$build/raytra"
for tool in $parts compare/$build/imgdiff compare/$build/mcstats grader/grade \
            book/*.sh compare/*.sh common/deps.sh platforms/gradescope/* platforms/slurm/grade-slurm \
            platforms/github-classroom/*.sh platforms/prairielearn/*.sh platforms/codegrade/*.sh \
            book/mistakes/gallery.sh; do
    count=$((count + 1))
    case $tool in *.sh | */setup.sh | */run_autograder) run="sh $tool" ;; *) run=$tool ;; esac
    if ! out=$($run --help 2>&1 </dev/null); then
        echo "help: $tool --help exits non-zero"
        failures=$((failures + 1))
    elif ! printf '%s\n' "$out" | grep -qi '^ *usage'; then
        echo "help: $tool --help prints no usage line"
        failures=$((failures + 1))
    fi
done
[ $failures -eq 0 ] && echo "help: $count programs and scripts answer --help with their usage"
[ $failures -eq 0 ]
