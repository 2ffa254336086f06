#!/usr/bin/awk -f
# mutate.awk: lists the mutants of a part's source file, or writes one: each a single small change
# to the body of a function the student writes (one marked "starter: todo").
#
# Usage: awk -f mutate.awk SOURCE            lists the mutants: K<tab>LINE<tab>WAS -> NOW
#        awk -v mutant=K -f mutate.awk SOURCE   writes SOURCE with mutant K applied
#
# A mutant changes one operator or constant as a wrong student might: a comparison made
# strict or not (< and <=, > and >=), == and != swapped, && and || swapped, + and -, * and /
# swapped (and their assignments), ++ and -- swapped, a ! or a unary - dropped, an integer
# constant 0 made 1 and any other made one more. Only code is changed, never a comment, a
# string or a preprocessor line; the bodies are found as book/starter.sh finds them: from
# the marker, the next line that is exactly "{" to the next that is exactly "}".

# Records a mutation site: on line LINE, column COL, the text WAS becomes NOW.
function site(col, was, now) {
    n++
    site_line[n] = FNR; site_col[n] = col; site_was[n] = was; site_now[n] = now
}

# Finds the sites of one line of a body: its code only, the state of an open comment kept.
function scan(s,    i, c, c2, c3, len, prev, tok, j) {
    len = length(s); prev = ""
    for (i = 1; i <= len; i++) {
        c = substr(s, i, 1); c2 = substr(s, i, 2); c3 = substr(s, i, 3)
        if (in_comment) {
            if (c2 == "*/") { in_comment = 0; i++ }
            continue
        }
        if (c2 == "/*") { in_comment = 1; i++; continue }
        if (c2 == "//") return
        if (c == " " || c == "\t") continue
        if (c == "\"" || c == "'") {
            for (j = i + 1; j <= len && substr(s, j, 1) != c; j++)
                if (substr(s, j, 1) == "\\") j++
            i = j; prev = "lit"; continue
        }
        if (c ~ /[A-Za-z_]/) {
            match(substr(s, i), /^[A-Za-z_][A-Za-z0-9_]*/)
            i += RLENGTH - 1; prev = "id"; continue
        }
        if (c ~ /[0-9]/ || (c == "." && substr(s, i + 1, 1) ~ /[0-9]/)) {
            match(substr(s, i), /^[0-9.]+([eE][-+]?[0-9]+)?[A-Za-z]*/)
            tok = substr(s, i, RLENGTH)
            if (tok ~ /^[0-9]+$/)
                site(i, tok, tok == "0" ? "1" : tok == "1" ? "0" : tok + 1)
            i += RLENGTH - 1; prev = "lit"; continue
        }
        # Operators, the longest first; a + - * is binary after an operand.
        if (c3 == "<<=" || c3 == ">>=") { i += 2; prev = "op"; continue }
        if (c2 == "->" || c2 == "<<" || c2 == ">>") { i++; prev = "op"; continue }
        if (c2 == "<=") { site(i, "<=", "<"); i++; prev = "op"; continue }
        if (c2 == ">=") { site(i, ">=", ">"); i++; prev = "op"; continue }
        if (c2 == "==") { site(i, "==", "!="); i++; prev = "op"; continue }
        if (c2 == "!=") { site(i, "!=", "=="); i++; prev = "op"; continue }
        if (c2 == "&&") { site(i, "&&", "||"); i++; prev = "op"; continue }
        if (c2 == "||") { site(i, "||", "&&"); i++; prev = "op"; continue }
        if (c2 == "++") { site(i, "++", "--"); i++; prev = "id"; continue }
        if (c2 == "--") { site(i, "--", "++"); i++; prev = "id"; continue }
        if (c2 == "+=") { site(i, "+=", "-="); i++; prev = "op"; continue }
        if (c2 == "-=") { site(i, "-=", "+="); i++; prev = "op"; continue }
        if (c2 == "*=") { site(i, "*=", "/="); i++; prev = "op"; continue }
        if (c2 == "/=") { site(i, "/=", "*="); i++; prev = "op"; continue }
        if (c == "<") { site(i, "<", "<="); prev = "op"; continue }
        if (c == ">") { site(i, ">", ">="); prev = "op"; continue }
        if (c == "!") { site(i, "!", ""); prev = "op"; continue }
        operand = prev == "id" || prev == "lit" || prev == "close"
        if (c == "+" && operand) { site(i, "+", "-"); prev = "op"; continue }
        if (c == "-") { site(i, "-", operand ? "+" : ""); prev = "op"; continue }
        if (c == "*" && operand) { site(i, "*", "/"); prev = "op"; continue }
        if (c == "/") { site(i, "/", "*"); prev = "op"; continue }
        prev = c == ")" || c == "]" ? "close" : "op"
    }
}

{ text[FNR] = $0 }
state == 0 && /^\/\* starter: todo(: .*)? \*\/$/ { state = 1; next }
state == 1 && $0 == "{" { state = 2; next }
state == 2 && $0 == "}" { state = 0; next }
state == 2 && $0 !~ /^[ \t]*#/ { scan($0) }

END {
    if (mutant == "") {
        for (k = 1; k <= n; k++)
            printf "%d\t%d\t%s -> %s\n", k, site_line[k], site_was[k],
                site_now[k] == "" ? "(nothing)" : site_now[k]
        exit 0
    }
    if (mutant < 1 || mutant > n) {
        printf "mutate.awk: no mutant %s (there are %d)\n", mutant, n > "/dev/stderr"
        exit 2
    }
    for (l = 1; l <= FNR; l++) {
        s = text[l]
        if (l == site_line[mutant])
            s = substr(s, 1, site_col[mutant] - 1) site_now[mutant] \
                substr(s, site_col[mutant] + length(site_was[mutant]))
        print s
    }
}
