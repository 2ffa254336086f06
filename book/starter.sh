#!/bin/sh
# starter.sh: writes a part's starter, the folder a course hands out, with the student's functions as stubs.
#
# Usage: book/starter.sh [--solution] [--stub-earlier] [--chapter] [--docs-url URL] PART [DEST]
#   PART            one part: 1.2, 1.2-shading or milestones/1.2-shading
#   DEST            the folder to write; default out/starter-<part> at the top
#   --solution      keep the bodies of every marked function: the instructor's copy
#   --stub-earlier  stub the marked functions of the earlier parts too; by default
#                   they ship complete, as a course hands out a part's solution
#                   after its deadline
#   --chapter       write the student edition of the part's chapter too, as
#                   docs/PART.md: the chapter with each marked function's excerpt
#                   as the starter has it (its contract and its stub), prose and
#                   figures kept; `make starter` gives this option
#   --docs-url URL  where the course publishes raytra's files (the chapters): the
#                   READMEs' links to files not in the starter point there
#
# A function whose body the student writes is marked in the source by a line
#     /* starter: todo */      or      /* starter: todo: HINT */
# anywhere before it (docs/starters.md): its body, from the next line that is
# exactly "{" to the next line that is exactly "}", becomes a TODO comment, casts
# of the parameters to void, and a return of a harmless value. The starter holds
# common/, the parts used, the part with its tests and references, the scenes
# they need, imgdiff, and a Makefile whose `make check` tests and grades. A link of a
# README to a file the starter does not hold (a chapter, which shows the solution) is
# made to point to it in the repository, or at URL. The starter gets the modes of any
# new folder (the umask's), so that it can be handed out as it is.
set -u
top=$(cd "$(dirname "$0")/.." && pwd) || exit 2
usage() {
    echo "usage: $0 [--solution] [--stub-earlier] [--chapter] [--docs-url URL] PART [DEST]" >&2
    exit 2
}
die() {
    echo "starter: $*" >&2
    exit 2
}

solution=no
stub_earlier=no
chapter=no
docs_url=
while [ $# -gt 0 ]; do
    case $1 in
    --solution) solution=yes ;;
    --stub-earlier) stub_earlier=yes ;;
    --chapter) chapter=yes ;;
    --docs-url) [ $# -ge 2 ] || usage; docs_url=${2%/}; shift ;;
    -h | --help) sed -n '2,28p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) usage ;;
    *) break ;;
    esac
    shift
done
[ $# -ge 1 ] && [ $# -le 2 ] || usage
[ $solution = yes ] && stub_earlier=no

# The part's folder, from its full name, its number, or its path: one part, one word
# (`make starter PART="1.2 1.3"` would otherwise write 1.2's starter into ./1.3).
case $1 in
'' | *[[:space:]]*) die "PART is one part (1.2, 1.2-shading or its folder), got '$1': a starter a part" ;;
esac
part=${1%/}
part=${part##*/}
case $part in
*-*) ;;
*) part=$(cd "$top/milestones" && for d in "$part"-*; do [ -d "$d" ] && echo "$d"; done) ;;
esac
[ -n "$part" ] && [ -f "$top/milestones/$part/Makefile" ] || die "no part '$1' in $top/milestones"
dest=${2:-$top/out/starter-$part}

# USES, SOURCES and TESTS as the part's Makefile sets them, asked of make itself
# (without the caller's MAKEFLAGS: a PART=... given to the top make must not leak in).
vars=$(mktemp) || exit 2
# shellcheck disable=SC2016 # $(USES) is make's, not the shell's
printf 'starter-vars:\n\t@echo "$(USES)|$(TESTS)"\n' >"$vars"
answer=$(MAKEFLAGS='' make --no-print-directory -s -C "$top/milestones/$part" -f Makefile -f "$vars" \
    starter-vars) || { rm -f "$vars"; die "cannot read milestones/$part/Makefile"; }
