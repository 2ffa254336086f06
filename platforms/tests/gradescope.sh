#!/bin/sh
# gradescope.sh: tests part 1.3's Gradescope autograder, run as Gradescope runs it, field by field.
#
# Usage: platforms/tests/gradescope.sh [SUBMISSION...]   (make check-gradescope; needs zip, unzip
#        and jq, which common/deps.sh gradescope-test installs)
#   SUBMISSION  run only these of correct, buggy, empty, unbuilt, none, hostile, cut-short
#               (tests/debian11.sh runs correct and buggy); by default every one
#
# In a temporary folder: `make gradescope PART=1.3` writes the zip, which is checked (the
# scripts at its root, tracked files only, no part's model answer, no build output) and
# unpacked into ROOT/source; setup.sh --build-only builds the grader there (installing
# nothing when nothing is missing); then run_autograder runs with AUTOGRADER_ROOT=ROOT on
# seven submissions: part 1.3's starter with the solutions written back (correct), the
# same with a sign flipped in secondary_reflect (buggy: the three scenes with mirrors
# fail), an empty folder, a folder whose make fails, none at all, a program that prints
# bytes JSON cannot hold as they are and crashes (hostile), and the correct one built 6 s
# late, under a time budget of 5 s (cut short: late by its own sleep, whatever the speed
# of the machine). Each results.json is
# parsed with jq and checked as UTF-8 with iconv, then field by field. Run as root, the
# submissions run as a student's uid and the grader as a grader's, two numbers no user
# has (no user is made here), which is checked; otherwise as the current user, which the
# test says. The correct submission's grading time is printed. Then a second zip, with a
# grading.conf (a part's total, points and visibilities) and two hidden scenes of the
# test's own (GRADING_CONF=, its `hidden` line): the correct submission scores them all,
# each test with its points and visibility, and a program that copies the references its
# folder carries fails the hidden scenes; the summary speaks of the visible scenes alone,
# the total is hidden as Gradescope's specification says, no hidden scene's test names a
# scene file, and no test has an execution_time. Then a Makefile that prints a fake
# submission_metadata.json (a marker in it) and the hidden scenes, then fails: as root, the
# marker must be nowhere in results.json. Last, late work: a submission_metadata.json whose
# created_at is 2 days after the due date (the zip's grading.conf takes 10% a day), then
# the same with the student's extension, then after the student's late due date, then a
# metadata file that is no JSON.
set -u
top=$(cd "$(dirname "$0")/../.." && pwd) || exit 2
for tool in zip unzip jq iconv; do
    command -v $tool >/dev/null 2>&1 ||
        { echo "gradescope.sh: $tool is missing (common/deps.sh gradescope-test)" >&2; exit 2; }
done
tmp=$(mktemp -d) || exit 2
# The submissions' user (nobody, when run as root) must reach the autograder's folder.
chmod 755 "$tmp" || exit 2
trap '[ -n "${KEEP:-}" ] || rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
root=$tmp/root
part=1.3-shadows-mirror

. "$top/tests/checks.sh"
# Tells whether submission $1 is to be run.
want() {
    [ -z "$wanted" ] || case " $wanted " in *" $1 "*) true ;; *) false ;; esac
}
wanted=$*
# Prints what jq's filter $1 gives for the results of the last run, compact.
field() {
    jq -c "$1" "$root/results/results.json"
}

# The zip, and what it holds.
make --no-print-directory -s -C "$top" gradescope PART=1.3 OUT="$tmp/autograder.zip" \
    >"$tmp/pack.log" 2>&1 ||
    { echo "gradescope.sh: make gradescope failed:" >&2; cat "$tmp/pack.log" >&2; exit 1; }
unzip -Z1 "$tmp/autograder.zip" | grep -v '/$' | sort >"$tmp/zipped"
for file in setup.sh run_autograder gradescope.conf grader/grade.c common/deps.sh \
    milestones/$part/references/renders.txt milestones/$part/references/demo.png \
    milestones/1.4-bvh/accel_options.c scenes/demo.scn common/Makefile; do
    check "the zip has no $file" grep -qx "$file" "$tmp/zipped"
