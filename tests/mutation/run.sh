#!/bin/sh
# run.sh: measures how well a part's graded scenes catch wrong programs: its student functions
# mutated one small change at a time (mutate.awk), each mutant graded like a student.
#
# Usage: tests/mutation/run.sh [--sample N] [--time-limit S] [--out DIR] PART...
#   PART            a part: 1.2, 1.2-shading or milestones/1.2-shading (built first)
#   --sample N      grade N of each part's mutants, spread evenly over them (default: all)
#   --time-limit S  seconds a mutant may take for one scene (default 30: a mutant that
#                   loops forever fails by it)
#   --out DIR       keep each part's grading and mutants.tsv in DIR/PART (default: a
#                   temporary folder, removed)
#
# Each mutant is compiled as the part's Makefile compiles its file and linked in place of
# it; one that does not compile is stillborn and not counted. The others, and the part
# unchanged, are graded as one class (grader/build/grade, two at a time) against the part's
# graded scenes. A mutant is caught when a scene fails; it survives when every scene passes
# (its images then the unchanged part's byte for byte, or not). A survivor listed in
# known.txt, by its file and its changed line, is known: the reason there says why no
# graded scene can tell it from the part (equivalent, a boundary case, unseen in this
# part's images, undefined behaviour, or a choice the course leaves open). Prints each
# part's mutation score (the caught over the mutants neither stillborn nor known) and
# every survivor; exit status 1 when the unchanged part fails a scene or a survivor is not
# known, 2 on a usage or build error.
set -u
here=$(cd "$(dirname "$0")" && pwd) || exit 2
top=$(cd "$here/../.." && pwd) || exit 2
usage() {
    echo "usage: $0 [--sample N] [--time-limit S] [--out DIR] PART..." >&2
    exit 2
}
sample=0 limit=30 out=
while [ $# -gt 0 ]; do
    case $1 in
    --sample) [ $# -ge 2 ] || usage; sample=$2; shift ;;
    --time-limit) [ $# -ge 2 ] || usage; limit=$2; shift ;;
    --out) [ $# -ge 2 ] || usage; out=$2; shift ;;
    -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;;
    -*) usage ;;
    *) break ;;
    esac
    shift
done
[ $# -ge 1 ] || usage
case $sample in '' | *[!0-9]*) usage ;; esac
grade=$top/grader/build/grade
[ -x "$grade" ] || { echo "run.sh: build the grader first (make -C grader)" >&2; exit 2; }
tmp=$(mktemp -d) || exit 2
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
[ -n "$out" ] && { mkdir -p "$out" && out=$(cd "$out" && pwd); } || [ -z "$out" ] || exit 2

# The command that compiles the part's FILE.c, as its Makefile gives it, for SOURCE into
# OBJECT: run in the part's folder, whose headers the mutant includes.
compile_command() { # FILE SOURCE OBJECT
    make --no-print-directory -s -n -W "$1.c" "build/$1.o" |
        awk -v file="$1" -v src="$2" -v obj="$3" '
            index($0, " -c " file ".c -o build/" file ".o") {
                sub(" -c " file ".c -o build/" file ".o", " -c " src " -o " obj)
                gsub(/ -MMD| -MP/, ""); print; found = 1 }
            END { exit !found }'
}

# The command that links the part's program with OBJECT ahead of the part's library, to
# PROGRAM.
link_command() { # FILE OBJECT PROGRAM
    make --no-print-directory -s -n -W "build/$1.o" raytra |
        awk -v obj="$2" -v prog="$3" '
            / -o raytra / && /build\/raytra\.o/ {
                sub(/ -o raytra /, " -o " prog " "); sub(/build\/raytra\.o/, "build/raytra.o " obj)
                print; found = 1 }
            END { exit !found }'
}