rm -f "$vars"
uses=${answer%%|*}
tests=${answer#*|}

# DEST is made in a temporary folder beside it and renamed when complete. An old
# starter (it holds .raytra-starter) is replaced; anything else is left alone.
if [ -e "$dest" ]; then
    [ -f "$dest/.raytra-starter" ] || die "$dest exists and is not a starter: not replacing it"
fi
mkdir -p "$(dirname "$dest")" || exit 2
tmp=$(mktemp -d "$(dirname "$dest")/.starter.XXXXXX") || exit 2
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

# Filters a C file of a part: stubs each marked body (MODE stub) or keeps it (MODE
# solution); drops the marker lines, and the docs' excerpt anchors unless ANCHORS is
# given (the student edition of a chapter is made from them). Each stub is listed in
# LIST as FILE:LINE: NAME for the starter's README.
filter() { # MODE SOURCE OUTPUT NAME-IN-LIST LIST [ANCHORS]
    awk -v mode="$1" -v file="$4" -v list="$5" -v anchors="${6:-}" '
    function trim(s) { gsub(/^[ \t]+|[ \t]+$/, "", s); return s }
    function emit(s) { print s; lines++ }
    function fail(msg) { printf "%s:%d: %s\n", file, FNR, msg > "/dev/stderr"; bad = 1; exit 2 }
    # The body of a stub: the TODO, the parameters cast to void, a harmless return.
    function stub(sig,    todo, open, head, params, name, type, n, k, p, ret) {
        open = index(sig, "(")
        if (open == 0) fail("a starter marker, but no function signature before \"{\"")
        head = trim(substr(sig, 1, open - 1))
        params = substr(sig, open + 1)
        sub(/\)[^)]*$/, "", params)
        match(head, /[A-Za-z_][A-Za-z0-9_]*$/)
        name = substr(head, RSTART, RLENGTH)
        type = trim(substr(head, 1, RSTART - 1))
        while (gsub(/(^|[ \t])(static|inline|extern)[ \t]/, " ", type) > 0) ;
        type = trim(type)
        todo = lines + 1
        emit("    /* TODO: " (hint != "" ? hint : "write " name ": see the comment above.") " */")
        n = split(params, p, ",")
        for (k = 1; k <= n; k++) {
            p[k] = trim(p[k])
            sub(/\[[^]]*\]$/, "", p[k])
            if (p[k] == "void" || p[k] == "" || p[k] == "...") continue
            match(p[k], /[A-Za-z_][A-Za-z0-9_]*$/)
            emit("    (void)" substr(p[k], RSTART, RLENGTH) ";")
        }
        # excerpt: starter-return
        # The harmless value: nothing found, black, zero, a struct of zeros.
        if (type == "void") ret = ""
        else if (type == "bool") ret = "false"
        else if (type == "Color") ret = "color(0, 0, 0)"
        else if (type ~ /\*/ || type ~ /^((un)?signed|long|short|int|char|float|double|size_t)( |$)/) ret = "0"
        else ret = "(" type "){0}"
        if (ret != "") emit("    return " ret ";")
        # end excerpt: starter-return
        printf "%s:%d: %s\n", file, todo, name >> list
    }
    /^[ \t]*\/\* (end )?excerpt: [a-z0-9-]+ \*\/[ \t]*$/ { if (anchors == "") next; print; next }
    state == 0 && /^\/\* starter: todo(: .*)? \*\/$/ {
        hint = $0
        sub(/^\/\* starter: todo:? ?/, "", hint)
        sub(/ ?\*\/$/, "", hint)
        state = 1; sig = ""; next
    }
    /starter:/ && /^[ \t]*\/\*/ { fail("not a starter marker: write /* starter: todo */ alone on a line") }
    state == 1 {
        emit($0)
        if ($0 == "{") {
            if (mode == "stub") { stub(sig); state = 2 } else state = 0
        } else if ($0 ~ /^[ \t]*(\/\*|\*)/ || $0 ~ /\*\/[ \t]*$/ || $0 == "") sig = ""
        else sig = sig " " $0
        next
    }
    state == 2 { if ($0 == "}") { emit($0); state = 0 } next }
    { emit($0) }
    END {
        if (!bad && state == 1) fail("a starter marker with no function after it")
        if (!bad && state == 2) fail("a stubbed function with no closing \"}\" at the start of a line")
    }' "$2" >"$3"
}

# Copies a part's sources, filtered, and its Makefile and README into the starter.
copy_part() { # PART MODE
    src=$top/milestones/$1
    mkdir -p "$tmp/milestones/$1"
    cp "$src/Makefile" "$tmp/milestones/$1/" || exit 2
    [ -f "$src/README.md" ] && cp "$src/README.md" "$tmp/milestones/$1/"
    copy_sources "milestones/$1" "$2"
}

# Copies the C files of a folder of the repository, filtered: MODE for the .c files,
# and the headers only stripped of their marker and excerpt lines.
copy_sources() { # FOLDER MODE
    mkdir -p "$tmp/$1"
    for c in "$top/$1"/*.c "$top/$1"/*.h; do
        mode=$2
        case $c in *.h) mode=solution ;; esac
        filter $mode "$c" "$tmp/$1/${c##*/}" "$1/${c##*/}" "$tmp/todo.txt" || exit 2
    done
}

