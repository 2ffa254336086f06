#!/bin/sh
# starter.sh: checks that a part's starter builds alone, fails its tests as handed out, and passes them once solved.
#
# Usage: tests/starter.sh [--stub-earlier] PART...
#
# For each PART, in a temporary folder: writes the starter (book/starter.sh) and
# the solution's starter (--solution), and checks that
#   - the solution's sources are the repository's, less the marker and excerpt lines;
#   - the starter has a TODO stub for each marker of the parts it stubs;
#   - its `make check WERROR=1` builds without a warning, yet fails: not one unit
#     test program and not one reference image passes with the stubs;
#   - with the solution's sources copied in, `make check WERROR=1` passes, and
#     --trace-pixel prints what the repository's part prints, line for line;
#   - nothing it built refers to the repository: the starter stands alone;
#   - it can be handed out: its folders and files have the modes the umask gives (readable
#     by all with umask 022), every link of its READMEs leads to a file in it, and its
#     README names every package common/deps.sh installs to build and test.
# And that `make starter` refuses a PART of two words, which would make the second DEST.
set -u
top=$(cd "$(dirname "$0")/.." && pwd) || exit 2
options=
[ "${1:-}" = --stub-earlier ] && { options=--stub-earlier; shift; }
[ $# -ge 1 ] || { echo "usage: $0 [--stub-earlier] PART..." >&2; exit 2; }
tmp=$(mktemp -d) || exit 2
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

failed=0
fail() {
    echo "FAIL $part: $*"
    failed=$((failed + 1))
}

# The solved starter's program traces pixels exactly as the repository's part does: the
# trace is told by the seams, not by the functions the student writes back.
same_trace() {
    MAKEFLAGS= SANITIZE= make --no-print-directory -s -C "$top/milestones/$1" all >/dev/null 2>&1 ||
        { fail "the repository's part $1 does not build"; return; }
    for trace in "scenes/trace-pixel.scn --trace-pixel 1,1" \
        "scenes/glass-sphere.scn --scale 0.1 --trace-pixel 20,15" \
        "scenes/soft-shadow.scn --scale 0.1 --samples 2 --light-samples 2 --trace-pixel 10,10@3"; do
        # shellcheck disable=SC2086 # the arguments are words by design
        (cd "$top" && "milestones/$1/raytra" -q $trace >"$tmp/trace.part" 2>&1)
        status=$?
        # A part before 1.6 refuses 1.6's options: that scene's trace is not for it.
        [ $status -eq 2 ] && grep -q 'unknown option' "$tmp/trace.part" && continue
        # shellcheck disable=SC2086
        if [ $status -ne 0 ] || ! (cd "$top" && "$2" -q $trace >"$tmp/trace.starter" 2>&1); then
            fail "--trace-pixel failed: $trace"
            continue
        fi
        cmp -s "$tmp/trace.starter" "$tmp/trace.part" ||
            fail "the solved starter traces $trace otherwise than the part"
    done
    echo "ok   solved: traces the pixels of the scenes it renders as the part does"
}

# Prints each relative link of the Markdown files in folder $1 that leads to no file
# within it, as FILE: TARGET.
dead_links() {
    root=$(cd "$1" && pwd -P)
    find "$root" -name '*.md' | while read -r md; do
        grep -o '\]([^)]*)' "$md" | sed 's/^](//; s/)$//; s/#.*//' | while read -r target; do
            case $target in '' | *:* | /*) continue ;; esac
            folder=$(cd "$(dirname "$md")/$(dirname "$target")" 2>/dev/null && pwd -P)
            case $folder/ in "$root"/*) [ -e "$folder/${target##*/}" ] && continue ;; esac
            echo "${md#"$root"/}: $target"
        done
    done
}

# The packages common/deps.sh installs to build and to test a starter (not Embree, for the
# benchmark, nor Chromium, for the grader's report, nor g++ and OpenEXR, for raytra's own
# tests and tools' reader of OpenEXR files, nor the autograder's zip, unzip and jq, nor
# bubblewrap, the grader's sandbox, nor universal-ctags, which makes the chapters' tables,
# nor xmllint and jsonschema, which check the platforms' formats: none of them a starter's
# make check uses).
packages=$(sed -n 's/.*need \("[^"]*"\|[A-Za-z0-9+-]*\) \([a-z0-9+-]*\) .*/\2/p' "$top/common/deps.sh" |
    grep -v -x -e libembree-dev -e chromium -e 'g++' -e libopenexr-dev -e zip -e unzip -e jq \
        -e bubblewrap -e universal-ctags -e libxml2-utils -e python3-jsonschema)
part=common/deps.sh
[ "$(echo "$packages" | wc -w)" -ge 4 ] || fail "cannot read the packages it installs: '$packages'"

part="make starter"
two="$1 $tmp/wrong"
make --no-print-directory -C "$top" starter PART="$two" >"$tmp/two.log" 2>&1 &&
    fail "PART='$two' succeeded"
grep -q "PART is one part" "$tmp/two.log" || fail "PART='$two' does not say why: $(cat "$tmp/two.log")"
[ ! -e "$tmp/wrong" ] || fail "PART='$two' wrote a starter into $tmp/wrong"
# The docs name the packages as Debian does, in code: `libopenexr-dev`.
part=docs
for word in $packages make; do
    sed -n '/^## 3\./,/^## 4\./p' "$top/docs/starters.md" | grep -qF -- "\`$word\`" ||
        fail "docs/starters.md, section 3, does not name the package $word"
    [ "$word" = check ] || grep -qF -- "\`$word\`" "$top/docs/grading.md" ||
        fail "docs/grading.md does not name the package $word"
