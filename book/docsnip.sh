#!/bin/sh
# docsnip: replaces each excerpt region of Markdown docs with the named excerpt of a source file.
#
# Usage: docsnip [--root DIR] --check|--update DOC.md...   docsnip --list SOURCE...
# A source marks an excerpt with lines holding only  /* excerpt: NAME */ ... /* end excerpt:
# NAME */  (or # excerpt: NAME); a doc quotes it between  <!-- excerpt: PATH NAME -->  and
# <!-- end excerpt -->, which docsnip fills with a fenced block and the caption *From PATH*.
# A C file needs no marker for a whole definition: NAME may name a function, a type (its
# typedef, or the struct T { ... }; of a typedef struct T NAME;) or a macro, quoted whole with
# the comment just above it, never a declaration; several names quote several, in turn.
# --definitions FILE NAME... prints those definitions of FILE as they stand, NAME: for a
# function's contract alone (its comment and signature); book/doctables.sh counts them.
# Exit status: 0 when all is well, 1 when a problem was found, 2 for bad usage.
usage() { echo "docsnip: $1" >&2; echo "Try 'docsnip --help'." >&2; exit 2; }
mode="" root=.
while [ $# -gt 0 ]; do
    case $1 in
    -h | --help) sed -n '2,13s/^# \{0,1\}//p' "$0"; exit 0 ;;
    --check | --update | --list | --definitions)
        [ -z "$mode" ] || usage "choose one of --check, --update, --list and --definitions"; mode=${1#--} ;;
    --root) [ $# -gt 1 ] || usage "--root needs a folder"; root=$2; shift ;;
    --root=*) root=${1#--root=} ;;
    --) shift; break ;;
    -*) usage "unknown option $1" ;;
    *) break ;;
    esac
    shift
