#!/bin/sh
# readme-images.sh: the README's pictures of the parts are the images `make demo` writes, byte for byte.
#
# Usage: tests/readme-images.sh [MAKE]   (make check-demo runs it; MAKE defaults to make)
#
# Runs make demo into a scratch folder (DEMO_DIR), which writes demo-PART.png for every
# part; then checks that every image of milestones/PART/references/ that README.md shows
# is a reference of that part's renders.txt (so tests/regress.sh keeps it up to date) and
# the very file make demo wrote for the part, and that every part's image is shown.
set -u
make=${1:-make}
top=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

if ! $make -s --no-print-directory -C "$top" demo DEMO_DIR="$tmp/demo" >"$tmp/log" 2>&1; then
    echo "FAIL make demo:"
    sed 's/^/    /' "$tmp/log"
    exit 1
fi
failed=0 count=0
# Every picture of a part's references that the README links, once each.
grep -o 'milestones/[^/)]*/references/[^)]*\.png' "$top/README.md" | sort -u >"$tmp/shown"
while IFS=/ read -r _ part _ image; do
    count=$((count + 1))
    if ! awk -v image="$image" '$1 == image || $1 == "!" image { found = 1 } END { exit !found }' \
        "$top/milestones/$part/references/renders.txt" 2>/dev/null; then
        echo "FAIL README.md shows milestones/$part/references/$image, which no line of its renders.txt renders"
        failed=$((failed + 1))
    elif [ ! -f "$tmp/demo/demo-$part.png" ]; then
        echo "FAIL README.md shows milestones/$part/references/$image, but make demo renders no part $part"
        failed=$((failed + 1))
    elif ! cmp -s "$top/milestones/$part/references/$image" "$tmp/demo/demo-$part.png"; then
        echo "FAIL README.md shows milestones/$part/references/$image, which is not the image" \
            "make demo writes for part $part"
        failed=$((failed + 1))
    else
        echo "ok   milestones/$part/references/$image is make demo's image of part $part"
    fi
done <"$tmp/shown"
# Every part's demo image is shown.
for image in "$tmp"/demo/demo-*.png; do
    part=${image##*/demo-}
    part=${part%.png}
    if ! grep -q "^milestones/$part/" "$tmp/shown"; then
        echo "FAIL make demo renders part $part, whose image README.md does not show"
        failed=$((failed + 1))
    fi
done
if [ $failed -gt 0 ]; then
    echo "readme-images: FAILED ($failed of the checks above)"
    exit 1
fi
echo "readme-images: the README's $count pictures of the parts are what make demo writes"