done
(cd "$top" && git ls-files) | sort >"$tmp/tracked"
untracked=$(grep -v -x -e setup.sh -e run_autograder -e gradescope.conf "$tmp/zipped" |
    comm -23 - "$tmp/tracked" | head -n 3)
check "the zip holds files git does not track: $untracked" test -z "$untracked"
answers=$(grep -E '^milestones/[^/]+/[^/]+\.c$' "$tmp/zipped" | grep -v '_options\.c$' | head -n 3)
check "the zip holds a part's model answer: $answers" test -z "$answers"
built=$(grep -E '(^|/)build/|\.o$|\.a$|(^|/)raytra$' "$tmp/zipped" | head -n 3)
check "the zip holds build outputs: $built" test -z "$built"

mkdir -p "$root/source" && unzip -q "$tmp/autograder.zip" -d "$root/source" || exit 2
check "run_autograder is not executable" test -x "$root/source/run_autograder"
check "gradescope.conf does not name the part" grep -qx "PART=$part" "$root/source/gradescope.conf"
if ! sh "$root/source/setup.sh" --build-only >"$tmp/setup.log" 2>&1; then
    echo "gradescope.sh: setup.sh --build-only failed:" >&2
    tail -n 20 "$tmp/setup.log" >&2
    exit 1
fi
if [ "$(id -u)" -eq 0 ]; then
    # Numbers of this run's own, so that a test running beside it has other users.
    student_uid=$((61000 + $$ % 1000 * 2))
    export AUTOGRADER_USER=$student_uid AUTOGRADER_GRADER_USER=$((student_uid + 1))
    echo "gradescope.sh: run as root: the submissions run as uid $student_uid, the grader as" \
        "uid $AUTOGRADER_GRADER_USER"
else
    echo "gradescope.sh: not root: the submissions run as $(id -un), the user running the test"
fi

# Runs the autograder on folder $1 (none: no submission folder) with the environment
# $2..., as Gradescope does: the submission in ROOT/submission, no results before.
autograde() {
    rm -rf "$root/submission" "$root/results"
    [ -n "$1" ] && cp -R "$1" "$root/submission"
    shift
    env AUTOGRADER_ROOT="$root" "$@" sh "$root/source/run_autograder" >"$tmp/run.log" 2>&1
    check "run_autograder's exit status is not 0 ($(tail -n 3 "$tmp/run.log"))" test $? -eq 0
    check "results.json is not JSON" jq -e . "$root/results/results.json" >/dev/null
    check "results.json is not UTF-8" iconv -f UTF-8 -t UTF-8 "$root/results/results.json" \
        -o /dev/null
}

# Checks the fields of a grading's results.json: the score $1, the scenes in the order of
# renders.txt, a point each, passed exactly when scored, visible; the tests that failed
# named in $2 (space-separated), each output starting with verdict $3.
check_results() {
    score=$1 failing=$2 verdict=$3
    check "the score is $(field .score), not $score" test "$(field .score)" = "$score"
    check "the score is not the sum of the tests' scores" \
        test "$(field '[.tests[].score] | add')" = "$score"
    expected=$(awk '$1 !~ /^[#!]/ && NF >= 2 {
        n = $1; sub(/\.[a-z]+$/, "", n); print n " (" $2 ")" }' \
        "$root/source/milestones/$part/references/renders.txt" | jq -R -s -c 'split("\n")[:-1]')
    check "the tests are $(field '[.tests[].name]'), not $expected" \
        test "$(field '[.tests[].name]')" = "$expected"
    check "a test's max_score is not 1, or its score not 0 or 1" \
        test "$(field '[.tests[] | select(.max_score != 1 or (.score != 0 and .score != 1))] |
        length')" = 0
    check "a test's status does not match its score" test "$(field '[.tests[] |
        select((.score == 1) != (.status == "passed") or
            (.status != "passed" and .status != "failed"))] |
        length')" = 0
    check "a test or the whole is not visible" \
        test "$(field '[.visibility, .tests[].visibility] | unique')" = '["visible"]'
    check "a test has no output" test "$(field '[.tests[].output | strings | select(length > 20)] |
        length')" = "$(field '.tests | length')"
    got=$(jq -r '[.tests[] | select(.status == "failed") | .name | sub(" .*"; "")] | join(" ")' \
        "$root/results/results.json")
    check "the failed tests are '$got', not '$failing'" test "$got" = "$failing"
    if [ -n "$verdict" ]; then
        check "a failed test's output does not start with $verdict" test "$(field "[.tests[] |
            select(.status == \"failed\") | .output | startswith(\"$verdict: \")] | all")" = true
    fi
    check "a passed test does not give the figures" test "$(field '[.tests[] |
        select(.status == "passed") | .output | test("^PASS: .*\nMax diff R, G, B: .*PSNR")] |
        all')" = true
}

