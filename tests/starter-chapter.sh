#!/bin/sh
# starter-chapter.sh: each part's student edition of its chapter shows each marked function it excerpts as a stub.
#
# Usage: tests/starter-chapter.sh PART...
# For each PART, `book/starter.sh --chapter` writes a starter into a temporary folder;
# every marked function (book/marked.sh list) whose signature the full chapter shows
# must stand in the student edition with a TODO in place of its body, and nothing else
# of the chapter may change but the lines of those bodies. Exit status 1 names each fault.
set -u
top=$(cd "$(dirname "$0")/.." && pwd) || exit 2
tmp=$(mktemp -d) || exit 2
trap 'rm -rf "$tmp"' EXIT
failed=0
for part in "$@"; do
    for dir in "$top/milestones/$part"*; do part=$(basename "$dir"); break; done
    full=$top/docs/$part.md
    sh "$top/book/starter.sh" --chapter "$part" "$tmp/$part" >"$tmp/out" 2>&1 ||
        { echo "FAIL: $part: book/starter.sh --chapter failed:"; sed 's/^/    /' "$tmp/out"; failed=$((failed + 1)); continue; }
    edition=$tmp/$part/docs/$part.md
    [ -f "$edition" ] || { echo "FAIL: $part: no docs/$part.md in the starter"; failed=$((failed + 1)); continue; }
    shown=0
    "$top/book/marked.sh" list | awk -v part="$part" '$1 == part { print $2, $3, $4 }' >"$tmp/marked"
    while read -r file line name; do
        signature=$(sed -n "${line}p" "$top/$file")
        grep -qF -- "$signature" "$full" || continue
        shown=$((shown + 1))
        grep -qF -- "$signature" "$edition" ||
            { echo "FAIL: $part: the student edition lacks the signature of $name"; failed=$((failed + 1)); }
    done <"$tmp/marked"
    todos=$(grep -c '^    /\* TODO: ' "$edition")
    [ "$todos" -eq "$shown" ] ||
        { echo "FAIL: $part: the chapter shows $shown marked functions; its student edition has $todos TODOs"; failed=$((failed + 1)); }
    # Only lines of the bodies go: every line of the edition but the stubs' is in the chapter,
    # but for the links to files the starter has not, which name where they are instead.
    grep -v '^    /\* TODO: \|^    (void)\|^    return ' "$edition" | grep -vxF -f "$full" |
        grep -v "in raytra's repository, not in this starter)" >"$tmp/new"
    [ -s "$tmp/new" ] &&
        { echo "FAIL: $part: the student edition has lines the chapter does not:"; head -5 "$tmp/new" | sed 's/^/    /'; failed=$((failed + 1)); }
    echo "starter-chapter: $part: $shown marked functions shown as stubs"
done
[ $failed -eq 0 ]
