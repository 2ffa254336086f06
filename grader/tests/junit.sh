#!/bin/sh
# junit.sh: tests grade --junit on a tiny class: valid against grader/tests/junit.xsd, with its verdicts.
#
# Usage: grader/tests/junit.sh GRADE   (make -C grader test runs it)
#   GRADE   the grader, grader/build/grade, with imgdiff beside it
#
# The class, made here in a temporary folder: the references handed in as they are; a
# folder with one image missing and one that is no image; a folder named with a dot (its
# classname has none); a program that crashes; and a
# program in a folder whose name holds every byte XML and UTF-8 refuse (control
# characters, invalid UTF-8, quotes, "]]>"), that prints such bytes and fails. Checks that
# xmllint validates the file against grader/tests/junit.xsd (xmllint is libxml2-utils; the test
# says it skips the validation without it), and the counts, types and names in it.
set -u
[ $# -eq 1 ] || { echo "usage: $0 GRADE" >&2; exit 2; }
case $1 in /*) grade=$1 ;; *) grade=$(pwd)/$1 ;; esac
top=$(cd "$(dirname "$0")/../.." && pwd)
refs=$top/milestones/1.1-spheres-red/references
# How many scenes part 1.1 grades (renders.txt's lines but comments and illustrations).
n=$(grep -c '^[^#![:space:]]' "$refs/renders.txt")
tmp=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
cd "$tmp" || exit 2

. "$top/tests/checks.sh"

# Prints what XPath expression $1 gives in the report.
xpath() {
    xmllint --xpath "$1" report.xml 2>/dev/null
}

mkdir -p class/correct class/wrong class/crashing
cp "$refs"/*.png class/correct/
# A name with a dot, which Jenkins would split into a package and a class.
mkdir class/barbara.liskov
cp "$refs"/*.png class/barbara.liskov/
cp "$refs"/*.png class/wrong/
rm class/wrong/demo.png
echo "not an image" >class/wrong/spheres-three.png
# A program: make copies the shell script read from stdin to raytra, in folder $1.
script_submission() {
    cat >"$1/raytra.sh"
    printf 'raytra: raytra.sh\n\tcp raytra.sh raytra\n\tchmod +x raytra\n' >"$1/Makefile"
}
script_submission class/crashing <<'EOF'
#!/bin/sh
kill -SEGV $$
EOF
# The name: a control character, a byte of no UTF-8 character, a cut sequence, quotes, the
# end of a CDATA section, markup and a tab. Its program prints the same bytes and fails.
nasty=$(printf 'x\001y\377 "q" ]]> <&>\tend\342\202')
mkdir "class/$nasty"
script_submission "class/$nasty" <<'EOF'
#!/bin/sh
printf 'out\001\377 ]]> <b>&\n'
exit 3
EOF

checks=$((checks + 1))
if ! "$grade" -q --time-limit 10 --out out --junit report.xml 1.1 class >grade.log 2>&1; then
    failures=$((failures + 1))
    echo "FAIL: grade --junit failed:"
    sed 's/^/    | /' grade.log
fi

if command -v xmllint >/dev/null 2>&1; then
    xmllint --noout --schema "$top/grader/tests/junit.xsd" report.xml >valid.log 2>&1
    check "report.xml is not valid against grader/tests/junit.xsd: $(head -n 5 valid.log)" \
        test "$(cat valid.log)" = "report.xml validates"
    # 5 submissions of n scenes: 3n - 2 pass; 2 failures (UNREADABLE, MISSING); n CRASHED
    # and n ERROR are errors.
    totals=$(xpath 'concat(/*/@tests, " ", /*/@failures, " ", /*/@errors)')
    check "the totals (tests, failures, errors) are $totals, not $((5 * n)) 2 $((2 * n))" \
        test "$totals" = "$((5 * n)) 2 $((2 * n))"
    check "not $((5 * n)) test cases" test "$(xpath 'count(//testcase)')" = $((5 * n))
    check "not 5 test suites" test "$(xpath 'count(/testsuites/testsuite)')" = 5
    check "a dotted name's classname is not barbara_liskov, its suite's name not barbara.liskov" \
        test "$(xpath 'count(//testsuite[@name="barbara.liskov"]/testcase[@classname="barbara_liskov"])')" = "$n"
    check "a classname holds a dot" test "$(xpath 'count(//testcase[contains(@classname, ".")])')" = 0
    check "the failures are not one UNREADABLE and one MISSING" test \
        "$(xpath 'concat(//testcase[@classname="wrong" and @name="spheres-three"]/failure/@type,
            " ", //testcase[@classname="wrong" and @name="demo"]/failure/@type)')" = \
        "UNREADABLE MISSING"
    check "the crashes are not $n errors of type CRASHED" test \
        "$(xpath 'count(//testcase[@classname="crashing"]/error[@type="CRASHED"])')" = "$n"
    check "correct's test cases hold a failure or an error" test \
        "$(xpath 'count(//testsuite[@name="correct"]/testcase[failure or error])')" = 0
    check "a pass does not give its figures" test \
        "$(xpath 'count(//testsuite[@name="correct"]/testcase/system-out[
            contains(., "PASS: identical") and contains(., "PSNR")])')" = "$n"
    # The name as the report shows it: each byte XML cannot hold as \xNN, the rest as it is.
    suite='/testsuites/testsuite[starts-with(@name, "x\x01")]'
    shown=$(printf 'x\\x01y\\xFF "q" ]]> <&>\tend\\xE2\\x82')
    name=$(xpath "string($suite/@name)")
    check "the nasty name is shown as '$name', not as '$shown'" test "$name" = "$shown"
    check "the nasty program's test cases are not $n errors of type ERROR" test \
        "$(xpath "count($suite/testcase/error[@type=\"ERROR\"])")" = "$n"
    check "its output is not in system-out, bytes shown" test \
        "$(xpath "count($suite/testcase/system-out[contains(., 'out\\x01\\xFF ]]> <b>&')])")" = "$n"
    check "a failure does not say what to do" test \
        "$(xpath 'count(//failure[contains(., "What to do: ")])')" = 2
else
    echo "junit.sh: no xmllint (Debian: libxml2-utils): the schema and XPath checks are skipped"
    check "report.xml has no $((5 * n)) test cases" test "$(grep -c '<testcase ' report.xml)" = $((5 * n))
fi

if [ $failures -eq 0 ]; then
    echo "junit.sh: all $checks checks passed"
else
    echo "junit.sh: $failures of $checks checks failed (KEEP the folder: run with sh -x)"
    exit 1
fi