correct=$tmp/correct buggy=$tmp/buggy hostile=$tmp/hostile
every="progression-1-diffuse progression-2-specular progression-3-ambient progression-4-mirror"
every="$every shadow-sphere acne-grazing acne-far mirrors-facing triangles-winding demo"
"$top/book/starter.sh" --solution 1.3 "$correct" >/dev/null || exit 2
cp -R "$correct" "$buggy"
sed -i 's/add_scaled(d, n, -2 \* vec3_dot(d, n))/add_scaled(d, n, 2 * vec3_dot(d, n))/' \
    "$buggy/milestones/$part/secondary.c"
check "the buggy copy has no flipped sign" \
    grep -q 'add_scaled(d, n, 2 \* vec3_dot' "$buggy/milestones/$part/secondary.c"
mkdir "$tmp/empty" "$hostile" "$tmp/unbuilt"
printf 'raytra:\n\t@echo "main.c:1: error: no main" >&2; false\n' >"$tmp/unbuilt/Makefile"
printf 'raytra: raytra.sh\n\tcp raytra.sh raytra\n\tchmod +x raytra\n' >"$hostile/Makefile"
cat >"$hostile/raytra.sh" <<'EOF'
#!/bin/sh
printf 'uid %s; bytes \001\033[31m\377 "q" \\ ]]>\n' "$(id -u)"
kill -SEGV $$
EOF

if want correct; then
echo "== correct: part 1.3's solution"
start=$(date +%s)
autograde "$correct"
seconds=$(($(date +%s) - start))
check_results 10 "" ""
check "the summary does not say 10 of 10" test "$(field '.output |
    startswith("Part 1.3-shadows-mirror: 10 of 10 scenes pass: 10 of 10 points.")')" = true
check "no execution_time at the top" test "$(field '.execution_time | numbers | . >= 0')" = true
check "a test has an execution_time, which Gradescope's specification does not have" \
    test "$(field '[.tests[] | has("execution_time")] | any')" = false
check "a test's output does not say how long the scene ran" test "$(field '[.tests[].output |
    test("\nRan in [0-9]+\\.[0-9]+ s\\.\n")] | all')" = true
check "a correct scene is not identical" test "$(field '[.tests[].output |
    startswith("PASS: identical to the reference.")] | all')" = true
budget=$(sed -n 's/^BUDGET=//p' "$root/source/gradescope.conf")
echo "gradescope.sh: the correct submission took $seconds s to grade (budget: $budget s)"
fi

if want buggy; then
echo "== buggy: a sign flipped in secondary_reflect"
autograde "$buggy"
check_results 7 "progression-4-mirror mirrors-facing demo" FAIL
check "a failure says no box, what to do or the command" test "$(field '[.tests[] |
    select(.status == "failed") | .output | test("in the box \\(\\d+,\\d+\\)-\\(\\d+,\\d+\\)") and
    test("\nWhat to do: .*out/check/[a-z0-9-]+\\.heat\\.png") and
    test("\nCommand \\(from the top of the folder\\): ./raytra scenes/[a-z0-9-]+\\.scn " +
        "[a-z0-9-]+\\.png\n")] | all')" = true
