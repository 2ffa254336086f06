#!/bin/sh
# doctables.sh: writes the docs' tables that are made from the source, or checks that they are current.
#
# Usage: book/doctables.sh --update|--check
# Each table stands in its doc between  <!-- generated: NAME -->  and  <!-- end generated -->:
#   marked-functions  docs/starters.md: the functions each part's students write, from
#                     the starter markers (book/marked.sh list)
#   student-reads     docs/1.*.md: what a student reads to write the part's functions,
#                     from the code (book/studentreads.sh)
#   reading-load      docs/architecture.md: each part's own lines, code and comments, the
#                     lines of the earlier parts it uses (its Makefile's USES), and the
#                     lines of its student's path: the definitions its chapter's table
#                     "student-reads" names
#   output NAME       what a tool prints, from a real run on the repository's own files
#                     (the outputs below): the block stands as generated, fences included
# A block may stand indented, inside a list item: its lines get the marker's indent.
# The outputs run the built programs: BUILD (default build) names compare/'s and the parts'
# build folder, RAYTRA_PROGRAM (default raytra) a part's program in its folder.
# --check exits 1, naming the doc, when a table is not what the source makes now.
case ${1:-} in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
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
    book/marked.sh list | awk '
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

# Prints the number of lines on the student's path of chapter doc, or - when it has none:
# the rows of its table "What a student reads" | `FILE` | `WHOLE` ... | `CONTRACT` ... |
# (book/studentreads.sh makes it).
student_path() {
    grep -q '^<!-- generated: student-reads -->$' "$1" || { echo -; return; }
    sed -n '/^<!-- generated: student-reads -->$/,/^<!-- end generated -->$/p' "$1" | grep '^| `' |
        while IFS='|' read -r _ file whole contract _; do
            file=$(echo "$file" | tr -d '` ')
            names=$(echo "$whole" | tr -d '`')
            contracts=$(echo "$contract" | tr -d '`' | awk '{ for (k = 1; k <= NF; k++) printf " %s:", $k }')
            [ -f "$file" ] || { echo "$1: the student's path names $file, which does not exist" >&2; exit 1; }
            # The definitions and contracts as they stand, by docsnip (its --definitions).
            # shellcheck disable=SC2086 # one word a name
            sh book/docsnip.sh --definitions "$file" $names $contracts || exit 1
        done >"$tmp/path" || exit 1
    wc -l <"$tmp/path" | tr -d ' '
}

# The reading load of each part: its own lines, the earlier parts' it links, and the
# lines on its student's path.
reading_load() {
    echo "| part | its own lines | code | comments | lines of the earlier parts it uses | in all | the student's path |"
    echo "|---|---|---|---|---|---|---|"
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
        path=$(student_path "docs/$part.md") || exit 1
        echo "| ${part%%-*} | $total | $code | $comments | $earlier | $((total + earlier)) | $path |"
    done
}

# The tool outputs. Each runs a built program, from the top of the repository, on files
# the repository holds, and prints the block the doc shows: the command, when the doc
# shows it, and what the program printed. Fails, saying so, when a program is not built.
build=${BUILD:-build}
program=${RAYTRA_PROGRAM:-raytra}
built() {
    [ -x "$1" ] || { echo "doctables: no $1: build it first (make; make -C book/mistakes)" >&2; exit 1; }
}

# raytra's --trace-pixel on a scene: the command and the tree. Arguments: PART OPTIONS...
trace() {
    part=$1; shift
    built "milestones/$part/$program"
    echo '```'
    echo "\$ milestones/$part/raytra $*"
    # shellcheck disable=SC2068 # the options are words by design
    "milestones/$part/$program" $@ 2>&1 || { echo "doctables: raytra failed: $*" >&2; exit 1; }
    echo '```'
}

# The lines of standard input matching each pattern in turn, the first after the last
# found, with "  ..." where lines are left out.
pick() {
    awk -v patterns="$*" '
        BEGIN { n = split(patterns, p, "|"); k = 1 }
        k <= n && index($0, p[k]) { if (NR > last + 1) print "  ..."; print; last = NR; k++ }
        END { if (k <= n) { print "doctables: no line with \"" p[k] "\"" >"/dev/stderr"; exit 1 } }'
}

# A starter's make check on part 1.2's phong-sweep.png, rendered by part 1.2 with the
# specular highlight of a light behind the surface (docs/mistakes.md): into $tmp/check,
# its lines in $tmp/check.out, imgdiff's report in $tmp/check/out/check/phong-sweep.diff.txt.
starter_check() {
    [ -f "$tmp/check.out" ] && return
    mistake=book/mistakes/$build/raytra-specular-behind
    built "$mistake"
    built "compare/$build/imgdiff"
    mkdir -p "$tmp/check/part/references" "$tmp/check/tests" || exit 1
    echo "phong-sweep.png scenes/phong-sweep.scn" >"$tmp/check/part/references/renders.txt"
    cp milestones/1.2-shading/references/phong-sweep.png "$tmp/check/part/references/" || exit 1
    (cd "$tmp/check" && "$top/book/starter-check.sh" part "$top/$mistake" tests \
        "$top/compare/$build/imgdiff" out/check) >"$tmp/check.out" 2>&1
    grep -q '^FAIL phong-sweep.png: ' "$tmp/check.out" ||
        { echo "doctables: the starter check did not fail phong-sweep.png:" >&2; cat "$tmp/check.out" >&2; exit 1; }
}

