#!/bin/sh
# marked.sh: the functions of the parts that students write, as their starter markers name them.
#
# Usage: book/marked.sh list            one line a marked function: PART FILE LINE NAME
#        book/marked.sh check-explain   fails, naming each, when a marked function's
#                                        body prints to --trace-pixel (calls explain_*):
#                                        the trace is told by the tracer's seams
# A function is marked by a line /* starter: todo */ before it (docs/starters.md); its
# body runs from the next line that is exactly "{" to the next that is exactly "}".
case ${1:-} in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
set -u
top=$(cd "$(dirname "$0")/.." && pwd) || exit 2
case ${1:-} in
list | check-explain) mode=$1 ;;
*) echo "usage: $0 list|check-explain" >&2; exit 2 ;;
esac
cd "$top" || exit 2
# shellcheck disable=SC2046 # one word a file
awk -v mode="$mode" '
FNR == 1 { state = "" }
/^\/\* starter: todo/ { state = "signature"; name = ""; next }
state == "signature" && name == "" && /\(/ && $0 !~ /^[ \t]*(\/\*|\*)/ {
    line = $0; sub(/\(.*/, "", line); n = split(line, w, /[ \t*]+/); name = w[n]; at = FNR
    part = FILENAME; sub(/^milestones\//, "", part); sub(/\/.*/, "", part)
    if (mode == "list") print part, FILENAME, at, name
    next
}
state == "signature" && $0 == "{" { state = "body"; next }
state == "body" && $0 == "}" { state = ""; next }
state == "body" && mode == "check-explain" && /explain/ {
    print FILENAME ":" FNR ": " name ", a function students write, prints to --trace-pixel; let a seam tell it" >"/dev/stderr"
    bad++
}
END { exit bad > 0 }
' $(ls milestones/*/*.c | sort)