fi

if want empty; then
echo "== empty"
autograde "$tmp/empty"
check_results 0 "$every" MISSING
check "the summary does not say the folder has no Makefile" \
    test "$(field '.output | test("no Makefile at its top")')" = true
fi

if want unbuilt; then
echo "== unbuilt: make fails"
autograde "$tmp/unbuilt"
check_results 0 "$every" "BUILD FAILED"
check "the summary does not say that the build failed, with make's output" test "$(field '.output |
    test("The build failed: make failed ") and
    test("\nThe end of make.s output:\n(.*\n)*main.c:1: error: no main")')" = true
fi

if want none; then
echo "== no submission folder at all"
autograde ""
check "no folder: the score is not 0" test "$(field .score)" = 0
fi

if want hostile; then
echo "== hostile: prints control characters and invalid UTF-8, then crashes"
autograde "$hostile"
check_results 0 "$every" CRASHED
check "the bytes are not escaped as \\u0001, \\u001b and \\ufffd" \
    grep -q 'bytes \\u0001\\u001b\[31m\\ufffd \\"q\\" \\\\ ]]>' "$root/results/results.json"
check "a crash does not show the program's output" test "$(field '[.tests[].output |
    test("The program.s last output:\nuid [0-9]+; bytes ")] | all')" = true
if [ "$(id -u)" -eq 0 ]; then
    check "the program did not run as uid $student_uid" test "$(field '.tests[0].output |
        test("uid '"$student_uid"';")')" = true
fi
fi

if want cut-short; then
echo "== cut short: the correct one, built 6 s late, with a time budget of 5 s"
cp -R "$correct" "$tmp/late"
# make reads GNUmakefile before Makefile: this one sleeps, then builds as the course does.
# shellcheck disable=SC2016 # $(MAKE) is for make to expand
printf 'all:\n\tsleep 6\n\t$(MAKE) -f Makefile\n' >"$tmp/late/GNUmakefile"
autograde "$tmp/late" AUTOGRADER_TIME_BUDGET=5
check "cut short: the score is not 0" test "$(field .score)" = 0
check "cut short: the output does not say why" \
    test "$(field '.output | test("did not finish within 5 s")')" = true
check "cut short: tests were given" test "$(field '.tests')" = '[]'
if [ "$(id -u)" -eq 0 ]; then
    check "cut short: a process of uid $student_uid (the build's sleep) outlived the grading" \
        sh -c '! grep -qs "^Uid:[[:space:]]*$1[[:space:]]" /proc/[0-9]*/status' sh "$student_uid"
fi
fi

# The instructor's controls: a zip with a grading.conf (points, visibilities, the part's
# total) and hidden scenes of the instructor's own, their references rendered into the zip.
echo "== controls: points, visibilities and two hidden scenes"
mkdir "$tmp/hidden"
sed 's/^s 0 20 -10   10$/s 3 22 -10   9/' "$top/scenes/shadow-sphere.scn" >"$tmp/hidden/own-shadow.scn"
sed 's/^c 0 38 125 /c 9 36 125 /' "$top/scenes/demo.scn" >"$tmp/hidden/own-demo.scn"
check "the hidden scenes are the shipped ones" sh -c '! cmp -s "$1" "$2" && ! cmp -s "$3" "$4"' sh \
    "$tmp/hidden/own-shadow.scn" "$top/scenes/shadow-sphere.scn" "$tmp/hidden/own-demo.scn" "$top/scenes/demo.scn"
mkdir "$tmp/hidden/meshes" && cp "$top/scenes/meshes/icosahedron.obj" "$tmp/hidden/meshes/" || exit 2
printf '# the instructor'"'"'s own\nown-shadow.png own-shadow.scn\nown-demo.png own-demo.scn\n' \
    >"$tmp/hidden/renders.txt"