: >"$tmp/todo.txt"
mkdir -p "$tmp/compare" "$tmp/grader" "$tmp/sandbox" "$tmp/book" "$tmp/tests" "$tmp/scenes" || exit 2
copy_sources common solution
cp "$top/common"/*.mk "$top/common/Makefile" "$top/common/deps.sh" "$tmp/common/" &&
    cp "$top/compare"/*.c "$top/compare"/*.h "$top/compare/Makefile" "$tmp/compare/" &&
    cp "$top/grader"/*.c "$top/grader"/*.h "$top/grader"/*.css "$top/grader/Makefile" "$tmp/grader/" &&
    cp "$top/sandbox"/*.c "$top/sandbox"/*.h "$top/sandbox/Makefile" "$tmp/sandbox/" &&
    cp "$top/book/docsnip.sh" "$top/book/starter-check.sh" "$tmp/book/" &&
    cp "$top/tests/testing.h" "$top/tests/regress.sh" "$tmp/tests/" || exit 2
# The parts only write images: without OpenEXR's library (exr_rgba.c), the starter's
# imgdiff reads the OpenEXR files raytra writes by itself, and needs no OpenEXR at all.
rm "$tmp/compare/exr_rgba.c" || exit 2

# USES names the earlier parts newest first; they are copied oldest first, so that the
# README lists the TODOs in the order of the course.
earliest_first=
for used in $uses; do earliest_first="$used $earliest_first"; done
for used in $earliest_first; do
    if [ $stub_earlier = yes ]; then copy_part "$used" stub; else copy_part "$used" solution; fi
done
if [ $solution = yes ]; then copy_part "$part" solution; else copy_part "$part" stub; fi
cp -R "$top/milestones/$part/tests" "$top/milestones/$part/references" "$tmp/milestones/$part/" ||
    exit 2
# The grader (make grade) knows every part's arguments from its headers and table of options:
# those of the parts after this one, which the starter has not, go to grader/parts/.
for folder in "$top"/milestones/*/; do
    later=$(basename "$folder")
    [ -d "$tmp/milestones/$later" ] || [ "$later" = "$part" ] && continue
    mkdir -p "$tmp/grader/parts/$later" &&
        cp "$folder"*.h "$folder"*_options.c "$tmp/grader/parts/$later/" || exit 2
done
# The instructor's controls (points, visibility, the folder of hidden scenes) stay theirs.
rm -f "$tmp/milestones/$part/references/grading.conf"
# The lists of the earlier parts' reference renders (not their images): a part's tests
# may render those scenes again (part 1.4's same-images.sh compares its modes with 1.3).
for used in $uses; do
    mkdir -p "$tmp/milestones/$used/references" &&
        cp "$top/milestones/$used/references/renders.txt" "$tmp/milestones/$used/references/" || exit 2
done

# The scenes: those the references are rendered from, those the tests name, and the
# meshes they load (w lines, relative to the scene).
refs=$top/milestones/$part/references/renders.txt
{
    for list in "$refs" $(for used in $uses; do echo "$top/milestones/$used/references/renders.txt"; done); do
        awk '$1 !~ /^#/ && NF >= 2 { sub(/^scenes\//, "", $2); print $2 }' "$list"
    done
    for t in $tests; do grep -o '[A-Za-z0-9_-]*\.scn' "$top/milestones/$part/$t"; done
} | sort -u | while read -r scene; do
    [ -f "$top/scenes/$scene" ] || continue
    mkdir -p "$tmp/scenes/$(dirname "$scene")" && cp "$top/scenes/$scene" "$tmp/scenes/$scene" || exit 2
    awk '$1 == "w" { print $2 }' "$top/scenes/$scene" | while read -r mesh; do
        from=$(dirname "$scene")/$mesh
        mkdir -p "$tmp/scenes/$(dirname "$from")" && cp "$top/scenes/$from" "$tmp/scenes/$from" || exit 2
    done || exit 2
done || exit 2

# The starter's Makefile: make, make check, make clean, on the repository's own makefiles.
sed "s/@PART@/$part/g" >"$tmp/Makefile" <<'EOF'
# Makefile of the starter of part @PART@: builds raytra, tests it and compares its images.
#
#   make          build milestones/@PART@/raytra, and copy it to ./raytra
#   make check    build, run the part's unit tests, render every scene of
#                 milestones/@PART@/references/renders.txt and compare each render with
#                 its reference image; renders and heat maps go to out/check/
#   make clean    remove everything make made
#
# WERROR=1 turns warnings into errors; SANITIZE=1 builds with AddressSanitizer and
# UndefinedBehaviorSanitizer.
include common/build.mk

