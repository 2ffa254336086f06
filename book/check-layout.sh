#!/bin/sh
# check-layout.sh: the rules that keep the parts of the course from copying each other.
#
# Usage: book/check-layout.sh [BUILD]   (BUILD: build or build-sanitize)
#   1. no two milestone folders hold files of the same content;
#   2. no two milestone folders hold C files of the same name (an #include would be ambiguous);
#   3. no function or variable is defined in two libraries (a part that changes an
#      earlier part's function gives its version a new name);
#   4. every part named in a Makefile's USES exists and comes earlier in the course.
case ${1:-} in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
set -u
cd "$(dirname "$0")/.." || exit 2
build=${1:-build}
status=0
problem() { echo "check-layout: $*"; status=1; }

dups=$(find milestones -path '*/build*' -prune -o -type f \( -name '*.c' -o -name '*.h' \) \
           -exec md5sum {} + | sort | awk '$1 == prev { print prevf " = " $2 } { prev = $1; prevf = $2 }')
[ -z "$dups" ] || problem "identical files in two parts: $dups"

names=$(find milestones -path '*/build*' -prune -o -path '*/tests' -prune -o -type f \
            \( -name '*.c' -o -name '*.h' \) -print | sed 's|.*/||' | grep -v '^raytra\.c$' |
            sort | uniq -d)
[ -z "$names" ] || problem "file names used by two parts: $names"

libs="common/$build/libraytra.a $(ls milestones/*/"$build"/libpart.a 2>/dev/null)"
twice=$(for lib in $libs; do
            nm --defined-only -g "$lib" 2>/dev/null | awk -v lib="$lib" 'NF == 3 { print $3, lib }'
        done | sort | awk '$1 == prev { print $1 " in " prevlib " and " $2 } { prev = $1; prevlib = $2 }')
[ -z "$twice" ] || problem "symbols defined twice: $twice"

for makefile in milestones/*/Makefile; do
    part=$(basename "$(dirname "$makefile")")
    for used in $(sed -n 's/^USES *:= *//p' "$makefile"); do
        [ -d "milestones/$used" ] || problem "$makefile: USES names $used, which does not exist"
        [ "$(printf '%s\n%s\n' "$used" "$part" | sort | head -1)" = "$used" ] &&
            [ "$used" != "$part" ] || problem "$makefile: USES names $used, not an earlier part"
    done
done

[ $status -eq 0 ] && echo "check-layout: parts share code only through their libraries"
exit $status
