#!/bin/sh
# unit-test.sh: CodeGrade's Unit Test step for a raytra part: grades the student's folder, writes the JUnit XML CodeGrade reads.
#
# Usage: unit-test.sh [--all] [--weights attribute|repeat] PART   (the step's command, run in
#        the student's folder, as AutoTest runs it)
#   PART    the part: 1.3 or 1.3-shadows-mirror
#   RAYTRA  raytra's folder, built (grader/grade builds what is missing); default the folder
#           two above this script's
#   CG_JUNIT_XML_LOCATION  where the XML goes: AutoTest sets it for a Unit Test step
#   --all, --weights  as codegrade-junit.sh takes them
#
# Runs `grader/grade --self --gradescope` on the current folder, with its output folder in a
# temporary one (its verdicts, on stdout, are the step's output), then codegrade-junit.sh
# on its results. Exits 0 when the XML is written, whatever the verdicts (CodeGrade scores
# the step by the XML); 2 when no grading could be done.
case ${1:-} in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
set -u
here=$(cd "$(dirname "$0")" && pwd) || exit 2
raytra=${RAYTRA:-$(cd "$here/../.." && pwd)}
options=""
while [ $# -gt 1 ]; do
    case $1 in
    --all) options="$options --all" ;;
    --weights) [ $# -gt 2 ] || break; options="$options --weights $2"; shift ;;
    *) break ;;
    esac
    shift
done
[ $# -eq 1 ] || { echo "usage: $0 [--all] [--weights attribute|repeat] PART" >&2; exit 2; }
[ -n "${CG_JUNIT_XML_LOCATION:-}" ] ||
    { echo "unit-test.sh: CG_JUNIT_XML_LOCATION is not set (AutoTest's Unit Test step sets it)" >&2; exit 2; }
tmp=$(mktemp -d) || exit 2
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

status=0
"$raytra/grader/grade" --self --quiet --out "$tmp/grading" --gradescope "$tmp/results.json" \
    "$1" . || status=$?
[ "$status" -le 1 ] && [ -s "$tmp/results.json" ] ||
    { echo "unit-test.sh: grade could not grade the folder (exit status $status)" >&2; exit 2; }
# shellcheck disable=SC2086 # options is words by design
sh "$here/codegrade-junit.sh" $options --output "$CG_JUNIT_XML_LOCATION" "$tmp/results.json"
