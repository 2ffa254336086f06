#!/bin/sh
# run.sh: PrairieLearn's external grading of a raytra part: Gradescope's autograder run on the student's files.
#
# Usage: run.sh   (a question's externalGradingOptions.entrypoint, in the image Dockerfile builds)
#   PL_GRADE_ROOT    the grading job's folder, default /grade: the student's files in student/,
#                    the results written to results/results.json
#   AUTOGRADER_ROOT  the part's Gradescope autograder, default /autograder (source/ holds the
#                    unpacked zip of `make gradescope`, set up by its setup.sh)
#   AUTOGRADER_TIME_BUDGET and the other variables run_autograder takes (info.json's
#                    externalGradingOptions.environment)
#
# Writes first a results.json that says the grading did not finish (gradable false: no
# attempt counted), then lays the student's files in AUTOGRADER_ROOT/submission: the files
# of a zip when the student handed in one .zip alone (its folder, or the folder in it), else
# the files as they are; runs AUTOGRADER_ROOT/source/run_autograder, which grades them as on
# Gradescope (the student's build and program as a user of their own, in the sandbox, under
# the time budget) and always writes its results.json; and converts that with
# prairielearn-result.sh into PrairieLearn's. Exits 0 whenever a results.json was written.
case ${1:-} in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
set -u
here=$(cd "$(dirname "$0")" && pwd) || exit 1
grade=${PL_GRADE_ROOT:-/grade}
root=${AUTOGRADER_ROOT:-/autograder}
export AUTOGRADER_ROOT="$root"
results=$grade/results
mkdir -p "$results" || exit 1

# Writes PrairieLearn's results.json saying that the grading failed, for the reason $1.
give_up() {
    jq -n --arg why "$1" '{gradable: false, format_errors: [$why], message: $why, tests: []}' \
        >"$results/results.json.tmp" && mv -f "$results/results.json.tmp" "$results/results.json"
    echo "run.sh: $1"
}
give_up "The grading did not finish (the grading job's timeout?): ask your instructor."
[ -x "$root/source/run_autograder" ] || {
    give_up "The grader's image has no autograder in $root/source: ask your instructor."
    exit 0
}

# The submission: one zip's files, or the files handed in.
sub=$root/submission
rm -rf "$sub" "$root/results" && mkdir -p "$sub" || { give_up "No submission folder: ask your instructor."; exit 0; }
set -- "$grade"/student/*
if [ $# -eq 1 ] && [ -f "$1" ] && case $1 in *.zip | *.ZIP) true ;; *) false ;; esac; then
    unzip -q -o "$1" -d "$sub" || {
        give_up "Your zip $(basename "$1") cannot be unpacked: make it again from your folder."
        exit 0
    }
elif [ -d "$grade/student" ]; then
    cp -R -P "$grade/student/." "$sub/" || { give_up "Your files cannot be copied: ask your instructor."; exit 0; }
fi

"$root/source/run_autograder"
if [ -s "$root/results/results.json" ] &&
    sh "$here/prairielearn-result.sh" "$root/results/results.json" >"$results/results.json.tmp"; then
    mv -f "$results/results.json.tmp" "$results/results.json"
else
    give_up "The autograder's results cannot be read: ask your instructor."
fi
exit 0
