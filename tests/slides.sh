#!/bin/sh
# slides.sh: checks every slide citation in the project against the lecture's text.
#
# Usage: tests/slides.sh [LECTURE]   (default ../shared/course/lecture-ray-tracing.txt)
#
# A citation names the slide by the number printed on it in the lecture and quotes
# words that stand on it: slide 45 ("d is measured in direction of normal"), or
# slides 51-53 ("spheres - intersections") for words on any slide of the range. The
# quote must be on the same line. A bare "slide N" is reported as unchecked.
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
lecture=${1:-$top/../shared/course/lecture-ray-tracing.txt}
if [ ! -f "$lecture" ]; then
    echo "slides: SKIP: the lecture is not at $lecture (../shared is not beside the checkout)"
    exit 0
fi
cd "$top" || exit 1
git ls-files -- '*.c' '*.h' '*.md' '*.scn' '*.sh' '*.mk' '*.txt' 'Makefile' '*/Makefile' |
    grep -v '^tests/bad-input/' |
    awk -v lecture="$lecture" '
    # Lower case, no Markdown stars, one blank between words: how quotes and slides are compared.
    function norm(s) { s = tolower(s); gsub(/\*/, "", s); gsub(/[ \t\r\n]+/, " ", s); return s }
    BEGIN {
        # The lecture: a line holding only a number ends the slide of that number.
        text = ""
        while ((getline line < lecture) > 0) {
            if (line ~ /^[ \t]*[0-9]+[ \t]*$/) {
                n = line + 0
                slide[n] = slide[n] " " norm(text)
                text = ""
            } else
                text = text " " line
        }
        close(lecture)
        checked = 0; bad = 0
    }
    {
        file = $0
        lineno = 0
        while ((getline line < file) > 0) {
            lineno++
            rest = line
            while (match(rest, /[Ss]lides? [0-9]+([-–][0-9]+)?/)) {
                cite = substr(rest, RSTART, RLENGTH)
                rest = substr(rest, RSTART + RLENGTH)
                split(cite, w, " ")
                range = w[2]; first = range + 0; last = first
                if (range ~ /[-–]/) { sub(/^[0-9]+[-–]/, "", range); last = range + 0 }
                if (substr(rest, 1, 3) != " (\"" || index(substr(rest, 4), "\")") == 0) {
                    printf "%s:%d: %s quotes no words of the slide: write %s (\"words on it\")\n", file, lineno, cite, cite
                    bad++
                    continue
                }
                quote = substr(rest, 4, index(substr(rest, 4), "\")") - 1)
                found = 0
                for (k = first; k <= last; k++)
                    if ((k in slide) && index(slide[k], norm(quote)) > 0)
                        found = 1
                if (!found) {
                    printf "%s:%d: \"%s\" is not on %s of the lecture\n", file, lineno, quote, cite
                    bad++
                }
                checked++
            }
        }
        close(file)
    }
    END {
        if (bad > 0) {
            printf "slides: %d of %d citations are wrong\n", bad, checked + bad
            exit 1
        }
        printf "slides: %d citations, each quoting words that stand on its slide\n", checked
    }'
