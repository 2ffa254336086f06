#!/bin/sh
# pack.sh: writes a part's Gradescope autograder: a zip, setup.sh and run_autograder at its root.
#
# Usage: platforms/gradescope/pack.sh PART [ZIP]   (make gradescope PART=1.3 [OUT=ZIP])
#   PART  one part: 1.3, 1.3-shadows-mirror or milestones/1.3-shadows-mirror
#   ZIP   the file to write; default out/gradescope-<part>.zip at the top
#
# The zip holds what the grader needs to build and run on a fresh machine, from the files
# git tracks: common/, the files of compare/, sandbox/ and grader/ (not their subfolders),
# scenes/, the part's references, and of every part its headers and its table of options
# (*_options.c), which the grader compiles in to know each part's arguments; no part's other
# sources, so that no model answer lies where a student's program could read it. At the
# root: setup.sh, run_autograder and gradescope.conf (the part, and the time budget: BUDGET
# seconds for the whole grading, default 540, and BUILD_TIME_LIMIT, default 120).
# grader/docs/gradescope.md says how to upload it. The zip is written to a temporary and
# renamed.
#
# The instructor's controls: the part's references/grading.conf (or GRADING_CONF=FILE), its
# points and visibilities, goes in as the part's; the hidden scenes of its `hidden` line
# (or HIDDEN=DIR) go in as hidden/, their references rendered here by the part's model
# answer into hidden/references/, which setup.sh leaves to the grader's user alone.
set -u
top=$(cd "$(dirname "$0")/../.." && pwd) || exit 2
die() {
    echo "gradescope: $*" >&2
    exit 2
}
case ${1:-} in -h | --help) sed -n '2,19s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
[ $# -ge 1 ] && [ $# -le 2 ] || die "usage: $0 PART [ZIP]"
command -v zip >/dev/null 2>&1 || die "zip is not installed (common/deps.sh gradescope installs it)"
command -v git >/dev/null 2>&1 && git -C "$top" rev-parse --git-dir >/dev/null 2>&1 ||
    die "$top is not a git checkout: the zip is made of the files git tracks"

# The part's folder, as grade finds it: its full name, its number, or its path.
case $1 in
'' | *[[:space:]]*) die "PART is one part (1.3, 1.3-shadows-mirror or its folder), got '$1'" ;;
esac
part=${1%/}
part=${part##*/}
case $part in
*-*) ;;
*) part=$(cd "$top/milestones" && for d in "$part"-*; do [ -d "$d" ] && echo "$d"; done) ;;
esac
[ -n "$part" ] && [ "$(echo "$part" | wc -l)" -eq 1 ] &&
    [ -f "$top/milestones/$part/references/renders.txt" ] ||
    die "no part '$1' with references in $top/milestones"