# Prints the output NAME.
output() {
    case $1 in
    starter-check-fail)
        starter_check
        echo '```'
        grep -E '^(FAIL |     heat map: )' "$tmp/check.out"
        echo '```' ;;
    imgdiff-report)
        starter_check
        echo '```'
        echo "\$ compare/build/imgdiff milestones/1.2-shading/references/phong-sweep.png phong-sweep.png"
        (cd "$tmp/check/out/check" && "$top/compare/$build/imgdiff" \
            "$top/milestones/1.2-shading/references/phong-sweep.png" phong-sweep.png)
        echo '```' ;;
    trace-pixel-1.3) trace 1.3-shadows-mirror -q scenes/trace-pixel.scn --trace-pixel 1,1 ;;
    trace-pixel-1.6-sample)
        trace 1.6-monte-carlo -q scenes/exercises/1.6-edges.scn --samples 2 --trace-pixel 1,1@2 ;;
    trace-glass-shadow) trace 1.5-refraction -q --trace-pixel 1,1 scenes/trace-glass-shadow.scn ;;
    trace-glass-absorbing)
        trace 1.5-refraction --trace-pixel 100,100 scenes/glass-absorbing.scn >"$tmp/absorbing" || exit 1
        sed -n 1,2p "$tmp/absorbing"
        sed 1,2d "$tmp/absorbing" | pick "glass of index 1.5, entering|reflected ray from|not followed|absorbed inside"
        echo '```' ;;
    note-1.1)
        built "milestones/1.1-spheres-red/$program"
        echo '```'
        echo "\$ milestones/1.1-spheres-red/raytra -q scenes/demo.scn demo.png"
        "milestones/1.1-spheres-red/$program" -q scenes/demo.scn "$tmp/demo.png" 2>&1 ;
        echo '```' ;;
    *) echo "doctables: no output named $1" >&2; exit 1 ;;
    esac
}

# Replaces the block NAME of doc with what stands in file new; --check compares instead.
# The block may stand indented: its lines get the indent of its marker.
status=0
put() {
    doc=$1 name=$2 new=$3
    grep -q "^ *<!-- generated: $name -->\$" "$doc" ||
        { echo "$doc: no '<!-- generated: $name -->' line for the table" >&2; status=1; return; }
    awk -v name="$name" -v new="$new" '
        { line = $0; sub(/^ +/, "", line) }
        line == "<!-- generated: " name " -->" {
            print; indent = substr($0, 1, length($0) - length(line))
            while ((getline l <new) > 0) print (l == "" ? "" : indent l)
            close(new); skip = 1; next }
        skip && line == "<!-- end generated -->" { skip = 0 }
        !skip' "$doc" >"$tmp/doc"
    if cmp -s "$tmp/doc" "$doc"; then return; fi
    if [ "$mode" = check ]; then
        echo "$doc: the block '$name' is not what the source makes now; run 'make docs'" >&2
        status=1
    else
        cp "$tmp/doc" "$doc" && echo "updated $doc ($name)"
    fi
}

marked_functions >"$tmp/marked" || exit 1
# Each chapter's table "What a student reads", from the code, before the reading load counts it.
for doc in docs/1.*.md; do
    grep -q '^<!-- generated: student-reads -->$' "$doc" || continue
    part=$(basename "$doc" .md)
    sh book/studentreads.sh "$part" >"$tmp/reads" || exit 1
    put "$doc" student-reads "$tmp/reads"
done
reading_load >"$tmp/load" || exit 1
put docs/starters.md marked-functions "$tmp/marked"
put docs/architecture.md reading-load "$tmp/load"
# Every block "output NAME" of the chapters (docs/, the grader's grader/docs/) and READMEs,
# from a run of its own.
for doc in docs/*.md grader/docs/*.md README.md milestones/*/README.md; do
    [ -f "$doc" ] || continue
    # shellcheck disable=SC2013 # a name is one word
    for name in $(sed -n 's/^ *<!-- generated: output \([^ ]*\) -->$/\1/p' "$doc"); do
        output "$name" >"$tmp/output" || exit 1
        put "$doc" "output $name" "$tmp/output"
    done
done
[ "$mode" = check ] && [ $status -eq 0 ] && echo "doctables: every generated table is current"
exit $status
