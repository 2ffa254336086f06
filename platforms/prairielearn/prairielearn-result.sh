#!/bin/sh
# prairielearn-result.sh: converts grade's results.json into the results.json of PrairieLearn's external grader.
#
# Usage: platforms/prairielearn/prairielearn-result.sh [--all] RESULTS
#   RESULTS  the results.json of `grader/grade --self --gradescope RESULTS PART FOLDER`, or of
#            platforms/gradescope/run_autograder
#   --all    a test for every scene; by default the scenes grading.conf does not show at once
#            (after_due_date, after_published, hidden) are one test, "Scenes not shown",
#            with their points, naming none of them
#
# Prints, as PrairieLearn's external grading documentation gives it (the file a grading
# job writes to /grade/results/results.json):
#   {"gradable": true, "score": from 0 to 1, "message": "Part P: K of N scenes pass: X of Y points.",
#    "output": what went wrong before any scene, make's output, the limits,
#    "tests": [{"name", "description", "points", "max_points", "message", "output"}]}
# a test a scene, its points and max_points grading.conf's (scaled to the part's), score
# their sum over the part's points. "gradable" is false, with "format_errors", when the
# build failed (PrairieLearn then counts no attempt, as it does for code that does not
# compile) or no scene was graded (run_autograder's results of a grading that failed).
# Needs jq. platforms/prairielearn/run.sh runs it in the grader's image; grader/docs/platforms.md
# tells the rest.
case ${1:-} in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
set -u
here=$(cd "$(dirname "$0")" && pwd) || exit 2
all=false
[ "${1:-}" = --all ] && { all=true; shift; }
[ $# -eq 1 ] || { echo "usage: $0 [--all] RESULTS" >&2; exit 2; }
command -v jq >/dev/null 2>&1 || { echo "prairielearn-result.sh: jq is not installed" >&2; exit 2; }
[ -f "$1" ] || { echo "prairielearn-result.sh: no file $1" >&2; exit 2; }

jq -L "$here/.." --argjson all "$all" '
    include "scenes";
    raytra_scenes as $every |
    ($every | raytra_fold($all)) as $scenes |
    ($every | map(.max) | add // 0) as $max |
    raytra_details as $details |
    if ($every | length) == 0 then
        {gradable: false,
         format_errors: [.output // "The grader graded no scene."],
         message: "No scene was graded.", output: (.output // ""), tests: []}
    elif ($every | all(.verdict == "BUILD FAILED")) then
        {gradable: false,
         format_errors: ["The build failed: \($every[0].reason).", $details],
         message: raytra_summary, output: $details, tests: []}
    else
        {gradable: true,
         score: (if $max > 0 then ($every | map(.score) | add) / $max
                 elif ($every | all(.pass)) then 1 else 0 end
                 | if . > 1 then 1 elif . < 0 then 0 else . end),
         message: raytra_summary,
         output: $details,
         tests: ($scenes | map({
             name: .name,
             description: (if .file != "" then "The scene \(.file)" else "Scenes of your instructor'"'"'s, not shown here" end),
             points: (.score | raytra_points),
             max_points: (.max | raytra_points),
             message: "\(.verdict): \(.reason).",
             output: .output
         }))}
    end' "$1"