# A function left to write leaves the static inline helpers it calls unused until it is
# written, which clang warns of (gcc does not): the starter builds without a warning.
CFLAGS += -Wno-unused-function
export CFLAGS

STARTER_PART := @PART@
PART_DIR     := milestones/$(STARTER_PART)
PART_PROGRAM := $(PART_DIR)/$(if $(filter 1,$(SANITIZE)),$(BUILD)/raytra,raytra)

.PHONY: all check grade clean
.NOTPARALLEL:

# The program is copied to the top too, where grader/grade looks for a submission's raytra.
all:
	$(DEPS_STEP)
	+@$(SUBMAKE) -C $(PART_DIR)
	@cp $(PART_PROGRAM) raytra

check:
	$(DEPS_STEP) test
	+@$(SUBMAKE) all
	+@$(SUBMAKE) -C $(PART_DIR) test-programs
	+@$(SUBMAKE) -C compare imgdiff
	@sh book/starter-check.sh $(PART_DIR) $(PART_PROGRAM) $(PART_DIR)/$(BUILD)/tests $(IMGDIFF) out/check

# Grades the part as the course's grader will (grader/grade --self: grader/docs/self.md): a
# copy built afresh, every graded scene under the same limits, each verdict with its
# reason; the report in grading-$(STARTER_PART)/, beside this folder.
grade:
	$(DEPS_STEP)
	+@$(SUBMAKE) -C grader grade
	@grader/build/grade --self --out ../grading-$(STARTER_PART) $(STARTER_PART) .

