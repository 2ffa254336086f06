#!/bin/sh
# formats.sh: tests the converters of platforms/ on a tiny class: each output valid in its platform's format.
#
# Usage: platforms/tests/formats.sh GRADE   (make check-platforms; needs jq, zip, unzip,
#        xmllint (libxml2-utils) and a python3 with jsonschema (python3-jsonschema), which
#        common/deps.sh platforms-test installs)
#   GRADE  the grader, grader/build/grade, with imgdiff beside it
#
# Made here in a temporary folder, four submissions of part 1.1 are graded by `GRADE --self
# --gradescope`: images with one missing and one no image, under a grading.conf of points
# and visibilities (a part's total, a scene after the due date, a hidden one); the
# references as they are; a program that prints bytes neither JSON nor XML may hold as they
# are (control characters, invalid UTF-8, quotes, "]]>") and fails or crashes, a scene of 0
# points; and a folder whose make fails. Each results.json goes through every converter
# (GitHub Classroom's, PrairieLearn's, CodeGrade's, with --all and each --weights), and each
# output is checked: the JSON against the platform's schema written here from its published
# format (platforms/*/*.schema.json, with python3's jsonschema, Draft 7) and field by field
# with jq, and the XML against platforms/codegrade/junit.xsd with xmllint, with XPath for
# the counts cg_junit checks; then the scores each platform computes from them (the
# reporter's sum of scores, PrairieLearn's score, CodeGrade's weighted fraction of cases
# that pass) against grade's own, and that no scene not shown at once is named without
# --all. Then PrairieLearn's run.sh with a stand-in for run_autograder (a zip handed in,
# loose files, no autograder, no results), CodeGrade's unit-test.sh in a student's folder,
# and the sample configurations: the workflow's step ids and job name as the reporter
# needs them, info.json's externalGradingOptions and the image's paths.
case ${1:-} in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
set -u
[ $# -eq 1 ] || { echo "usage: $0 GRADE" >&2; exit 2; }
case $1 in /*) grade=$1 ;; *) grade=$(pwd)/$1 ;; esac
top=$(cd "$(dirname "$0")/../.." && pwd) || exit 2
platforms=$top/platforms
for tool in jq zip unzip xmllint; do
    command -v $tool >/dev/null 2>&1 ||
        { echo "formats.sh: $tool is missing (common/deps.sh platforms-test)" >&2; exit 2; }
done
python=""
for candidate in /usr/bin/python3 python3; do
    if "$candidate" -c 'import jsonschema' 2>/dev/null; then
        python=$candidate
        break
    fi
done
refs=$top/milestones/1.1-spheres-red/references
tmp=$(mktemp -d) || exit 2
trap '[ -n "${KEEP:-}" ] || rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
cd "$tmp" || exit 2
began=$(date +%s)

. "$top/tests/checks.sh"
classroom=$platforms/github-classroom/classroom-result.sh
prairielearn=$platforms/prairielearn/prairielearn-result.sh
codegrade=$platforms/codegrade/codegrade-junit.sh
# Schema and document pairs, validated together at the end (one python3).
pairs=""

# Tells whether jq (its arguments, a filter and a file) gives true.
holds() {
    jq -e "$@" >/dev/null
}
# Writes into file $1 what converter $3 (its arguments after it) prints, to be validated
# against JSON schema $2; false (a failed check) when the converter fails.
convert() {
    out=$1 schema=$2
    shift 2
    if sh "$@" >"$out"; then
        pairs="$pairs $schema $out"
    else
        fail "$(basename "$1") failed on $*"
        return 1
    fi
}
# Prints what XPath expression $1 gives in XML file $2.
xpath() {
    xmllint --xpath "$1" "$2" 2>/dev/null
}

# The submissions: a folder each, in class/.
mkdir -p class/images class/correct class/nasty class/unbuilt
cp "$refs"/*.png class/images/ && rm class/images/demo.png
echo "not an image" >class/images/spheres-three.png
cp "$refs"/*.png class/correct/
cat >class/nasty/raytra.sh <<'EOF'
#!/bin/sh
printf 'out\001\033[31m\377 "q" ]]> <b>&amp;\n'
case $1 in *demo*) kill -SEGV $$ ;; esac
exit 3
EOF
printf 'raytra: raytra.sh\n\tcp raytra.sh raytra\n\tchmod +x raytra\n' >class/nasty/Makefile
printf 'raytra:\n\techo "error: \\001 no raytra here" >&2; exit 1\n' >class/unbuilt/Makefile
cat >images.conf <<'EOF'
part 10
*                     1
demo                  3
spheres-grid-wide     2    after_due_date
camera-straight-down  1    hidden
EOF
printf '*  1\ndemo  0\n' >nasty.conf
for sub in images correct nasty unbuilt; do
    conf=""
    [ -f $sub.conf ] && conf="--grading-conf $sub.conf"
    # shellcheck disable=SC2086 # conf is words by design
    "$grade" -q --self --time-limit 10 $conf --out "out-$sub" --gradescope $sub.json 1.1 \
        class/$sub >$sub.log 2>&1
    status=$?
    check "grade --self on $sub ended with $status, not 0 or 1: $(tail -n 3 $sub.log)" \
        test $status -le 1
    check "grade wrote no results.json for $sub" test -s $sub.json
done

# Every converter on every results.json.
for sub in images correct nasty unbuilt; do
    # grade's score and the part's points.
    # shellcheck disable=SC2046 # two numbers, split by design
    set -- $(jq -r '"\(.score) \([.tests[] | .max_score // empty] | add)"' "$sub.json")
    score=$1 max=$2
    # --all and the encodings where they change something: the images' hidden scenes.
    alls=""
    [ $sub = images ] && alls=--all

    # GitHub Classroom: the reporter sums the tests' scores out of max_score.
    for all in "" $alls; do
        out=gh-$sub${all:+-all}.json
        # shellcheck disable=SC2086 # all is no word or one
        convert "$out" "$platforms/github-classroom/result.schema.json" "$classroom" $all \
            "$sub.json" || continue
        # shellcheck disable=SC2016 # jq's variables
        check "$out lacks a field, has one of another type, or its scores do not sum to \
$score of $max" holds --argjson score "$score" --argjson max "$max" '
            .version == 1 and (.status | IN("pass", "fail")) and (.max_score | type == "number")
            and (.tests | length > 0) and all(.tests[];
                (.name | type == "string") and (.status | IN("pass", "fail", "error"))
                and (.score | type == "number") and (.message | type == "string")
                and (.test_code | type == "string") and (.filename | type == "string")
                and (.line_no | type == "number") and (.duration | type == "number"))
            and ([.tests[].score] | add - $score | fabs < 0.001)
            and (.max_score - $max | fabs < 0.001)' "$out"
    done
    if [ $sub = images ]; then
        : >gh-output
        sh "$classroom" --github-output gh-output $sub.json
        sh "$classroom" --base64 $sub.json >gh-base64
        check "--github-output did not append result=BASE64, or --base64 does not decode to the result" \
            test "$(sed -n 's/^result=//p' gh-output | base64 -d)" = "$(base64 -d gh-base64)" -a \
            "$(base64 -d gh-base64)" = "$(cat gh-$sub.json)"
    fi

    # PrairieLearn: score is the points over the part's.
    for all in "" $alls; do
        out=pl-$sub${all:+-all}.json
        # shellcheck disable=SC2086 # all is no word or one
        convert "$out" "$platforms/prairielearn/results.schema.json" "$prairielearn" $all \
            "$sub.json" || continue
        check "$out is 1 MB or more, PrairieLearn's limit" test "$(wc -c <"$out")" -lt 1000000
        if [ $sub = unbuilt ]; then
            check "$out: a build that failed is not gradable false, with make's output" holds '
                .gradable == false and (.format_errors | length > 0)
                and (.format_errors | join("\n") | test("no raytra here"))' "$out"
            continue
        fi
        # shellcheck disable=SC2016 # jq's variables
        check "$out lacks a field, has one of another type, or its score is not $score of $max" \
            holds --argjson score "$score" --argjson max "$max" '
            .gradable == true and (.score | type == "number") and .score >= 0 and .score <= 1
            and (.message | type == "string") and (.output | type == "string")
            and all(.tests[]; (.name | type == "string") and (.description | type == "string")
                and (.points | type == "number") and (.max_points | type == "number")
                and .points <= .max_points and (.message | type == "string")
                and (.output | type == "string"))
            and (.score - $score / $max | fabs < 0.001)
            and ([.tests[].points] | add - $score | fabs < 0.001)' "$out"
    done

    # CodeGrade: the counts cg_junit checks, and the weighted fraction of the cases that pass.
    variants=attribute
    case $sub in images) variants="attribute repeat attribute-all" ;; nasty) variants="attribute repeat" ;; esac
    for variant in $variants; do
        out=cg-$sub-$variant.xml
        case $variant in
        attribute-all) options="--all --weights attribute" ;;
        *) options="--weights $variant" ;;
        esac
        # shellcheck disable=SC2086 # options is words by design
        if ! sh "$codegrade" $options --output $out $sub.json; then
            fail "codegrade-junit.sh $options $sub.json failed"
            continue
        fi
        xmllint --noout --schema "$platforms/codegrade/junit.xsd" "$out" >valid.log 2>&1
        check "$out is not valid against platforms/codegrade/junit.xsd: $(head -n 3 valid.log)" \
            test "$(cat valid.log)" = "$out validates"
        # Suites whose counts are not their cases'; the totals less the suites'; the fraction.
        # shellcheck disable=SC2046 # four values, split by design
        set -- $(xpath "concat(count(//testsuite[@tests != count(testcase)
            or @failures != count(testcase/failure) or @errors != count(testcase/error)
            or @skipped != count(testcase/skipped)]), ' ',
            /testsuites/@tests - sum(//testsuite/@tests), /testsuites/@failures
            - sum(//testsuite/@failures), /testsuites/@errors - sum(//testsuite/@errors), ' ',
            $(if [ "$variant" = repeat ]; then echo 'count(//testcase[not(*)])'; else
                echo 'sum(//testcase[not(*)]/@weight)'; fi), ' ',
            $(if [ "$variant" = repeat ]; then echo 'count(//testcase[not(skipped)])'; else
                echo 'sum(//testcase[not(skipped)]/@weight)'; fi))" "$out")
        check "$out: a testsuite's counts are not those of its cases" test "${1:-x}" = 0
        check "$out: the testsuites' counts are not the sum of their suites'" test "${2:-x}" = 000
        check "$out: CodeGrade's fraction is ${3:-?} of ${4:-?}, not $score of $max" awk \
            -v a="${3:-0}" -v b="${4:-0}" -v s="$score" -v m="$max" \
            'BEGIN { d = (b > 0 ? a / b : 0) - (m > 0 ? s / m : 0); exit !(d < 0.001 && d > -0.001) }'
    done
done

# What each case holds.
check "images: GitHub Classroom's tests are not the 5 scenes shown and Scenes not shown" test \
    "$(jq -c '[.tests[] | [.name, .status, .score]]' gh-images.json)" = \
    '[["spheres-three","fail",0],["spheres-behind-camera","pass",1],["camera-straight-up","pass",1],["camera-inside-sphere","pass",1],["demo","fail",0],["Scenes not shown","pass",3]]'
check "images: a failing test gives no command line as its test_code" test \
    "$(jq -r '.tests[4].test_code' gh-images.json)" = "./raytra scenes/demo.scn demo.png"
for out in gh-images.json pl-images.json cg-images-attribute.xml cg-images-repeat.xml; do
    check "$out names a scene not shown at once" \
        test "$(grep -c -e camera-straight-down -e spheres-grid-wide $out)" = 0
done
for out in gh-images-all.json pl-images-all.json cg-images-attribute-all.xml; do
    check "$out (--all) does not name every scene" \
        test "$(grep -o -e camera-straight-down -e spheres-grid-wide $out | sort -u | wc -l)" = 2
done
check "images: PrairieLearn's message is not the part's summary" test \
    "$(jq -r .message pl-images.json)" = "Part 1.1-spheres-red: 5 of 7 scenes pass: 6 of 10 points."
check "images: CodeGrade's weights are not the points" test \
    "$(xpath 'concat(//testcase[@name="demo"]/@weight, " ", //testcase[@name="Scenes not shown: passed"]/@weight)' cg-images-attribute.xml)" = "3 3"
check "images: --weights repeat did not make demo 3 cases of 1 point" test \
    "$(xpath 'count(//testcase[starts-with(@name, "demo (")])' cg-images-repeat.xml)" = 3
check "images: the failures are not typed UNREADABLE and MISSING" test \
    "$(xpath 'concat(//testcase[@name="spheres-three"]/failure/@type, " ", //testcase[@name="demo"]/failure/@type)' cg-images-attribute.xml)" = \
    "UNREADABLE MISSING"
check "nasty: the crash is not an <error> typed CRASHED" test \
    "$(xpath 'count(//testcase[@name="demo"]/error[@type="CRASHED"])' cg-nasty-attribute.xml)" = 1
check "nasty: a scene of 0 points is not one <skipped> case with --weights repeat" test \
    "$(xpath 'count(//testcase[@name="demo"]/skipped)' cg-nasty-repeat.xml)" = 1
check "nasty: the program's bytes are not in CodeGrade's XML, what XML cannot hold dropped" \
    grep -q "out\\[31m$(printf '\357\277\275') &quot;q&quot; \\]\\]&gt; &lt;b&gt;&amp;amp;" cg-nasty-attribute.xml
check "unbuilt: CodeGrade's cases are not 7 errors typed BUILD FAILED" test \
    "$(xpath 'count(//error[@type="BUILD FAILED"])' cg-unbuilt-attribute.xml)" = 7
check "correct: GitHub Classroom's status is not pass" test "$(jq -r .status gh-correct.json)" = pass
check "correct: PrairieLearn's score is not 1" test "$(jq .score pl-correct.json)" = 1

# PrairieLearn's run.sh, with a stand-in for run_autograder that records what it was given.
mkdir -p ag/source pl/student
cat >ag/source/run_autograder <<'EOF'
#!/bin/sh
(cd "$AUTOGRADER_ROOT/submission" && find . -type f | sort) >"$AUTOGRADER_ROOT/seen"
mkdir -p "$AUTOGRADER_ROOT/results" && cp "$STUB_RESULTS" "$AUTOGRADER_ROOT/results/results.json"
EOF
chmod +x ag/source/run_autograder
mkdir -p work/mine && echo 'raytra:' >work/mine/Makefile && echo 'int x;' >work/mine/a.c
(cd work && zip -q -r ../pl/student/submission.zip mine)
# Runs run.sh with the stand-in writing results $1; prints nothing.
run_pl() {
    rm -f pl/results/results.json ag/seen
    PL_GRADE_ROOT=$tmp/pl AUTOGRADER_ROOT=$tmp/ag STUB_RESULTS=$1 \
        sh "$platforms/prairielearn/run.sh" >pl.log 2>&1
    status=$?
    check "run.sh exited $status, not 0: $(tail -n 2 pl.log)" test $status = 0
}
run_pl "$tmp/images.json"
check "run.sh did not unpack the zip handed in: $(cat ag/seen 2>/dev/null)" \
    test "$(cat ag/seen 2>/dev/null)" = "$(printf './mine/Makefile\n./mine/a.c')"
check "run.sh's results.json is not prairielearn-result.sh's" \
    test "$(jq -c . pl/results/results.json)" = "$(jq -c . pl-images.json)"
cp pl/results/results.json pl-run-zip.json
pairs="$pairs $platforms/prairielearn/results.schema.json pl-run-zip.json"
rm pl/student/submission.zip && cp work/mine/* pl/student/
run_pl "$tmp/unbuilt.json"
check "run.sh did not copy the files handed in: $(cat ag/seen 2>/dev/null)" \
    test "$(cat ag/seen 2>/dev/null)" = "$(printf './Makefile\n./a.c')"
run_pl "$tmp/nothing.json"
check "run.sh, when the autograder writes nothing, is not gradable false" \
    holds '.gradable == false and (.message | test("cannot be read"))' pl/results/results.json
cp pl/results/results.json pl-run-none.json
pairs="$pairs $platforms/prairielearn/results.schema.json pl-run-none.json"
rm ag/source/run_autograder
run_pl "$tmp/images.json"
check "run.sh, with no autograder, is not gradable false" \
    holds '.gradable == false and (.message | test("no autograder"))' pl/results/results.json

# CodeGrade's unit-test.sh in a student's folder, as AutoTest runs a Unit Test step.
cp -R class/images student
(cd student && CG_JUNIT_XML_LOCATION=$tmp/step.xml RAYTRA=$top \
    sh "$platforms/codegrade/unit-test.sh" --weights attribute 1.1 >../step.log 2>&1)
status=$?
check "unit-test.sh exited $status: $(tail -n 3 step.log)" test $status = 0
xmllint --noout --schema "$platforms/codegrade/junit.xsd" step.xml >valid.log 2>&1
check "unit-test.sh wrote no valid XML where CG_JUNIT_XML_LOCATION says: $(head -n 3 valid.log)" \
    test "$(cat valid.log)" = "step.xml validates"
check "unit-test.sh's cases are not 5 passes of 7" test \
    "$(xpath 'concat(count(//testcase[not(*)]), " of ", count(//testcase))' step.xml)" = "5 of 7"
(cd student && env -u CG_JUNIT_XML_LOCATION sh "$platforms/codegrade/unit-test.sh" 1.1 \
    >/dev/null 2>&1)
status=$?
check "unit-test.sh without CG_JUNIT_XML_LOCATION exited $status, not 2" test $status = 2

# The sample configurations.
workflow=$platforms/github-classroom/classroom.yml
check "classroom.yml has no job run-autograding-tests, the check run the reporter looks for" \
    grep -q '^  run-autograding-tests:$' "$workflow"
# shellcheck disable=SC2016 # the workflow's expression, as it stands
check "classroom.yml's reporter does not read the step raytra's result as RAYTRA_RESULTS" \
    grep -q '^          RAYTRA_RESULTS: "${{ steps.raytra.outputs.result }}"$' "$workflow"
check "classroom.yml's grading step is not id raytra, or the reporter's runners not raytra" \
    test "$(grep -c -e '^        id: raytra$' -e '^          runners: raytra$' "$workflow")" = 2
check "classroom.yml does not run classroom-result.sh and the reporter" test "$(grep -c \
    -e 'platforms/github-classroom/classroom-result.sh' \
    -e 'uses: classroom-resources/autograding-grading-reporter@v1' "$workflow")" = 2
if "${python:-false}" -c 'import yaml' 2>/dev/null; then
    check "classroom.yml is not YAML with jobs.run-autograding-tests.steps" "$python" -c '
import sys, yaml
steps = yaml.safe_load(open(sys.argv[1]))["jobs"]["run-autograding-tests"]["steps"]
sys.exit(0 if [s.get("id") for s in steps].count("raytra") == 1 else 1)' "$workflow"
fi
info=$platforms/prairielearn/question/info.json
check "info.json lacks what an externally graded question needs" holds '
    (.uuid | test("^[0-9a-f]{8}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{12}$"))
    and .type == "v3" and .gradingMethod == "External" and (.title | type == "string")
    and (.topic | type == "string") and .externalGradingOptions.enabled == true
    and (.externalGradingOptions.image | type == "string")
    and .externalGradingOptions.entrypoint == "/opt/raytra/platforms/prairielearn/run.sh"
    and .externalGradingOptions.timeout <= 600
    and (.externalGradingOptions.environment.AUTOGRADER_TIME_BUDGET | tonumber)
        < .externalGradingOptions.timeout' "$info"
check "the Dockerfile does not put run.sh, its converter and scenes.jq in /opt/raytra" test \
    "$(grep -c -e '^COPY platforms/scenes.jq /opt/raytra/platforms/scenes.jq$' \
        -e '^COPY platforms/prairielearn/run.sh platforms/prairielearn/prairielearn-result.sh /opt/raytra/platforms/prairielearn/$' \
        "$platforms/prairielearn/Dockerfile")" = 2
check "question.html does not upload submission.zip and show the grader's results" test \
    "$(grep -c -e '<pl-file-upload file-names="submission.zip">' \
        -e '<pl-external-grader-results>' "$platforms/prairielearn/question/question.html")" = 2

# The JSON schemas, with one python3.
if [ -n "$python" ]; then
    # shellcheck disable=SC2086 # pairs is words by design
    "$python" - $pairs >schemas.log 2>&1 <<'EOF'
import json, sys
import jsonschema
args = sys.argv[1:]
for schema_path, document in zip(args[0::2], args[1::2]):
    with open(schema_path) as f:
        schema = json.load(f)
    jsonschema.Draft7Validator.check_schema(schema)
    with open(document) as f:
        errors = list(jsonschema.Draft7Validator(schema).iter_errors(json.load(f)))
    print("ok" if not errors else "FAIL: %s is not valid against %s: %s (at %s)" % (
        document, schema_path.split("/platforms/")[-1], errors[0].message, list(errors[0].path)))
EOF
    # shellcheck disable=SC2086
    set -- $pairs
    checks=$((checks + $# / 2))
    check "python3's jsonschema did not check every document: $(tail -n 3 schemas.log)" \
        test "$(grep -c -e '^ok$' -e '^FAIL: ' schemas.log)" = $(($# / 2))
    checks=$((checks - 1))
    grep '^FAIL: ' schemas.log
    failures=$((failures + $(grep -c '^FAIL: ' schemas.log)))
    echo "formats.sh: $(($# / 2)) JSON documents validated with $python's jsonschema" \
        "$("$python" -c 'from importlib.metadata import version; print(version("jsonschema"))')"
else
    echo "formats.sh: no python3 with jsonschema (Debian: python3-jsonschema): the JSON" \
        "schemas are skipped; jq checked every field"
fi

if [ "$failures" -eq 0 ]; then
    echo "formats.sh: all $checks checks passed ($(($(date +%s) - began)) s)"
else
    echo "formats.sh: $failures of $checks checks failed (KEEP the folder: run with sh -x)"
    exit 1
fi
