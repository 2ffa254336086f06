#!/bin/sh
# replace.sh: writes a part's source file with some of its marked functions' bodies replaced by a variant's.
#
# Usage: tests/bvh-variants/replace.sh VARIANT SOURCE
#   VARIANT  a C file of function definitions, each named as a marked function of the part
#            (book/marked.sh) and written as the starter markers delimit a body: the
#            signature, a line that is exactly "{", the body, a line that is exactly "}"
#   SOURCE   one of the part's C files
# Prints SOURCE with the body of each of its marked functions that VARIANT defines replaced
# by VARIANT's body; signatures, comments and every other line are kept. The functions are
# found by name, as book/starter.sh finds them, so a variant keeps working while the code
# around them changes. Exit status 2 when VARIANT defines a function that no marked function
# of any file of SOURCE's folder is named after (the name changed: the variant must follow).
set -u
[ $# -eq 2 ] || { echo "usage: $0 VARIANT SOURCE" >&2; exit 2; }
variant=$1 source=$2
marked=$(cat "$(dirname "$source")"/*.c | awk -v ORS=' ' '
/^\/\* starter: todo/ { s = 1; next }
s && /\(/ && $0 !~ /^[ \t]*(\/\*|\*)/ { l = $0; sub(/\(.*/, "", l); n = split(l, w, /[ \t*]+/); print w[n]; s = 0 }')
awk -v marked=" $marked " -v vfile="$variant" '
# The name of the function whose signature starts on this line, or "".
function name_of(line,    n, w) {
    if (line !~ /\(/ || line ~ /^[ \t]*(\/\*|\*|#)/ || line ~ /^[ \t]/) return ""
    sub(/\(.*/, "", line); n = split(line, w, /[ \t*]+/); return w[n]
}
FNR == NR {
    if (state == "" && (nm = name_of($0)) != "") { state = "signature"; name = nm; next }
    if (state == "signature" && $0 == "{") { state = "body"; body[name] = ""; next }
    if (state == "body" && $0 == "}") { state = ""; if (index(marked, " " name " ") == 0) {
        printf "%s: %s is not a marked function of the part (book/marked.sh list)\n", vfile, name >"/dev/stderr"; bad = 1 }
        next }
    if (state == "body") body[name] = body[name] $0 "\n"
    next
}
bad { exit 2 }
/^\/\* starter: todo/ { marker = 1 }
marker && state == "" && (nm = name_of($0)) != "" { state = "signature"; name = nm; marker = 0 }
state == "signature" && $0 == "{" { print; state = (name in body) ? "skip" : ""; if (state == "skip") printf "%s", body[name]; next }
state == "skip" && $0 == "}" { print; state = ""; next }
state == "skip" { next }
{ print }
END { exit bad ? 2 : 0 }
' "$variant" "$source"