done

for part in "$@"; do
    echo "== starter of $part $options"
    stub=$tmp/$part
    solved=$tmp/$part-solution
    # shellcheck disable=SC2086 # options is one word or none
    if ! (umask 022 && "$top/book/starter.sh" --chapter $options "$part" "$stub" >/dev/null) ||
        ! (umask 027 && "$top/book/starter.sh" --chapter $options --solution "$part" "$solved" >/dev/null); then
        fail "book/starter.sh failed"
        continue
    fi

    # It can be handed out: readable by all (umask 022); a more private umask is kept.
    private=$(find "$stub" ! -perm -o=r -o -type d ! -perm -o=x | head -n 3)
    [ -z "$private" ] || fail "made with umask 022, yet not readable by all: $private"
    [ "$(stat -c %a "$solved")" = 750 ] || fail "made with umask 027, the folder has mode $(stat -c %a "$solved")"
    dead=$(dead_links "$stub")
    [ -z "$dead" ] || fail "links in the starter that lead nowhere: $dead"
    for word in $packages make; do
        sed -n '/^Packages needed/,/^$/p' "$stub/README.md" | grep -qw -- "$word" ||
            fail "its README does not name the package $word"
    done

    # The solution is the repository's code; the stubs stand where the markers were.
    markers=0
    for file in "$solved"/milestones/*/*.[ch] "$solved"/common/*.[ch]; do
        rel=${file#"$solved"/}
        if ! grep -v -e '^/\* starter: ' -e '^[[:space:]]*/\* \(end \)\{0,1\}excerpt: ' "$top/$rel" |
            cmp -s - "$file"; then
            fail "the solution's $rel is not the repository's less its marker and excerpt lines"
        fi
        case $rel in *.h | common/*) continue ;; esac
        if [ -n "$options" ] || [ "${rel#milestones/"$part"/}" != "$rel" ]; then
            markers=$((markers + $(grep -c '^/\* starter: todo' "$top/$rel")))
        fi
    done
    todos=$(cat "$stub"/milestones/*/*.c | grep -c '^    /\* TODO: ')
    [ "$markers" -gt 0 ] || fail "no function of the part is marked /* starter: todo */"
    [ "$todos" -eq "$markers" ] || fail "$todos TODO stubs for $markers markers"
    if grep -l '^/\* starter: ' "$stub"/*/*.[ch] "$stub"/milestones/*/*.[ch] \
        "$solved"/milestones/*/*.[ch]; then
        fail "marker lines left in the files above"
    fi

    # As handed out: it builds without a warning, and every check fails.
    make --no-print-directory -C "$stub" check WERROR=1 >"$tmp/stub.log" 2>&1
    status=$?
    if [ ! -x "$stub/raytra" ] || ! grep -q '^unit tests: ' "$tmp/stub.log"; then
        fail "the starter does not build (WERROR=1):"
        grep -e 'error' -e 'warning' "$tmp/stub.log" | grep -v '^cc ' | head -n 20 | sed 's/^/    /'
        continue
    fi
    [ $status -ne 0 ] || fail "make check passes with the stubs"
    grep -q '^unit tests: 0 of [1-9]' "$tmp/stub.log" ||
        fail "some unit test passes with the stubs: $(grep '^unit tests:' "$tmp/stub.log")"
    grep -q '^images: 0 of [1-9]' "$tmp/stub.log" ||
        fail "some image matches with the stubs: $(grep '^images:' "$tmp/stub.log")"
    heat=$(grep -c 'heat map: out/check/' "$tmp/stub.log")
    [ "$heat" -gt 0 ] && [ -f "$stub/out/check/demo.heat.png" ] || fail "no heat maps written"
    echo "ok   as handed out: $todos stubs; $(grep '^unit tests:' "$tmp/stub.log");" \
        "$(grep '^images:' "$tmp/stub.log")"

    # Solved: the bodies put back, it passes every check.
    for file in "$solved"/milestones/*/*.c; do cp "$file" "$stub/${file#"$solved"/}"; done
    if make --no-print-directory -C "$stub" check WERROR=1 >"$tmp/solved.log" 2>&1; then
        echo "ok   solved: $(grep '^unit tests:' "$tmp/solved.log"); $(grep '^images:' "$tmp/solved.log")"
        same_trace "$part" "$stub/raytra"
        # make grade, from inside the starter, grades it as the course's grader does.
        if make --no-print-directory -C "$stub" grade >"$tmp/grade.log" 2>&1 &&
            grep -q '^\([0-9]*\) of \1 scenes pass' "$tmp/grade.log"; then
            echo "ok   solved: make grade: $(grep 'scenes pass' "$tmp/grade.log")"
        else
            fail "make grade does not pass the solved starter:"
            tail -n 5 "$tmp/grade.log" | sed 's/^/    /'
        fi
        rm -rf "$tmp/grading-$part"*
    else
        fail "make check fails with the bodies put back:"
        grep -e '^FAIL' -e 'error' -e 'warning' "$tmp/solved.log" | grep -v '^cc ' | head -n 20 | sed 's/^/    /'
    fi
    if grep -rl -F "$top" "$stub" >"$tmp/refs"; then
        fail "the built starter refers to the repository:"
        sed 's/^/    /' "$tmp/refs" | head -n 5
    fi
    rm -rf "$stub" "$solved"
done

[ $failed -eq 0 ] && echo "starters: every check passed"
[ $failed -eq 0 ]