cat >"$tmp/grading.conf" <<EOF
# part 1.3, as a course weighs it
part 50
hidden hidden
*            1
demo         2   after_published
own-demo     3   hidden
# late work: the due date is Gradescope's (submission_metadata.json)
grace            15m
penalty_per_day  10%
EOF
make --no-print-directory -s -C "$top" gradescope PART=1.3 OUT="$tmp/controls.zip" \
    GRADING_CONF="$tmp/grading.conf" >"$tmp/pack.log" 2>&1 ||
    { echo "gradescope.sh: make gradescope with controls failed:" >&2; cat "$tmp/pack.log" >&2; exit 1; }
check "make gradescope does not say the next steps" grep -q "^Next steps" "$tmp/pack.log"
check "make gradescope does not say how to try it locally" grep -q "AUTOGRADER_ROOT=" "$tmp/pack.log"
unzip -Z1 "$tmp/controls.zip" >"$tmp/zipped"
for file in hidden/renders.txt hidden/own-demo.scn hidden/references/own-demo.png \
    hidden/references/own-shadow.png milestones/$part/references/grading.conf; do
    check "the zip with controls has no $file" grep -qx "$file" "$tmp/zipped"
done
rm -rf "$root/source" && mkdir -p "$root/source" && unzip -q "$tmp/controls.zip" -d "$root/source" ||
    exit 2
sh "$root/source/setup.sh" --build-only >"$tmp/setup.log" 2>&1 || { tail "$tmp/setup.log"; exit 1; }
# What students see before the tests not visible are: the summary (visible) speaks of the
# visible tests alone, neither counting nor naming the others; the total is hidden as
# Gradescope's specification says (a test not shown yet hides it; a "hidden" scene that
# counts brings a note shown once the grades are published, which does); no advice names
# a scene file the student does not have.
summary9="Part 1.3-shadows-mirror: 9 of 9 scenes shown here pass: 30 of 30 points. \
Gradescope shows your total score later."
check_unshown() {
    check "controls: the summary does not speak of the 9 visible scenes alone: $(field .output)" \
        test "$(field ".output | startswith(\"$summary9\n\")")" = true
    check "controls: the summary names a test that is not visible, or its scene file" \
        test "$(field '. as $r | [$r.tests[] | select(.visibility != "visible" and has("score")) |
            .name | capture("^(?<n>[^ ]+) \\((?<f>.*)\\)$") | [.n, .f][] as $word |
            $r.output | contains($word)] | any')" = false
    check "controls: the summary counts the tests not visible, or all" \
        test "$(field '.output | test("\\b(3|12) (of|scenes)|of (3|12)\\b|\\b50\\b")')" = false
    check "controls: a test that counts is not visible, yet none hides the total as the spec says" \
        test "$(field '([.tests[] | select(.visibility != "visible" and .max_score > 0)] |
            length == 0) or ([.tests[].visibility | select(. == "after_due_date" or
            . == "after_published")] | length > 0)')" = true
    check "controls: a hidden scene counts, yet no note shown after publishing hides the total" \
        test "$(field '[.tests[] | select(.visibility == "after_published" and
            (has("score") | not) and (.output | test("total score")))] | length')" = 1
    check "controls: a test has an execution_time" \
        test "$(field '[.tests[] | has("execution_time")] | any')" = false
    check "controls: a hidden scene's output names a scene file or a command" \
        test "$(field '[.tests[] | select(.name | startswith("own-")) | .output |
            test("\\.scn|Command|\\./raytra|heat\\.png")] | any')" = false
}
autograde "$correct"
check "controls: the score is not 50" test "$(field .score)" = 50
check "controls: not 12 tests and a note" test "$(field '.tests | length')" = 13
check "controls: the points are not 1 a scene, demo 2, own-shadow 1, own-demo 3, scaled to 50" \
    test "$(field '[.tests[] | select(has("max_score")) | .max_score * 15 / 50 | round]')" = \
    '[1,1,1,1,1,1,1,1,1,2,1,3]'
check "controls: the visibilities" test "$(field '[.tests[].visibility]')" = \
    '["visible","visible","visible","visible","visible","visible","visible","visible","visible","after_published","after_due_date","hidden","after_published"]'
