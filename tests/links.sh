#!/bin/sh
# links.sh: checks the docs' links: every relative link of a chapter or README names a file
# (or folder) that exists, and every #anchor a heading of the page it points into.
#
# Usage: tests/links.sh [FILE.md...]   (from anywhere; POSIX sh and awk)
# By default the pages are docs/*.md, grader/docs/*.md, the top README and the wings' and
# the parts' READMEs. A link is ](TARGET) outside code (fenced blocks and `spans`); a
# TARGET with a scheme (https:, mailto:) is not checked. A heading's anchor is made as
# GitHub makes it: its text (a link's words, no HTML tags) in lower case, punctuation
# dropped but '-' and '_', each space a '-'; the second heading of the same anchor gets
# '-1', the third '-2'. Exit status 1 names each dead link, FILE:LINE.
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top" || exit 2
if [ $# -eq 0 ]; then
    for page in docs/*.md grader/docs/*.md README.md */README.md milestones/*/README.md; do
        [ -f "$page" ] && set -- "$@" "$page"
    done
fi

LC_ALL=C awk '
# The anchor of a heading line, without its count.
function slug(h,   t) {
    sub(/^#+[ \t]*/, "", h); sub(/[ \t]+#+[ \t]*$/, "", h); sub(/[ \t]+$/, "", h)
    while (match(h, /\[[^]]*\]\([^)]*\)/)) {
        t = substr(h, RSTART + 1, RLENGTH); sub(/\]\(.*/, "", t)
        h = substr(h, 1, RSTART - 1) t substr(h, RSTART + RLENGTH)
    }
    gsub(/<[^>]*>/, "", h)
    h = tolower(h)
    gsub(/[!-,.\/:-@[-^`{-~]/, "", h)
    gsub(/ /, "-", h)
    return h
}
# Reads the headings of page once, into ANCHOR[page, anchor].
function anchors(page,   line, fenced, s, seen) {
    if (page in READ) return
    READ[page] = 1
    while ((getline line <page) > 0) {
        if (line ~ /^ *(```|~~~)/) { fenced = !fenced; continue }
        if (fenced || line !~ /^#+ /) continue
        s = slug(line)
        ANCHOR[page, seen[s] ? s "-" seen[s] : s] = 1
        seen[s]++
    }
    close(page)
}
# The path of target, relative to the top, for a link in the folder dir.
function resolve(dir, target,   n, k, part, m, out, path) {
    n = split(dir "/" target, part, "/")
    m = 0
    for (k = 1; k <= n; k++) {
        if (part[k] == "" || part[k] == ".") continue
        if (part[k] == "..") { if (m == 0) return ""; m--; continue }
        out[++m] = part[k]
    }
    path = ""
    for (k = 1; k <= m; k++) path = path (k > 1 ? "/" : "") out[k]
    return path
}
function exists(path) {
    if (!(path in EXISTS)) EXISTS[path] = system("test -e \"" path "\"") == 0
    return EXISTS[path]
}
function dead(text) { print FILENAME ":" FNR ": " text; bad++ }
FNR == 1 { fenced = 0; dir = FILENAME; if (!sub(/\/[^\/]*$/, "", dir)) dir = "." }
/^ *(```|~~~)/ { fenced = !fenced; next }
fenced { next }
{
    line = $0
    gsub(/`[^`]*`/, "", line)
    while (match(line, /\]\([^)]*\)/)) {
        target = substr(line, RSTART + 2, RLENGTH - 3)
        line = substr(line, RSTART + RLENGTH)
        sub(/[ \t].*/, "", target)
        if (target == "" || target ~ /^[a-zA-Z][a-zA-Z+.-]*:/) continue
        links++
        file = target; sub(/#.*/, "", file)
        anchor = substr(target, length(file) + 1); sub(/^#/, "", anchor)
        page = file == "" ? FILENAME : resolve(dir, file)
        if (page == "") { dead("the link " target " leads out of the repository"); continue }
        if (!exists(page)) { dead("the link " target ": no file " page); continue }
        if (anchor == "" || page !~ /\.md$/) continue
        anchors(page)
        if (!((page, anchor) in ANCHOR)) dead("the link " target ": no heading #" anchor " in " page)
    }
}
END {
    if (bad) { print "links: " bad " dead links"; exit 1 }
    print "links: " links " relative links in " ARGC - 1 " pages, each to a file that exists (and its heading)"
}' "$@"