status=0
for arg in "$@"; do
    part=${arg%/}
    part=${part##*/}
    case $part in *-*) ;; *) part=$(cd "$top/milestones" && for d in "$part"-*; do [ -d "$d" ] && echo "$d"; done) ;; esac
    dir=$top/milestones/$part
    [ -n "$part" ] && [ -f "$dir/Makefile" ] || { echo "run.sh: no part '$arg'" >&2; exit 2; }
    MAKEFLAGS= make --no-print-directory -s -C "$dir" all >/dev/null || { echo "run.sh: $part does not build" >&2; exit 2; }
    work=$tmp/$part
    mkdir -p "$work/class/model" "$work/mutants"
    cp "$dir/raytra" "$work/class/model/model"
    printf "raytra: model\n\tcp model raytra\n" >"$work/class/model/Makefile"

    # Every mutant of the part: FILE K LINE WAS -> NOW, in the order of its files.
    for src in "$dir"/*.c; do
        grep -q '^/\* starter: todo' "$src" || continue
        file=$(basename "$src" .c)
        awk -f "$here/mutate.awk" "$src" | sed "s/^/$file	/"
    done >"$work/all.tsv"
    total=$(wc -l <"$work/all.tsv")
    # The sample: N rows spread evenly, the same on every run.
    if [ "$sample" -gt 0 ] && [ "$sample" -lt "$total" ]; then
        awk -F'\t' -v n="$sample" -v total="$total" \
            'BEGIN { for (i = 0; i < n; i++) pick[int((i + 0.5) * total / n) + 1] = 1 } pick[NR]' \
            "$work/all.tsv" >"$work/picked.tsv"
    else
        cp "$work/all.tsv" "$work/picked.tsv"
    fi
    picked=$(wc -l <"$work/picked.tsv")
    echo "== $part: $picked of its $total mutants"

    stillborn=0
    while IFS='	' read -r file k line change; do
        name=$file-$k
        m=$work/mutants/$name
        mkdir -p "$m"
        awk -v mutant="$k" -f "$here/mutate.awk" "$dir/$file.c" >"$m/$file.c" || exit 2
        if ! (cd "$dir" && cc_line=$(compile_command "$file" "$m/$file.c" "$m/$file.o") &&
            ld_line=$(link_command "$file" "$m/$file.o" "$m/raytra") &&
            eval "$cc_line" && eval "$ld_line") >"$m/build.log" 2>&1; then
            stillborn=$((stillborn + 1))
            echo "$name	$file.c:$line	$change	stillborn" >>"$work/verdicts.tsv"
            continue
        fi
        mkdir "$work/class/$name"
        mv "$m/raytra" "$work/class/$name/model"
        printf "raytra: model\n\tcp model raytra\n" >"$work/class/$name/Makefile"
        changed_line=$(sed -n "${line}p" "$m/$file.c" | sed 's/^[ \t]*//')
        echo "$name	$file.c:$line	$change	$changed_line" >>"$work/graded.tsv"
    done <"$work/picked.tsv"

    "$grade" -q --jobs 2 --time-limit "$limit" --out "$work/out" "$part" "$work/class" >"$work/grade.log" 2>&1
    [ -f "$work/out/grades.csv" ] || { cat "$work/grade.log" >&2; echo "run.sh: grade wrote no grades.csv" >&2; exit 2; }
    csv=$work/out/grades.csv
    # A submission's verdicts: PASS when every scene passes.
    passes() { awk -F, -v n="$1" '$1 == n { seen = 1; if ($3 != "PASS") bad = 1 } END { exit !(seen && !bad) }' "$csv"; }
    passes model || { echo "FAIL $part: the unchanged part fails a scene"; status=1; }
    model_images=$(ls -d "$work/out/work/"*-model/images)

    caught=0 equivalent=0 survived=0
    while IFS='	' read -r name where change changed_line; do
        if ! passes "$name"; then
            caught=$((caught + 1))
            echo "$name	$where	$change	caught" >>"$work/verdicts.tsv"
            continue
        fi
        images=$(ls -d "$work/out/work/"*-"$name"/images)
        how="its images differ within the tolerance"
        diff -r -q "$images" "$model_images" >/dev/null && how="its images are the part's"
        why=$(awk -F'\t' -v p="$part" -v f="${where%%:*}" -v l="$changed_line" \
            '$1 == p && $2 == f && $3 == l { print $4; exit }' "$here/known.txt")
        if [ -n "$why" ]; then
            equivalent=$((equivalent + 1))
            echo "$name	$where	$change	known	$how" >>"$work/verdicts.tsv"
            echo "     known $where: $change ($how): $why"
        else
            survived=$((survived + 1))
            echo "$name	$where	$change	survived	$how" >>"$work/verdicts.tsv"
            echo "SURVIVED $where: $change ($how): $changed_line"
        fi
    done <"$work/graded.tsv"
    counted=$((caught + survived))
    score=$(awk -v c="$caught" -v n="$counted" 'BEGIN { printf n ? "%.1f %%" : "-", 100 * c / (n ? n : 1) }')
    echo "$part: $picked mutants: $stillborn stillborn, $equivalent known, $caught caught," \
        "$survived survived: score $score ($caught of $counted)"
    [ "$survived" -eq 0 ] || status=1
    [ -n "$out" ] && { rm -rf "${out:?}/$part"; cp -r "$work" "$out/$part"; }
    rm -rf "$work"
done
exit $status