check_unshown
if [ "$(id -u)" -eq 0 ]; then
    check "controls: the student's uid can read a hidden reference" sh -c '! setpriv \
        --reuid="$AUTOGRADER_USER" --regid="$AUTOGRADER_USER" --clear-groups \
        cat "$1" >/dev/null 2>&1' sh "$root/source/hidden/references/own-demo.png"
    check "controls: the grader's uid cannot read a hidden reference" setpriv \
        --reuid="$AUTOGRADER_GRADER_USER" --regid="$AUTOGRADER_GRADER_USER" --clear-groups \
        cat "$root/source/hidden/references/own-demo.png" >/dev/null
else
    echo "gradescope.sh: not root: the hidden references' protection from the student's user" \
        "is not tried"
fi
# A program that copies the references its folder carries: the hidden scenes fail.
cp -R "$correct" "$tmp/copier"
cat >"$tmp/copier/raytra.sh" <<'EOF'
#!/bin/sh
exec cp "$(dirname "$0")/milestones/1.3-shadows-mirror/references/$(basename "$2")" "$2"
EOF
printf 'raytra: raytra.sh\n\tcp raytra.sh raytra\n\tchmod +x raytra\n' >"$tmp/copier/Makefile"
autograde "$tmp/copier"
check "controls: the copier passes a hidden scene" test "$(field '[.tests[] |
    select(.status == "failed") | .name | sub(" .*"; "")]')" = '["own-shadow","own-demo"]'
check "controls: the copier's score is not 11 of 15, scaled to 50" \
    test "$(field '.score * 15 / 50 | round')" = 11
check "controls: the copier's hidden scenes do not fail as ERROR" test "$(field '[.tests[] |
    select(.name | startswith("own-")) | .output | startswith("ERROR: ")] | all')" = true
check_unshown

# A curious build: it prints Gradescope's submission_metadata.json (earlier results,
# hidden tests included) and the hidden scenes into make's output, which the summary shows.
echo "== curious: make prints submission_metadata.json and the hidden scenes, and fails"
marker="raytra-metadata-marker-$$"
printf '{"id": 1, "previous_submissions": [{"score": 7, "results": {"output": "%s"}}]}\n' \
    "$marker" >"$root/submission_metadata.json" && chmod 644 "$root/submission_metadata.json" ||
    exit 2
mkdir "$tmp/curious"
# The metadata last, so that it would be in the end of make's output the summary shows.
printf 'raytra:\n\t%s\n\t-cat /autograder/submission_metadata.json %s/submission_metadata.json\n\texit 1\n' \
    '-cat ../../hidden-scenes/*.scn ../../../hidden/*.scn' "$root" >"$tmp/curious/Makefile"
autograde "$tmp/curious"
check "curious: the build did not fail" test "$(field '.output |
    test("The build failed: make failed ")')" = true
check "curious: make's output, up to the cat of the metadata, is not in the summary" \
    test "$(field '.output | test("\nThe end of make.s output:\n(.*\n)*cat: [^\n]*" +
        "submission_metadata.json[^\n]*\n(.*\n)*make: \\*\\*\\* .*Error 1")')" = true
if [ "$(id -u)" -eq 0 ]; then
    check "curious: submission_metadata.json reached results.json" \
        sh -c '! grep -q "$1" "$2"' sh "$marker" "$root/results/results.json"
    # Denied by its mode, or out of sight in the grader's sandbox.
    check "curious: the build could read submission_metadata.json" test "$(field '.output |
        test("cat: [^\n]*/submission_metadata.json: (Permission denied|No such file)")')" = true
    check "curious: submission_metadata.json is not root's alone (600)" \
        test "$(stat -c '%u %a' "$root/submission_metadata.json")" = "0 600"
else
    echo "gradescope.sh: not root: submission_metadata.json stays readable by the submission" \
        "(it runs as the user running the test): not tried"