clean:
	+@$(SUBMAKE) -C common clean
	+@$(SUBMAKE) -C compare clean
	+@$(SUBMAKE) -C grader clean
	+@for dir in milestones/*; do $(SUBMAKE) -C $$dir clean; done
	rm -rf out raytra
EOF

# The student edition of the chapter: its excerpts taken by docsnip from the sources as
# the starter has them (anchors kept), so that a marked function shows its contract and
# its stub; the figures of the part beside it.
if [ $chapter = yes ]; then
    doc=$top/docs/$part.md
    [ -f "$doc" ] || die "no chapter docs/$part.md for --chapter"
    mirror=$tmp/.chapter-sources
    sed -n 's/^<!-- excerpt: \([^ ]*\) .*/\1/p' "$doc" | sort -u | while read -r file; do
        mode=solution
        case $file in
        milestones/"$part"/*.c) [ $solution = yes ] || mode=stub ;;
        milestones/*.c) [ $stub_earlier = no ] || mode=stub ;;
        esac
        mkdir -p "$mirror/$(dirname "$file")" &&
            filter "$mode" "$top/$file" "$mirror/$file" "$file" /dev/null anchors || exit 2
    done || exit 2
    mkdir -p "$tmp/docs" && cp "$doc" "$tmp/docs/$part.md" && cp "$top/docs/students.md" "$tmp/docs/" ||
        exit 2
    sh "$top/book/docsnip.sh" --root "$mirror" --update "$tmp/docs/$part.md" >/dev/null ||
        die "docsnip could not make the student edition of docs/$part.md"
    rm -rf "$mirror"
    if [ -d "$top/docs/figures/$part" ]; then
        mkdir -p "$tmp/docs/figures" && cp -R "$top/docs/figures/$part" "$tmp/docs/figures/" || exit 2
    fi
fi

# The starter's README: what to do, and where each TODO is.
earlier="the parts in \`milestones/\` other than $part are complete."
[ $stub_earlier = yes ] && earlier="the TODOs of the parts before $part are yours to write too."
{
    echo "# Starter of part $part"
    echo
    echo "Write the functions marked TODO, then run \`make check\`: it builds the"
    echo "program, runs the part's unit tests, renders every scene of"
    echo "\`milestones/$part/references/renders.txt\` and compares each render with its"
    echo "reference image. It ends with \`make check: every test passes\` when all is done;"
    echo "for each image that differs it names a heat map in \`out/check/\`: black where"
    echo "your render equals the reference, blue to yellow to white where it differs."
    echo
    echo "\`make\` alone builds \`milestones/$part/raytra\`; run it as"
    echo "\`milestones/$part/raytra SCENE OUTPUT.png\` (\`--help\` lists its options)."
    echo "Packages needed on Debian or Ubuntu: gcc, libc6-dev, make, pkg-config, libpng-dev,"
    echo "zlib1g-dev and check (\`common/deps.sh test\` installs them when it may, or names"
    echo "the command that does, with apt-get, dnf or brew). No OpenEXR: raytra writes and"
    echo "reads its \`.exr\` files itself."
    echo
    echo "The functions to write:"
    echo
    sed 's/^\(.*\): \(.*\)$/- `\2` (`\1`)/' "$tmp/todo.txt"
    [ -s "$tmp/todo.txt" ] || echo "- none: this is the solution"
    echo
    echo "\`common/\` is the library every part links (vectors, scenes, images, the"
    echo "render loop); $earlier"
    echo "\`milestones/$part/README.md\` describes the part."
    if [ $chapter = yes ]; then
        echo "\`docs/$part.md\` is its chapter, as students read it: the functions you write"
        echo "stand there as their contracts and stubs. The other chapters show solutions and"
        echo "are not in the starter; links to them lead to raytra's repository."
    elif [ -n "$docs_url" ]; then
        echo "Its chapters are not in the starter: its links take you to them at $docs_url."
    else
        echo "Its chapters (\`docs/\` of raytra's repository) show its solution and are not"
        echo "in the starter."
    fi
    echo
    [ $chapter = yes ] && echo "\`docs/students.md\` is the whole round, from \`make\` to \`make grade\`."
    echo "\`make grade\` grades your part as the course's grader will: a copy of this folder"
    echo "built afresh, every graded scene run under the same limits and judged, each verdict"
    echo "with its reason, and a report in \`../grading-$part/report.html\`."
} >"$tmp/README.md"
rm "$tmp/todo.txt"
echo "raytra starter of part $part" >"$tmp/.raytra-starter"

# The READMEs' and the chapter's links to files the starter does not hold: a picture (an
# earlier part's, a figure of the chapters) is copied in; anything else (a chapter, which shows the solution; bench/) is pointed to
# where it is, at URL or by its path in raytra's repository, so that no link is dead.
find "$tmp/milestones" "$tmp/docs" -name '*.md' 2>/dev/null | while read -r md; do
    rel=${md#"$tmp"/}
    awk -v dir="${rel%/*}" -v tmp="$tmp" -v top="$top" -v url="$docs_url" '
    # The path of target from the top, for a link in folder dir: "." and ".." resolved.
    function resolve(target,    n, k, part, out, m) {
        n = split(dir "/" target, part, "/")
        m = 0
        for (k = 1; k <= n; k++) {
            if (part[k] == "" || part[k] == ".") continue
            if (part[k] == "..") { if (m > 0) m--; continue }
            out[++m] = part[k]
        }
        target = ""
        for (k = 1; k <= m; k++) target = target (k > 1 ? "/" : "") out[k]
        return target
    }
    function exists(path) { return system("test -e \"" path "\"") == 0 }
    {
        line = $0; done = ""
        while (match(line, /!?\[[^]]*\]\([^)]*\)/)) {
            link = substr(line, RSTART, RLENGTH)
            done = done substr(line, 1, RSTART - 1)
            line = substr(line, RSTART + RLENGTH)
            text = link; sub(/\]\(.*/, "", text); sub(/^!?\[/, "", text)
            target = link; sub(/^[^]]*\]\(/, "", target); sub(/\)$/, "", target)
            file = target; sub(/#.*/, "", file)
            if (target ~ /^([a-z]+:|#|\/)/ || file == "" || exists(tmp "/" resolve(file))) {
                done = done link; continue
            }
            path = resolve(file)
            folder = tmp "/" path
            sub(/\/[^\/]*$/, "", folder)
            if (link ~ /^!/ && path ~ /^(milestones|docs\/figures)\// && exists(top "/" path) &&
                system("mkdir -p \"" folder "\" && cp \"" top "/" path "\" \"" tmp "/" path "\"") == 0)
                done = done link
            else if (url != "")
                done = done (link ~ /^!/ ? "!" : "") "[" text "](" url "/" path substr(target, length(file) + 1) ")"
            else
                done = done (text == path ? "`" path "` (" : text " (`" path "`, ") "in raytra'"'"'s repository, not in this starter)"
        }
        print done line
    }' "$md" >"$md.new" && mv "$md.new" "$md" || exit 2
done || exit 2

# mktemp -d made the folder private (0700): it gets the modes the umask gives a new folder.
chmod "$(umask -S)" "$tmp" || exit 2
rm -rf "$dest" && mv "$tmp" "$dest" || exit 2
trap - EXIT
echo "starter: wrote $dest"
