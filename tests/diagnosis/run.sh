#!/bin/sh
# run.sh: measures how well the grader names the known mistake a failing image resembles, on mistakes it was not made from.
#
# Usage: tests/diagnosis/run.sh GRADE PART PROGRAMS [TABLE]
#   GRADE     the grader, grader/build/grade, with its mistakes rendered (make -C grader mistakes)
#   PART      the part, 1.4-bvh
#   PROGRAMS  a list of lines "NAME PROGRAM EXPECTED KIND": a submission NAME runs PROGRAM
#             (from the top of the repository; $BUILD is GRADE's build folder, build);
#             EXPECTED is the known mistake (grader/mistakes/PART.txt) its failing scenes must
#             be named as, or "none" (no known mistake is it: the grader must abstain), or
#             "pass" (a correct program: every scene passes, no hint, no diagnosis); KIND is
#             "gallery" (a mistake of the catalogue itself), "held-out" or "right"
#   TABLE     where to write the table of results in Markdown (default: standard output only)
# Grades the class, two at a time, and reads grades.csv: for each failing scene, the mistake
# the message names ("closest to: TITLE (") or its abstention ("no known mistake matches").
# Prints a row a program and the totals over the held-out ones: the right mistake named, a
# wrong one named. Exit status 1 when the held-out figures miss the bar (right named at
# least 80 %, when some have a known mistake; a wrong one named at most 5 % of their
# failing scenes), when a correct program
# fails or gets a hint, or when a gallery mistake is not named on every scene it fails.
set -u
[ $# -ge 3 ] || { echo "usage: $0 GRADE PART PROGRAMS [TABLE]" >&2; exit 2; }
case $1 in /*) grade=$1 ;; *) grade=$(pwd)/$1 ;; esac
part=$2 programs=$3 table=${4:-}
top=$(cd "$(dirname "$0")/../.." && pwd)
catalog=$top/grader/mistakes/$part.txt
build=$(basename "$(dirname "$grade")")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

mkdir "$tmp/class"
while read -r name program expected kind; do
    case $name in '' | '#'*) continue ;; esac
    program=$(echo "$program" | sed "s|\\\$BUILD|$build|")
    case $program in /*) ;; *) program=$top/$program ;; esac
    mkdir "$tmp/class/$name"
    # The submission carries its program: the sandbox shows a build nothing but its folder.
    cp "$program" "$tmp/class/$name/model" || exit 2
    printf "raytra: model\n\tcp model raytra\n" >"$tmp/class/$name/Makefile"
done <"$programs"
"$grade" -q --jobs 2 --time-limit 600 --out "$tmp/out" "$part" "$tmp/class" ||
    { echo "run.sh: grade failed" >&2; exit 1; }
csv=$tmp/out/grades.csv

# The mistake a message names, by the catalogue's title; "-" when it abstains, "?" for neither.
named() {
    case $1 in *"no known mistake matches"*) echo -; return ;; esac
    while read -r mistake _ title; do
        case $mistake in '' | '#'*) continue ;; esac
        case $1 in *"closest to: $title ("*) echo "$mistake"; return ;; esac
    done <"$catalog"
    echo "?"
}

failed=0
{
    echo "| program | kind | its mistake | failing scenes | right mistake named | another named | abstained |"
    echo "|---|---|---|---|---|---|---|"
} >"$tmp/table"
: >"$tmp/totals"
while read -r name program expected kind; do
    case $name in '' | '#'*) continue ;; esac
    fails=0 right=0 wrong=0 none=0
    awk -F, -v name="$name" '$1 == name { print $2, $3 }' "$csv" >"$tmp/rows"
    while read -r scene verdict; do
        [ "$verdict" = PASS ] && continue
        # The message: the CSV's field after the bounding box, quoted (it has commas) or not.
        message=$(awk -F, -v name="$name" -v scene="$scene" '$1 == name && $2 == scene' "$csv")
        fails=$((fails + 1))
        said=$(named "$message")
        echo "   $name $scene $verdict: $said"
        if [ "$expected" = pass ]; then
            echo "FAIL $name is correct and fails $scene: $message"
            failed=1
        elif [ "$said" = "$expected" ]; then
            right=$((right + 1))
        elif [ "$said" = - ]; then
            none=$((none + 1))
        elif [ "$said" = "?" ]; then
            echo "FAIL $name $scene: the message neither names a mistake nor abstains: $message"
            failed=1
        else
            wrong=$((wrong + 1))
        fi
    done <"$tmp/rows"
    [ -s "$tmp/rows" ] || { echo "FAIL $name: not in grades.csv"; failed=1; }
    if [ "$kind" = gallery ] && [ $right -ne $fails ]; then
        echo "FAIL $name: a mistake of the catalogue, named on $right of the $fails scenes it fails"
        failed=1
    fi
    echo "| \`$name\` | $kind | $expected | $fails | $right | $wrong | $none |" >>"$tmp/table"
    echo "$kind $expected $fails $right $wrong $none" >>"$tmp/totals"
done <"$programs"

# The held-out totals: of the failing scenes of held-out programs with a known mistake, the
# share named right; of all held-out failing scenes, the share named as another mistake.
awk -v table="$tmp/table" '
$1 == "held-out" && $2 != "none" { known += $3; right += $4 }
$1 == "held-out" { all += $3; wrong += $5 }
END {
    r = known ? 100 * right / known : 0; w = all ? 100 * wrong / all : 0
    printf "\n| held-out programs | scenes | share |\n|---|---|---|\n" >>table
    printf "| right mistake named (of the scenes of a known mistake) | %d of %d | %.0f %% |\n", right, known, r >>table
    printf "| a wrong mistake named (of all their failing scenes) | %d of %d | %.0f %% |\n", wrong, all, w >>table
    exit !((known == 0 || r >= 80) && w <= 5)
}' "$tmp/totals" || { echo "FAIL the held-out figures miss the bar (right >= 80 %, wrong <= 5 %)"; failed=1; }
cat "$tmp/table"
[ -z "$table" ] || cp "$tmp/table" "$table" || exit 2
exit $failed
