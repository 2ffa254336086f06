#!/bin/sh
# studentreads.sh: the table "What a student reads" of a part: every definition its students' functions name.
#
# Usage: book/studentreads.sh PART   (book/doctables.sh writes it into docs/PART.md)
#
# The functions a part's students write (book/marked.sh list) name types, macros and other
# functions. Each of those the part or an earlier one it uses (its Makefile's USES), or
# common/, defines is a row of the table, under the file that defines it:
#   read whole        the student's functions themselves; the types (typedefs, structs,
#                     enums: an enumerator stands for its enum's type) and macros they
#                     name; the part's own file-local (static) functions they call
#   read the contract of   every other function they call: its comment and signature
# A definition a header only declares is listed at its definition. The table is made from
# the code (universal-ctags finds the definitions), so that nothing a TODO needs is missing.
case ${1:-} in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
set -u
[ $# -eq 1 ] || { echo "usage: $0 PART" >&2; exit 2; }
top=$(cd "$(dirname "$0")/.." && pwd) || exit 2
cd "$top" || exit 2
part=$1
[ -f "milestones/$part/Makefile" ] || { echo "studentreads: no part $part" >&2; exit 2; }
command -v ctags >/dev/null 2>&1 && ctags --version 2>/dev/null | grep -q 'Universal Ctags' ||
    { echo "studentreads: needs universal-ctags (Debian: universal-ctags)" >&2; exit 2; }
tmp=$(mktemp -d) || exit 2
trap 'rm -rf "$tmp"' EXIT

# The files of the part, of the parts it uses, and of common/, in that order.
uses=$(sed -n 's/^USES[[:space:]]*:=[[:space:]]*//p' "milestones/$part/Makefile")
folders="milestones/$part"
for used in $uses; do folders="$folders milestones/$used"; done
files=$(for folder in $folders common; do ls "$folder"/*.h "$folder"/*.c 2>/dev/null; done)

# Every definition: NAME KIND LINE FILE s=SCOPE t=TYPEREF and its line of source.
# shellcheck disable=SC2086 # one word a file
ctags -x --c-kinds=+pe --fields=+t --_xformat='%N %K %n %F s=%s t=%t %C' $files >"$tmp/tags" ||
    exit 1

# The text of the part's marked functions, from their signature to their closing brace,
# comments and strings left out; and their names.
book/marked.sh list | awk -v part="$part" '$1 == part { print $2, $3, $4 }' >"$tmp/marked"
[ -s "$tmp/marked" ] || { echo "studentreads: part $part marks no function" >&2; exit 1; }
while read -r file line _; do
    awk -v from="$line" 'FNR >= from { print } FNR > from && $0 == "}" { exit }' "$file"
done <"$tmp/marked" | sed -e 's|/\*.*\*/||g' -e 's|"[^"]*"||g' >"$tmp/text"

# The rows: FILE NAME whole|contract, in the order of the files, then of the lines.
awk -v part_dir="milestones/$part/" '
    FILENAME == ARGV[1] { marked[$3] = 1; next }
    FILENAME == ARGV[2] {
        # The tags: a definition wins over a prototype of the same name.
        name = $1; kind = $2
        if (kind == "prototype") { if (!(name in kindof)) proto[name] = $4 " " $3; next }
        if (kind == "enum" || kind == "struct" || kind == "member" || kind == "local") {
            if (kind == "enum" || kind == "struct") anon_line[name] = $4 " " $3
            next
        }
        if (kind == "macro" && name ~ /_H$/) next
        kindof[name] = kind; where[name] = $4; line[name] = $3
        file_local[name] = $7 == "static"; scope[name] = substr($5, 3); typeref[name] = substr($6, 3)
        next
    }
    { while (match($0, /[A-Za-z_][A-Za-z0-9_]*/)) {
          used[substr($0, RSTART, RLENGTH)] = 1; $0 = substr($0, RSTART + RLENGTH) } }
    END {
        # An anonymous enum or struct stands under the typedef that names it.
        for (n in kindof) if (kindof[n] == "typedef" && typeref[n] ~ /:__anon/) {
            t = typeref[n]; sub(/^[a-z]*:/, "", t); typedef_of[t] = n }
        for (n in used) {
            if (n in kindof) k = kindof[n]
            else if (n in proto) { split(proto[n], p, " "); k = "function"; where[n] = p[1]; line[n] = p[2] }
            else continue
            how = "contract"
            if (n in marked) how = "whole"
            else if (k == "typedef" || k == "macro" || k == "enumerator") how = "whole"
            else if (k == "function" && file_local[n] && index(where[n], part_dir) == 1) how = "whole"
            if (k == "enumerator") {
                if (!(scope[n] in typedef_of)) continue
                n2 = typedef_of[scope[n]]; print where[n2], line[n2], n2, how; continue
            }
            print where[n], line[n], n, how
        }
        for (n in marked) if (n in where) print where[n], line[n], n, "whole"
    }' "$tmp/marked" "$tmp/tags" "$tmp/text" | sort -u >"$tmp/rows"

# The table: a row a file, the part's own files first, then the earlier parts', then common.
echo "| file | read whole | read the contract of |"
echo "|---|---|---|"
for folder in $folders common; do
    awk -v folder="$folder/" 'index($1, folder) == 1' \
        "$tmp/rows" | sort -k1,1 -k2,2n | awk '
        function flush() { if (file != "") printf "| `%s` | %s | %s |\n", file, whole, contract }
        $1 != file { flush(); file = $1; whole = ""; contract = "" }
        { name = "`" $3 "`"
          if ($4 == "whole" && index(" " whole " ", " " name " ") == 0) whole = whole (whole == "" ? "" : " ") name
          if ($4 == "contract" && index(" " contract " ", " " name " ") == 0) contract = contract (contract == "" ? "" : " ") name }
        END { flush() }'
done