zip=${2:-$top/out/gradescope-$part.zip}
case $zip in /*) ;; *) zip=$(pwd)/$zip ;; esac
budget=${BUDGET:-540}
build_limit=${BUILD_TIME_LIMIT:-120}
case $budget$build_limit in *[!0-9]*) die "BUDGET and BUILD_TIME_LIMIT are whole seconds" ;; esac
[ "$budget" -gt "$((build_limit + 60))" ] ||
    die "BUDGET ($budget s) leaves no time to render after BUILD_TIME_LIMIT ($build_limit s)"

stage=$(mktemp -d) || exit 2
trap 'rm -rf "$stage"' EXIT
trap 'exit 130' INT TERM
mkdir "$stage/root" || exit 2

# The tracked files the grader needs, copied from the working tree.
(cd "$top" && git ls-files -- common scenes "milestones/$part/references" 'milestones/*/*.h' \
    'milestones/*/*_options.c' && git ls-files -- compare sandbox grader |
    grep -E '^(compare|sandbox|grader)/[^/]*$') >"$stage/files" ||
    die "git ls-files failed"
while IFS= read -r file; do
    mkdir -p "$stage/root/$(dirname "$file")" && cp -p "$top/$file" "$stage/root/$file" || exit 2
done <"$stage/files"
cp "$top/platforms/gradescope/setup.sh" "$top/platforms/gradescope/run_autograder" "$stage/root/" || exit 2

# The part's known mistakes and their renders (make -C grader mistakes), when made: the
# grader names the one a failing image resembles (grader/docs/diagnosis.md). The zip holds
# no model answer to render them from.
mistakes=$top/grader/build/mistakes/$part
if [ -f "$top/grader/mistakes/$part.txt" ] && [ -d "$mistakes" ]; then
    mkdir -p "$stage/root/grader/mistakes" "$stage/root/grader/build/mistakes" &&
        cp "$top/grader/mistakes/$part.txt" "$stage/root/grader/mistakes/" &&
        cp -R "$mistakes" "$stage/root/grader/build/mistakes/" &&
        find "$stage/root/grader/build/mistakes" -name '*.log' -exec rm -f {} + || exit 2
fi

# The instructor's controls, and the hidden scenes with their references, rendered now.
conf=${GRADING_CONF:-$top/milestones/$part/references/grading.conf}
hidden=${HIDDEN:-}
if [ -f "$conf" ]; then
    cp "$conf" "$stage/root/milestones/$part/references/grading.conf" || exit 2
    # Its "hidden FOLDER" line, as the grader reads it: from the file's folder, or ~/.
    line=$(awk '$1 == "hidden" && NF == 2 { print $2 }' "$conf" | tail -n 1)
    case $line in
    '') ;;
    '~/'*) line=$HOME/${line#'~/'} ;;
    /*) ;;
    *) line=$(dirname "$conf")/$line ;;
    esac
    hidden=${hidden:-$line}
elif [ -n "${GRADING_CONF:-}" ]; then
    die "no file GRADING_CONF=$conf"
fi
hidden_count=0
if [ -n "$hidden" ]; then
    [ -f "$hidden/renders.txt" ] || die "no hidden scenes: $hidden/renders.txt is not there"
    make --no-print-directory -s -C "$top/milestones/$part" SANITIZE= raytra >&2 ||
        die "the model answer of $part does not build, to render the hidden scenes"
    mkdir -p "$stage/root/hidden/references" && cp -R -P "$hidden/." "$stage/root/hidden/" &&
        rm -rf "$stage/root/hidden/references" && mkdir "$stage/root/hidden/references" || exit 2
    n=0
    while read -r image scene options; do
        n=$((n + 1))
        case $image in '' | '#'* | '!'*) continue ;; esac
        case $scene in /*) ;; *) scene=$hidden/$scene ;; esac
        # shellcheck disable=SC2086 # the options are words, as renders.txt gives them
        "$top/milestones/$part/raytra" "$scene" "$stage/root/hidden/references/$image" \
            $options >"$stage/render.log" 2>&1 ||
            die "$hidden/renders.txt:$n: the model answer cannot render it: $(tail -n 3 "$stage/render.log")"
        hidden_count=$((hidden_count + 1))
    done <"$hidden/renders.txt"
fi
{
    echo "# gradescope.conf: what run_autograder grades, written by platforms/gradescope/pack.sh."
    echo "PART=$part"
    echo "BUDGET=$budget"
    echo "BUILD_TIME_LIMIT=$build_limit"
} >"$stage/root/gradescope.conf"
chmod -R u+rwX,go-w,a+rX "$stage/root" &&
    chmod a+x "$stage/root/setup.sh" "$stage/root/run_autograder" || exit 2

mkdir -p "$(dirname "$zip")" || exit 2
rm -f "$stage/out.zip"
(cd "$stage/root" && zip -q -r -X "$stage/out.zip" .) || die "zip failed"
mv -f "$stage/out.zip" "$zip.tmp$$" && mv -f "$zip.tmp$$" "$zip" || die "cannot write $zip"
echo "gradescope: wrote $zip ($(wc -l <"$stage/files") files of raytra, part $part;" \
    "grading within $budget s)"
[ "$hidden_count" -eq 0 ] ||
    echo "gradescope: with $hidden_count hidden scenes of $hidden, rendered by the model answer"
cat <<EOF
Next steps (grader/docs/gradescope.md):
  1. On Gradescope, create a Programming Assignment; in Configure Autograder choose the
     base image Ubuntu 22.04 (or later) and upload $zip.
  2. Gradescope runs setup.sh as it builds the image; then Test Autograder with a
     solution: make starter PART=$part STARTER_OPTIONS=--solution, zipped: every scene passes.
  3. To try it here first, as Gradescope would:
       mkdir -p /tmp/ag/source && unzip -q $zip -d /tmp/ag/source
       sh /tmp/ag/source/setup.sh --build-only
       cp -R YOUR-SOLUTION /tmp/ag/submission
       AUTOGRADER_ROOT=/tmp/ag /tmp/ag/source/run_autograder && cat /tmp/ag/results/results.json
     (make check-gradescope, platforms/tests/gradescope.sh, does this with part 1.3.)
EOF
