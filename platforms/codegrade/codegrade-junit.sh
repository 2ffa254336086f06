#!/bin/sh
# codegrade-junit.sh: converts grade's results.json into JUnit XML for CodeGrade's Unit Test step, weights kept.
#
# Usage: platforms/codegrade/codegrade-junit.sh [--all] [--weights attribute|repeat] [--output FILE] RESULTS
#   RESULTS    the results.json of `grader/grade --self --gradescope RESULTS PART FOLDER`
#   --weights  how a scene's points (grading.conf's) reach CodeGrade, which scores a Unit Test
#              step by the fraction of its test cases that pass:
#              attribute  (the default) a test case a scene with a `weight` attribute, its
#                         points: CodeGrade's JUnit reader (cg_junit) counts each case by it
#              repeat     a scene as many test cases as its points are units ("demo (2 of
#                         3)"), for a reader that counts cases alone: the fraction of the
#                         cases that pass is then the fraction of the points
#   --all      a test case for every scene; by default the scenes grading.conf does not show
#              at once (after_due_date, after_published, hidden) are folded into at most two
#              cases, "Scenes not shown: passed" and "Scenes not shown: not passed", with
#              their points, naming none of them
#   --output FILE  write the XML to FILE (CodeGrade's $CG_JUNIT_XML_LOCATION); default stdout
#
# The XML: <testsuites> holding one <testsuite> named the part, a <testcase> a scene (name,
# classname "raytra", time the seconds its program ran, weight); a scene that did not pass
# has a <failure> (FAIL, WRONG SIZE, LINK, UNREADABLE, MISSING) or an <error> (ERROR,
# CRASHED, TIMEOUT, OUT OF MEMORY, BUILD FAILED) typed by its verdict, its reason as the
# message and its output (figures, what to do, command line) as text; a scene that passed
# has no child, which every version of cg_junit counts a success; with --weights repeat, a
# scene of 0 points is one <skipped> case, which counts for nothing. The counts of each
# element are the cases'. Bytes XML 1.0 cannot hold are dropped. Needs jq.
# grader/docs/platforms.md gives a sample configuration.
case ${1:-} in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
set -u
here=$(cd "$(dirname "$0")" && pwd) || exit 2
usage="usage: $0 [--all] [--weights attribute|repeat] [--output FILE] RESULTS"
all=false weights=attribute output=""
while [ $# -gt 1 ]; do
    case $1 in
    --all) all=true ;;
    --weights) [ $# -gt 2 ] || break; weights=$2; shift ;;
    --output) [ $# -gt 2 ] || break; output=$2; shift ;;
    *) break ;;
    esac
    shift
done
[ $# -eq 1 ] || { echo "$usage" >&2; exit 2; }
case $weights in attribute | repeat) ;; *) echo "$usage" >&2; exit 2 ;; esac
command -v jq >/dev/null 2>&1 || { echo "codegrade-junit.sh: jq is not installed" >&2; exit 2; }
[ -f "$1" ] || { echo "codegrade-junit.sh: no file $1" >&2; exit 2; }

xml=$(jq -r -L "$here/.." --argjson all "$all" --arg weights "$weights" '
    include "scenes";
    # Text as XML 1.0 character data or attribute value: what XML cannot hold dropped.
    def xml: explode | map(select(. == 9 or . == 10 or . == 13 or (. >= 32 and . < 55296)
        or (. > 57343 and . < 65534) or . > 65535)) | implode | @html;
    def fold($what): raytra_fold(false) | map(.name = "Scenes not shown: \($what)");
    # Each case: {name, pass, error, verdict, reason, output, seconds, weight, copies}.
    (raytra_scenes | if $all then . else
        map(select(.visible)) + (map(select((.visible | not) and .pass)) | fold("passed"))
        + (map(select((.visible or .pass) | not)) | fold("not passed")) end
     | map(. + {weight: (.max | raytra_points)})) as $scenes |
    # With repeat: the copies of each case, its weight in the smallest unit that keeps the
    # ratios of the weights (to 0.1%), found among 1 to 1000 times the least weight.
    ($scenes | map(select(.weight > 0) | .weight) | min) as $least |
    (if $weights == "attribute" or $least == null then 1 else
        first(range(1; 1001) as $k |
            select($scenes | all(.weight * $k / $least | (. - round) | fabs < 0.001)) | $k)
        // error("the points of the scenes have no common unit: use --weights attribute")
     end) as $k |
    ($scenes | map(.copies = (if $weights == "attribute" then 1
        else (.weight * $k / $least | round) end))) as $scenes |
    if $weights == "repeat" and ($scenes | map(.copies) | add) > 2000 then
        error("more than 2000 test cases: use --weights attribute") else . end |
    [$scenes[] | . as $s |
        if $weights == "attribute" then $s
        elif $s.copies == 0 then $s + {skipped: true}
        else range(1; $s.copies + 1) as $i |
            $s + {weight: 1, name: (if $s.copies > 1 then "\($s.name) (\($i) of \($s.copies))"
                else $s.name end)}
        end] as $cases |
    (if ($cases | length) == 0 then
        [{name: "raytra grade", pass: false, error: true, verdict: "NOT GRADED",
          reason: "the grader graded no scene", output: (.output // ""), seconds: 0, weight: 1}]
     else $cases end) as $cases |
    ($cases | map(select(.skipped | not))) as $counted |
    ($counted | map(select(.pass | not) | select(.error | not)) | length) as $failures |
    ($counted | map(select((.pass | not) and .error)) | length) as $errors |
    ($cases | map(select(.skipped)) | length) as $skipped |
    ($cases | map(.seconds) | add | . * 1000 | round / 1000) as $time |
    (raytra_part | if . == "" then "raytra" else . end) as $part |
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>",
    "<testsuites name=\"raytra grade \($part | xml)\" tests=\"\($cases | length)\" failures=\"\($failures)\" errors=\"\($errors)\" time=\"\($time)\">",
    "  <testsuite name=\"\($part | xml)\" tests=\"\($cases | length)\" failures=\"\($failures)\" errors=\"\($errors)\" skipped=\"\($skipped)\" time=\"\($time)\">",
    ($cases[] |
        "    <testcase name=\"\(.name | xml)\" classname=\"raytra\" time=\"\(.seconds)\""
        + (if $weights == "attribute" then " weight=\"\(.weight)\"" else "" end)
        + (if .skipped then ">\n      <skipped message=\"worth no points: \("\(.verdict): \(.reason)" | xml)\"/>\n    </testcase>"
           elif .pass then "/>"
           else ">\n      <\(if .error then "error" else "failure" end) type=\"\(.verdict | xml)\" message=\"\(.reason | xml)\">"
                + (.output | xml)
                + "</\(if .error then "error" else "failure" end)>\n    </testcase>"
           end)),
    "  </testsuite>",
    "</testsuites>"' "$1") || exit 1
if [ -n "$output" ]; then
    printf '%s\n' "$xml" >"$output.tmp" && mv -f "$output.tmp" "$output" || exit 1
else
    printf '%s\n' "$xml"
fi
