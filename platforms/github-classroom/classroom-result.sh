#!/bin/sh
# classroom-result.sh: converts grade's results.json into the result GitHub Classroom's autograding reporter reads.
#
# Usage: platforms/github-classroom/classroom-result.sh [--all] [--base64 | --github-output FILE] RESULTS
#   RESULTS   the results.json of `grader/grade --self --gradescope RESULTS PART FOLDER`
#   --all     a test for every scene; by default the scenes grading.conf does not show at
#             once (after_due_date, after_published, hidden) are one test, "Scenes not
#             shown", with their points, naming none of them
#   --base64  print the result base64-encoded, as a step's output gives it to the reporter
#   --github-output FILE  append `result=BASE64` to FILE (a step's $GITHUB_OUTPUT), the
#             line the reporter's env entry reads as steps.ID.outputs.result
#
# Prints the result of one runner as classroom-resources/autograding-command-grader makes it
# and classroom-resources/autograding-grading-reporter reads it (the reporter decodes the
# base64 of the variable RUNNER_RESULTS, RUNNER the step's id in capitals):
#   {"version": 1, "status": "pass" or "fail", "max_score": the part's points,
#    "tests": [{"name", "status": "pass" or "fail", "score", "message", "test_code",
#               "filename": "", "line_no": 0, "duration": milliseconds}]}
# a test a scene, worth its points (grading.conf's, scaled to the part's): the reporter
# records the sum of the tests' scores out of max_score. "message" is the scene's verdict,
# figures and what to do; "test_code" the command line that renders it. Needs jq.
# platforms/github-classroom/classroom.yml is a workflow that runs it; grader/docs/platforms.md
# tells the rest.
case ${1:-} in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
set -u
here=$(cd "$(dirname "$0")" && pwd) || exit 2
all=false encode=false output=""
while [ $# -gt 1 ]; do
    case $1 in
    --all) all=true ;;
    --base64) encode=true ;;
    --github-output) [ $# -gt 2 ] || break; output=$2; encode=true; shift ;;
    *) break ;;
    esac
    shift
done
[ $# -eq 1 ] || { echo "usage: $0 [--all] [--base64 | --github-output FILE] RESULTS" >&2; exit 2; }
command -v jq >/dev/null 2>&1 || { echo "classroom-result.sh: jq is not installed" >&2; exit 2; }
[ -f "$1" ] || { echo "classroom-result.sh: no file $1" >&2; exit 2; }

result=$(jq -rc -L "$here/.." --argjson all "$all" --argjson encode "$encode" '
    include "scenes";
    (raytra_scenes | raytra_fold($all)) as $scenes |
    {
        version: 1,
        status: (if ($scenes | length) > 0 and ($scenes | all(.pass)) then "pass" else "fail" end),
        max_score: ($scenes | map(.max) | add // 0 | raytra_points),
        tests: (if ($scenes | length) == 0 then
                [{name: "raytra grade", status: "fail", score: 0,
                  message: (.output // "The grader graded no scene."), test_code: "",
                  filename: "", line_no: 0, duration: 0}]
            else $scenes | map({
                name: .name,
                status: (if .pass then "pass" else "fail" end),
                score: (.score | raytra_points),
                message: .output,
                test_code: (.output | capture("Command \\(from the top of the folder\\): (?<c>[^\n]*)").c // ""),
                filename: "",
                line_no: 0,
                duration: (.seconds * 1000 | round)
            }) end)
    } | if $encode then tojson | @base64 else . end' "$1") || exit 1
if [ -n "$output" ]; then
    printf 'result=%s\n' "$result" >>"$output" || exit 1
else
    printf '%s\n' "$result"
fi