done
[ -n "$mode" ] || usage "say what to do: --check, --update, --list or --definitions"
[ $# -gt 0 ] || usage "no files given"
new=$(mktemp) || exit 1
trap 'rm -f "$new"' EXIT
trap 'exit 1' HUP INT TERM

# The awk program: reads sources and one doc (or lists one source); exit 1 on a problem,
# 3 when the doc's new text (written to $new) differs from the old.
program='
function problem(where, line, text) { print where (line ? ":" line : "") ": " text >"/dev/stderr"; problems++ }
function source_problem(path, line, text) { problem(path, line, text); STATE[path] = "bad" }
# Returns "open", "close", "bad" for the words of a marker comment, "" for another comment;
# sets MPATH and MNAME. In a doc an open marker takes PATH NAME..., each the name of an excerpt
# or a C identifier, and MNAME holds them all; in a source, it takes one excerpt NAME.
function marker(body, doc,   w, n, k, i, re) {
    n = split(body, w, " "); k = w[1] == "end" ? 2 : 1
    if (n < k || (w[k] != "excerpt" && substr(w[k], 1, 8) != "excerpt:")) return ""
    if (doc && k == 2) return n == 2 && w[2] == "excerpt" ? "close" : "bad"
    if (w[k] != "excerpt:" || n < k + 1 + doc || (!doc && n > k + 1)) return "bad"
    MPATH = w[k + 1]; MNAME = ""
    re = doc ? "^([a-z0-9-]+|[A-Za-z_][A-Za-z0-9_]*)$" : "^[a-z0-9-]+$"
    for (i = k + 1 + doc; i <= n; i++) {
        if (w[i] !~ re || length(w[i]) > 64) return "bad"
        MNAME = MNAME (MNAME == "" ? "" : " ") w[i]
    }
    return k == 2 ? "close" : "open"
}
function trim(s) { sub(/^[ \t]+/, "", s); sub(/[ \t]+$/, "", s); return s }
# Returns the kind of marker the source line t is: a comment holding nothing else.
function source_marker(t) {
    t = trim(t)
    if (substr(t, 1, 1) == "#") return marker(substr(t, 2), 0)
    if (substr(t, 1, 2) == "/*" && length(t) >= 4 && substr(t, length(t) - 1) == "*/") return marker(substr(t, 3, length(t) - 4), 0)
    return ""
}
# Reads the source at path (relative to the root) once, finding its excerpts and reporting
# markers that do not pair up; returns "ok", "bad" (marker errors) or why it cannot be read.
function load(path,   file, line, n, st, kind, key) {
    if (path in STATE) return STATE[path]
    file = root "/" path; n = 0; STATE[path] = "ok"
    while ((st = (getline line <file)) > 0) {
        sub(/\r$/, "", line); SRC[path, ++n] = line; NL[path] = n
        if ((kind = source_marker(line)) == "") continue
        ISM[path, n] = 1; key = path SUBSEP MNAME
        if (kind == "bad") source_problem(path, n, "malformed excerpt marker: the comment must hold '\''excerpt: NAME'\'' or '\''end excerpt: NAME'\'', NAME made of a-z, 0-9 and '\''-'\''")
        else if (kind == "open" && key in OPEN) source_problem(path, n, "excerpt '\''" MNAME "'\'' is defined twice (first on line " OPEN[key] ")")
        else if (kind == "open") { OPEN[key] = n; NAMES[path, ++COUNT[path]] = MNAME }
        else if (!(key in OPEN) || key in CLOSE) source_problem(path, n, "end of excerpt '\''" MNAME "'\'', which was never opened")
        else CLOSE[key] = n
    }
    close(file)
    if (st < 0) return STATE[path] = system("test -e \"" file "\"") ? "No such file or directory" : "Permission denied"
    for (n = 1; n <= COUNT[path]; n++)
        if (!((path, NAMES[path, n]) in CLOSE)) source_problem(path, OPEN[path, NAMES[path, n]], "excerpt '\''" NAMES[path, n] "'\'' is never closed")
    return STATE[path]
}
function common(a, b,   i) { for (i = 1; i <= length(a) && substr(a, i, 1) == substr(b, i, 1); i++); return substr(a, 1, i - 1) }
# Prepares path for the C definition finder, once. CODE holds each line with its comments,
# strings and character constants blanked; DIR marks the lines of preprocessor directives,
# DIRSTART their first lines; TOP the other lines that begin in column 0 outside any
# comment, braces or parentheses. Then reads each typedef: TDEND is its last line, TDNAMES
# the names it defines (" A B "); one that only names a struct, typedef struct T X; (a
# forward declaration when X is T), defines nothing but makes ALIAS[path, X] = T.
function prepare(path,   n, line, code, tok, incom, dir, depth, paren, c, tag) {
    if (path in PREP) return
    PREP[path] = 1
    for (n = 1; n <= NL[path]; n++) {
        line = SRC[path, n]; code = ""
        if (dir || (!incom && line ~ /^[ \t]*#/)) { DIR[path, n] = 1; if (!dir) DIRSTART[path, n] = 1 }
        else if (!incom && !depth && !paren && line ~ /^[A-Za-z_]/) TOP[path, n] = 1
        dir = ((path, n) in DIR) && line ~ /\\$/
        while (line != "") {
            if (incom) { if (!(c = index(line, "*/"))) break; line = substr(line, c + 2); code = code " "; incom = 0; continue }
            if (!match(line, /\/[*\/]|["'\'']/)) { code = code line; break }
            code = code substr(line, 1, RSTART - 1); tok = substr(line, RSTART, RLENGTH); line = substr(line, RSTART + RLENGTH)
            if (tok == "//") break
            if (tok == "/*") { incom = 1; code = code " "; continue }
            while (match(line, tok == "\"" ? "[\\\\\"]" : "[\\\\'\'']") && substr(line, RSTART, 1) == "\\") line = substr(line, RSTART + 2)
            line = RSTART ? substr(line, RSTART + 1) : ""; code = code tok tok
        }
        CODE[path, n] = code
        if ((path, n) in DIR) continue
        c = code; depth += gsub(/[{]/, "", c) - gsub(/[}]/, "", c); paren += gsub(/[(]/, "", c) - gsub(/[)]/, "", c)
    }
    for (n = 1; n <= NL[path]; n++) {
        if (!((path, n) in TOP) || CODE[path, n] !~ /^typedef([^A-Za-z0-9_]|$)/ || !scan(path, n)) continue
        TDEND[path, n] = SEND; sub(/^typedef[ \t]+((const|volatile)[ \t]+)*/, "", SHEAD); tag = tagof(SHEAD)
        if (SBRACE) TDNAMES[path, n] = declared(STAIL) (SHEAD ~ TAGONLY ? tag " " : "")
        else if (tag != "" && (c = declared(SHEAD)) ~ /^ [A-Za-z_][A-Za-z0-9_]* $/ && SHEAD ~ ("[ \t]" substr(c, 2, length(c) - 2) "[ \t]*$")) {
            c = substr(c, 2, length(c) - 2); if (!((path, c) in ALIAS)) ALIAS[path, c] = tag
        } else TDNAMES[path, n] = declared(SHEAD)
    }
}
# Returns T when text begins with struct T, union T or enum T, "" otherwise.
function tagof(text) {
    if (!match(text, /^(struct|union|enum)[ \t]+[A-Za-z_][A-Za-z0-9_]*/)) return ""
    text = substr(text, 1, RLENGTH); sub(/^[a-z]+[ \t]+/, "", text); return text
}
# Reads the declaration or definition that begins on line i of path, to its ";" or the
# brace that closes a function'\''s body: sets SEND to its last line and returns it (0 when
# it has no end), sets SBRACE to the line of its first outer "{" (0 when none), SFN when
# those braces are a function'\''s body, SHEAD and STAIL to its outer text before and after.
function scan(path, i,   n, c, t, ch, depth, paren) {
    SEND = SBRACE = SFN = 0; SHEAD = STAIL = ""
    for (n = i; n <= NL[path]; n++) {
        if ((path, n) in DIR) continue
        for (c = CODE[path, n] " "; c != ""; ) {
            if (match(c, /[{}();]/)) { ch = substr(c, RSTART, 1); t = substr(c, 1, RSTART - 1); c = substr(c, RSTART + 1) }
            else { ch = ""; t = c; c = "" }
            if (ch == "(" || ch == ")") { t = t ch; paren += ch == "(" ? 1 : -1 }
            if (!depth) { if (SBRACE) STAIL = STAIL t; else SHEAD = SHEAD t }
            if (ch == "{" && !depth++ && !SBRACE) { SBRACE = n; SFN = SHEAD ~ /[(]/ && SHEAD !~ /=/ && SHEAD !~ /^typedef/ }
            else if (ch == "}" && --depth <= 0) { if (depth < 0) return 0; if (SFN) return SEND = n }
            else if (ch == ";" && !depth && !paren) return SEND = n
        }
    }
    return 0
}
# Returns the names the declarators of text declare, as " A B ": in each, the name after
# the "(*" of a pointer to a function, or else the last name before any "(" or "[".
function declared(text,   names, d, ch, k, paren) {
    names = " "
    for (k = 1; k <= length(text) + 1; k++) {
        ch = k <= length(text) ? substr(text, k, 1) : ","
        if (ch == "(") paren++; else if (ch == ")") paren--
        if (ch != "," || paren) { d = d ch; continue }
        if (match(d, /[(][ \t]*[*][ \t*]*/)) { d = substr(d, RSTART + RLENGTH); while (sub(/^(const|volatile|restrict)[ \t]+/, "", d)); }
        else { sub(/[[(].*/, "", d); d = match(d, /[A-Za-z_][A-Za-z0-9_]*[ \t]*$/) ? substr(d, RSTART) : "" }
        if (match(d, /^[A-Za-z_][A-Za-z0-9_]*/)) names = names substr(d, 1, RLENGTH) " "
        d = ""
    }
    return names
}
# Returns the name a function'\''s head declares: the one before its last outer "(", past
# any macro before it, as in static void PRINTF_LIKE(1, 2) say(const char *fmt, ...).
function fname(head,   k, ch, paren, at) {
    for (k = 1; k <= length(head); k++)
        if ((ch = substr(head, k, 1)) == "(" && !paren++) at = k
        else if (ch == ")") paren--
    head = substr(head, 1, at - 1); sub(/[ \t]+$/, "", head)
    return match(head, /[A-Za-z_][A-Za-z0-9_]*$/) ? substr(head, RSTART) : ""
}
# Finds the C definition of name in path with the comment just above it, the first of: a
# function with its body; a macro with its continued lines; a typedef whose own name is
# name (of a struct, union or enum with its braces, of a pointer to a function, ...); a
# struct, union or enum T { ... }; whose T is name, or T of a typedef struct T name;.
# Declarations are passed over: a prototype, struct T;, typedef struct T T;. Sets DFROM
# and DTO to its first and last lines and DBODY to the line of the "{" of a function (past
# DTO otherwise), or returns why it cannot.
function definition(path, name,   i, t, from, to, body, tag, h) {
    if (name !~ /^[A-Za-z_][A-Za-z0-9_]*$/) return "no definition of " name
    prepare(path)
    tag = (path, name) in ALIAS ? ALIAS[path, name] : name
    for (i = 1; i <= NL[path] && !to; i++) {
        t = CODE[path, i]
        if ((path, i) in DIRSTART) {
            if (sub(/^[ \t]*#[ \t]*define[ \t]+/, "", t) && match(t, /^[A-Za-z_][A-Za-z0-9_]*/) && substr(t, 1, RLENGTH) == name)
                for (from = to = i; to < NL[path] && SRC[path, to] ~ /\\$/; to++);
        } else if (!((path, i) in TOP)) continue
        else if ((path, i) in TDEND) { if (index(TDNAMES[path, i], " " name " ")) { from = i; to = TDEND[path, i] } }
        else if ((h = tagof(t)) != "" && (h == name || h == tag) && scan(path, i) && SBRACE && !SFN && SHEAD ~ TAGONLY) { from = i; to = SEND }
        else if (t ~ ("(^|[^A-Za-z0-9_])" name "[ \t]*[(]") && scan(path, i) && SFN && fname(SHEAD) == name) {
            from = i; to = SEND; body = SBRACE + (CODE[path, SBRACE] !~ /^[ \t]*[{][ \t]*$/)
        }
    }
    if (!to) return "no definition of " name
    DFROM = from; DTO = to; DBODY = body ? body : to + 1
    if (from > 1 && SRC[path, from - 1] ~ /\*\/[ \t]*$/ && SRC[path, from - 1] !~ /^\/\* starter:/ && !((path, from - 1) in ISM))
        for (DFROM = from - 1; DFROM > 1 && SRC[path, DFROM] !~ /^\/\*/; DFROM--);
    for (i = DFROM; i < from; i++) if (CODE[path, i] ~ /[^ \t]/ || ((path, i) in DIR)) DFROM = from
    return ""
}
# Appends the lines of excerpt or definition name of path to PICK (0 a blank line between two).
function pick(path, name,   i) {
    if (NPICK) PICK[++NPICK] = 0
    if ((path, name) in OPEN) for (i = OPEN[path, name] + 1; i < CLOSE[path, name]; i++) PICK[++NPICK] = i
    else for (i = DFROM; i <= DTO; i++) PICK[++NPICK] = i
}
# Returns what a region quoting the lines of PICK from path holds: those lines but markers,
# less the indentation their non-blank lines share, fenced by more backticks than any run.
function block(path,   i, k, t, indent, seen, code, s, longest, fence, lang) {
    for (k = 1; k <= NPICK; k++)
        if ((i = PICK[k]) && !((path, i) in ISM) && SRC[path, i] !~ /^[ \t]*$/) {
            match(SRC[path, i], /^[ \t]*/); s = substr(SRC[path, i], 1, RLENGTH)
            indent = seen++ ? common(indent, s) : s
        }
    for (k = 1; k <= NPICK; k++)
        if (!(i = PICK[k])) code = code "\n"
        else if (!((path, i) in ISM)) code = code substr(SRC[path, i], length(common(SRC[path, i], indent)) + 1) "\n"
    for (s = code; match(s, /`+/); s = substr(s, RSTART + RLENGTH)) if (RLENGTH > longest) longest = RLENGTH
    for (fence = "``"; length(fence) <= longest || length(fence) < 3; ) fence = fence "`"
    lang = path ~ /\.[ch]$/ ? "c" : path ~ /\.sh$/ ? "sh" : path ~ /(\.mk|(^|\/)(GNU)?[Mm]akefile)$/ ? "make" : ""
    return fence lang "\n" code fence "\n*From " path "*\n"
}
# Follows the doc'\''s fenced code blocks; tells whether line t (number i) is in one.
function fenced(t, i,   lead, c, run, rest) {
    while (lead < 3 && substr(t, lead + 1, 1) == " ") lead++
    c = substr(t, lead + 1, 1); if (c != "`" && c != "~") c = ""
    while (c != "" && substr(t, lead + run + 1, 1) == c) run++
    rest = substr(t, lead + run + 1)
    if (FMARK != "") { if (c == FMARK && run >= FLEN && rest ~ /^[ \t]*$/) FMARK = ""; return 1 }
    if (run < 3 || (c == "`" && index(rest, "`"))) return 0
    FMARK = c; FLEN = run; FLINE = i; return 1
}
# Checks the region opened on line o and closed on line e, or brings it up to date.
function region(o, e, path, names,   i, n, w, have, want, st, why) {
    for (i = o + 1; i < e; i++) have = have L[i] "\n"
    if (path !~ /^[A-Za-z0-9._\/-]+$/ || path ~ /^\// || ("/" path "/") ~ /\/\.\.\// || length(path) > 1024)
        return problem(doc, o, "excerpt path '\''" path "'\'' must be relative to the root, without '\''..'\'', made of letters, digits, '\''.'\'', '\''_'\'', '\''-'\'' and '\''/'\''")
    st = load(path)
    if (st != "ok" && st != "bad") return problem(doc, o, "cannot read " path ": " st)
    if (st == "bad") return problem(doc, o, "excerpt '\''" names "'\'' cannot be used: " path " has marker errors (above)")
    n = split(names, w, " "); NPICK = 0
    for (i = 1; i <= n; i++) {
        why = w[i] ~ /^[A-Za-z_][A-Za-z0-9_]*$/ ? definition(path, w[i]) : "no excerpt"
        if ((path, w[i]) in OPEN && why == "") return problem(doc, o, "'\''" w[i] "'\'' is both an excerpt and a definition in " path)
        if (!((path, w[i]) in OPEN) && why != "") return problem(doc, o, "no excerpt or definition '\''" w[i] "'\'' in " path)
        pick(path, w[i])
    }
    if (have == (want = block(path))) return
    if (mode == "check") return problem(doc, o, "excerpt '\''" names "'\'' from " path " is stale; run '\''make docs'\''")
    gsub(/\n/, E[o], want); OUT[o] = L[o] E[o] want; changed = 1
    for (i = o + 1; i < e; i++) OUT[i] = ""
}
BEGIN { TAGONLY = "^(struct|union|enum)[ \t]+[A-Za-z_][A-Za-z0-9_]*[ \t]*$" }
{ E[NR] = sub(/\r$/, "") ? "\r\n" : "\n"; L[NR] = $0 }
END {
    if (defs != "") {
        if ((st = load(defs)) != "ok" && st != "bad") problem("docsnip", 0, "cannot read " defs ": " st)
        n = split(names, w, " ")
        for (k = 1; k <= n && st != "" && !problems; k++) {
            contract = sub(/:$/, "", w[k])
            if ((why = definition(defs, w[k])) != "") problem(defs, 0, why)
            else for (i = DFROM; i <= (contract ? DBODY - 1 : DTO); i++) if (!((defs, i) in ISM)) print SRC[defs, i]
        }
        exit problems > 0
    }
    if (list != "") {
        if ((st = load(list)) != "ok" && st != "bad") problem("docsnip", 0, "cannot read " list ": " st)
        for (i = 1; i <= COUNT[list]; i++) print list ":" OPEN[list, NAMES[list, i]] ": " NAMES[list, i]
        exit problems > 0
    }
    if (noeol) E[NR] = ""
    for (i = 1; i <= NR; i++) {
        OUT[i] = L[i] E[i]; t = trim(L[i])
        if (fenced(L[i], i) || substr(t, 1, 4) != "<!--" || substr(t, length(t) - 2) != "-->") continue
        kind = marker(substr(t, 5, length(t) - 7), 1)
        if (kind == "bad") problem(doc, i, "malformed excerpt marker: write '\''<!-- excerpt: PATH NAME... -->'\'' and '\''<!-- end excerpt -->'\'', each NAME an excerpt'\''s (a-z, 0-9 and '\''-'\'') or a C function'\''s or type'\''s")
        else if (kind == "open") { if (open) problem(doc, open, "excerpt region not closed"); open = i; path = MPATH; name = MNAME }
        else if (kind == "close" && !open) problem(doc, i, "end of an excerpt region never opened")
        else if (kind == "close") { region(open, i, path, name); open = 0 }
    }
    if (open) problem(doc, open, "excerpt region not closed" (FMARK != "" ? " (its code fence on line " FLINE " is not closed either)" : ""))
    else if (FMARK != "") problem(doc, FLINE, "code fence not closed: any excerpt marker after it is unseen")
    for (i = 1; i <= NR; i++) printf "%s", OUT[i] >out
    exit problems ? 1 : changed ? 3 : 0
}'

if [ "$mode" = definitions ]; then
    file=$1; shift
    awk -v root=. -v defs="$file" -v names="$*" "$program" </dev/null
    exit
fi
status=0
for file; do
    if [ "$mode" = list ]; then
        awk -v root=. -v list="$file" "$program" </dev/null || status=1
        continue
    fi
    if [ ! -r "$file" ] || [ -d "$file" ]; then
        echo "docsnip: cannot read $file: $( [ -e "$file" ] && echo Permission denied || echo No such file or directory)" >&2
        status=1
        continue
    fi
    noeol=0
    [ -s "$file" ] && [ "$(tail -c 1 "$file" | od -An -c | tr -d ' ')" != '\n' ] && noeol=1
    awk -v root="$root" -v doc="$file" -v mode="$mode" -v out="$new" -v noeol=$noeol "$program" "$file"
    case $? in
    0) ;;
    3)  # Replaced whole through a temporary beside the real file, which keeps its mode;
        # a symbolic link stays a link.
        real=$(readlink -f -- "$file")
        if ! temp=$(mktemp "$real.docsnip-XXXXXX" 2>&1); then
            echo "docsnip: cannot write $file: ${temp##*: }" >&2
            status=1
        elif cp -p -- "$real" "$temp" && cat "$new" >"$temp" && mv -f -- "$temp" "$real"; then
            echo "updated $file"
        else
            rm -f "$temp"
            echo "docsnip: cannot write $file" >&2
            status=1
        fi ;;
    *)  [ "$mode" = update ] && echo "$file: not updated because of the problems above" >&2
        status=1 ;;
    esac
done
exit $status