fi
rm -f "$root/submission_metadata.json"
# The hidden scenes: the grader copies them where the program reads them, and without the
# grader's sandbox (grader/docs/containment.md) make can read them too.
if grep -q '^s 3 22 -10   9$' "$tmp/hidden/own-shadow.scn" &&
    jq -r .output "$root/results/results.json" | grep -q '^s 3 22 -10   9$'; then
    echo "gradescope.sh: note: the build read a hidden scene, which results.json shows (no sandbox)"
fi

# Late work: Gradescope's submission_metadata.json says when the submission was handed in
# and when it was due; a student's own dates (an extension) win over the assignment's.
# Writes the metadata of a submission handed in at $1, the assignment due at $2, the
# student's own due date $3 and late due date $4 (JSON: a quoted time, or null).
metadata() {
    cat >"$root/submission_metadata.json" <<EOF || exit 2
{"id": 7, "created_at": "$1",
 "assignment": {"due_date": "$2", "late_due_date": null, "title": "Part \"1.3\"",
  "total_points": "50.0"},
 "users": [{"email": "ada@example.com", "id": 3, "name": "Ada",
  "assignment": {"due_date": $3, "late_due_date": $4}}],
 "previous_submissions": [{"submission_time": "2026-03-01T10:00:00-05:00", "score": 50,
  "results": {"output": "\"created_at\": \"2026-01-01T00:00:00Z\""}}]}
EOF
}
# Handed in 1 day and 10 h after the due date, with 15 min of grace: 2 days late, 20% off.
echo "== late: handed in 2 days late, then with an extension, then after the late due date"
metadata 2026-03-03T10:00:00-05:00 2026-03-01T23:59:00-05:00 '"2026-03-01T23:59:00-05:00"' null
autograde "$correct"
check "late: the score is not 50 less 20%: $(field .score)" test "$(field .score)" = 40
check "late: the summary does not say 2 days late and 20% off: $(field .output)" \
    test "$(field '.output | test("\nHanded in 2026-03-03T10:00:00-05:00, 2 days late \\(due " +
        "2026-03-01T23:59:00-05:00, a grace of 15 min\\): the late penalty takes 20% of your " +
        "points\\.\n")')" = true
check "late: the summary gives the total, which is hidden" \
    test "$(field '.output | test("Your score|\\b40\\b")')" = false
check "late: the tests lost their points" test "$(field '[.tests[].score | numbers] | add * 13 / 50 |
    round')" = 13
if [ "$(id -u)" -eq 0 ]; then
    check "late: submission_metadata.json is not root's alone (600)" \
        test "$(stat -c '%u %a' "$root/submission_metadata.json")" = "0 600"
fi
metadata 2026-03-03T10:00:00-05:00 2026-03-01T23:59:00-05:00 '"2026-03-04T23:59:00-05:00"' null
autograde "$correct"
check "extension: the score is not 50: $(field .score)" test "$(field .score)" = 50
check "extension: the summary does not say on time" test "$(field '.output |
    test("\nHanded in 2026-03-03T10:00:00-05:00: on time \\(due 2026-03-04T23:59:00-05:00\\)")')" = true
metadata 2026-03-03T10:00:00-05:00 2026-03-01T23:59:00-05:00 '"2026-03-01T23:59:00-05:00"' \
    '"2026-03-02T23:59:00-05:00"'
autograde "$correct"
check "after the late due date: the score is not 0: $(field .score)" test "$(field .score)" = 0
check "after the late due date: the summary does not say so" test "$(field '.output |
    test("later than late work is taken, so the work gets 0")')" = true
printf '{"created_at": ' >"$root/submission_metadata.json"
autograde "$correct"
check "broken metadata: the score is not 50" test "$(field .score)" = 50
check "broken metadata: the instructor is not told" \
    grep -q "submission_metadata.json cannot be read: no lateness is counted" "$tmp/run.log"
rm -f "$root/submission_metadata.json"

if [ $failures -eq 0 ]; then
    echo "gradescope.sh: all $checks checks passed"
else
    echo "gradescope.sh: $failures of $checks checks failed (KEEP=1 keeps $tmp)"
    exit 1
fi
