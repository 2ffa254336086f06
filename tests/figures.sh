#!/bin/sh
# figures.sh: checks the docs' figures: every docs/figures/*.svg is well-formed XML with a
# viewBox, and every figure a chapter links to exists.
#
# Usage: tests/figures.sh   (from anywhere; POSIX sh, grep and awk; xmllint when installed)
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top" || exit 1
bad=0
count=0

if command -v xmllint >/dev/null 2>&1; then
    xmllint=yes
else
    xmllint=no
    echo "figures: SKIP well-formedness: xmllint is not installed (Debian: apt-get install libxml2-utils)"
fi

for svg in docs/figures/*.svg; do
    [ -f "$svg" ] || continue
    count=$((count + 1))
    if [ "$xmllint" = yes ] && ! xmllint --noout "$svg" 2>/dev/null; then
        echo "$svg: not well-formed XML (xmllint --noout $svg says where)"
        bad=$((bad + 1))
    fi
    # The root <svg ...> tag, however many lines it spans, must carry viewBox="x y w h".
    if ! awk '
        { text = text " " $0 }
        END {
            start = index(text, "<svg")
            if (start == 0) exit 1
            tag = substr(text, start)
            tag = substr(tag, 1, index(tag, ">"))
            n = "[-+]?[0-9.]+"
            exit !(tag ~ ("viewBox=\"[ ]*" n "[ ,]+" n "[ ,]+" n "[ ,]+" n "[ ]*\""))
        }' "$svg"; then
        echo "$svg: the <svg> element has no viewBox=\"x y width height\""
        bad=$((bad + 1))
    fi
done

# Every link to a figure, in every chapter (docs/, grader/docs/) and README, names a file that exists.
links=0
for md in docs/*.md grader/docs/*.md README.md */README.md milestones/*/README.md; do
    [ -f "$md" ] || continue
    dir=$(dirname "$md")
    for target in $(grep -o '](\([^) ]*figures/[^) ]*\))' "$md" | sed 's/^](//; s/)$//; s/#.*//'); do
        links=$((links + 1))
        if [ ! -f "$dir/$target" ]; then
            line=$(grep -n "]($target" "$md" | head -n 1 | cut -d: -f1)
            echo "$md:$line: the figure $target does not exist"
            bad=$((bad + 1))
        fi
    done
done

if [ "$bad" -gt 0 ]; then
    echo "figures: $bad problems"
    exit 1
fi
echo "figures: $count SVG figures with a viewBox$([ "$xmllint" = yes ] && echo ', well-formed'); $links links to figures, each to a file that exists"
