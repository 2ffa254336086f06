#!/bin/sh
# doctables.sh: writes the docs' tables that are made from the source, or checks that they are current.
#
# Usage: tools/doctables.sh --update|--check
# Each table stands in its doc between  <!-- generated: NAME -->  and  <!-- end generated -->:
#   marked-functions  docs/starters.md: the functions each part's students write, from
#                     the starter markers (tools/marked.sh list)
#   reading-load      docs/architecture.md: each part's own lines, code and comments, and
#                     the lines of the earlier parts it uses (its Makefile's USES)
# --check exits 1, naming the doc, when a table is not what the source makes now.
set -u
top=$(cd "$(dirname "$0")/.." && pwd) || exit 2
case ${1:-} in
--update | --check) mode=${1#--} ;;
*) echo "usage: $0 --update|--check" >&2; exit 2 ;;
esac
cd "$top" || exit 2
tmp=$(mktemp -d) || exit 2
trap 'rm -rf "$tmp"' EXIT

# The marked functions, a row a part: | 1.2 | `plane_intersect` (plane.c), ... |
marked_functions() {
    echo "| part | the functions a student writes (file) |"
    echo "|---|---|"
    tools/marked.sh list | awk '
        { part = $1; sub(/-.*/, "", part); file = $2; sub(/.*\//, "", file)
          if (part != last) { if (last != "") print row " |"; row = "| " part " | "; sep = ""; last = part }
          row = row sep "`" $4 "` (" file ")"; sep = ", " }
        END { if (last != "") print row " |" }'
}

# Prints "TOTAL CODE COMMENT" for the C files given: lines in all, lines with code,
# lines of comment alone (blank lines count in the total only).
count_lines() {
    cat "$@" | awk '
        { line = $0; code = 0; comment = 0
          while (length(line) > 0) {
              if (in_comment) {
                  comment = 1; end = index(line, "*/")
                  if (end == 0) { line = ""; break }
                  line = substr(line, end + 2); in_comment = 0
              } else {
                  start = index(line, "/*")
                  before = start == 0 ? line : substr(line, 1, start - 1)
                  if (before ~ /[^ \t]/) code = 1
                  if (start == 0) break
                  line = substr(line, start + 2); in_comment = 1
              }
          }
          total++; if (code) codes++; else if (comment) comments++ }
        END { print total + 0, codes + 0, comments + 0 }'
}

# The reading load of each part: its own lines, and the earlier parts' it links.
reading_load() {
    echo "| part | its own lines | code | comments | lines of the earlier parts it uses | in all |"
    echo "|---|---|---|---|---|---|"
    for dir in milestones/*/; do
        part=$(basename "$dir")
        set -- "$dir"*.c "$dir"*.h
        count_lines "$@" >"$tmp/$part.count"
        read -r total code comments <"$tmp/$part.count"
        uses=$(sed -n 's/^USES[[:space:]]*:=[[:space:]]*//p' "$dir/Makefile")
        earlier=0
        for used in $uses; do
            read -r used_total _ <"$tmp/$used.count" || { echo "doctables: $part uses $used, which comes later" >&2; exit 1; }
            earlier=$((earlier + used_total))
        done
        echo "| ${part%%-*} | $total | $code | $comments | $earlier | $((total + earlier)) |"
    done
}

# Replaces the table NAME of doc with what stands in file new; --check compares instead.
status=0
put() {
    doc=$1 name=$2 new=$3
    grep -q "^<!-- generated: $name -->\$" "$doc" ||
        { echo "$doc: no '<!-- generated: $name -->' line for the table" >&2; status=1; return; }
    awk -v name="$name" -v new="$new" '
        $0 == "<!-- generated: " name " -->" { print; while ((getline l <new) > 0) print l; skip = 1; next }
        skip && $0 == "<!-- end generated -->" { skip = 0 }
        !skip' "$doc" >"$tmp/doc"
    if cmp -s "$tmp/doc" "$doc"; then return; fi
    if [ "$mode" = check ]; then
        echo "$doc: the table '$name' is not what the source makes now; run 'make docs'" >&2
        status=1
    else
        cp "$tmp/doc" "$doc" && echo "updated $doc ($name)"
    fi
}

marked_functions >"$tmp/marked" || exit 1
reading_load >"$tmp/load" || exit 1
put docs/starters.md marked-functions "$tmp/marked"
put docs/architecture.md reading-load "$tmp/load"
[ "$mode" = check ] && [ $status -eq 0 ] && echo "doctables: every generated table is current"
exit $status
