#!/bin/sh
# docsnip.sh: checks that docsnip finds stale, missing and broken excerpts, and rewrites
# docs safely.
#
# Usage: sh book/tests/docsnip.sh PATH/TO/docsnip
# Every fixture is written into a temporary folder, removed at the end.

set -u
if [ $# -ne 1 ]; then
    echo "usage: sh book/tests/docsnip.sh PATH/TO/docsnip" >&2
    exit 2
fi
case $1 in
/*) docsnip=$1 ;;
*) docsnip=$(pwd)/$1 ;;
esac
[ -x "$docsnip" ] || { echo "docsnip.sh: $docsnip is not a program" >&2; exit 2; }

work=$(mktemp -d "${TMPDIR:-/tmp}/docsnip-test.XXXXXX") || exit 1
trap 'chmod -R u+w "$work"; rm -rf "$work"' EXIT
trap 'exit 1' HUP INT TERM
cd "$work" || exit 1
failures=0

# Tells about a failed check and counts it.
fail() {
    echo "  FAILED: $*"
    failures=$((failures + 1))
}

# expect WHAT STATUS LINE COMMAND...: runs COMMAND, which must exit with STATUS and, unless
# LINE is empty, print LINE as one whole line (on stdout or stderr).
expect() {
    what=$1 status=$2 line=$3
    shift 3
    echo "checking: $what"
    "$@" >out.txt 2>&1
    got=$?
    before=$failures
    [ $got -eq "$status" ] || fail "exit status $got instead of $status"
    if [ -n "$line" ] && ! grep -qxF -- "$line" out.txt; then
        fail "no line '$line'"
    fi
    [ $failures -eq $before ] || sed 's/^/    | /' out.txt
}

# same WHAT EXPECTED ACTUAL: the two files must be byte for byte equal.
same() {
    echo "checking: $1"
    cmp -s "$2" "$3" || { fail "$3 differs from $2"; diff "$2" "$3" | sed 's/^/    | /'; }
}

# --- Fixtures ---------------------------------------------------------------

mkdir src
cat >src/sphere.c <<'EOF'
/* sphere.c: a fixture with nested excerpts. */
#include <math.h>

/* excerpt: quadratic */
double discriminant(double a, double b, double c)
{
    /* excerpt: body */
    double d = b * b - 4 * a * c;

    return d;
    /* end excerpt: body */
}
/* end excerpt: quadratic */
EOF

cat >src/rules.mk <<'EOF'
# rules.mk: a fixture with hash markers.
  # excerpt: link
$(BUILD)/x: $(BUILD)/x.o
	$(CC) -o $@ $^
  # end excerpt: link
EOF

cat >src/fence.sh <<'EOF'
#!/bin/sh
# excerpt: fence
printf '```\n'
# end excerpt: fence
EOF

# The docs exactly as docsnip must write them: this is the region format.
cat >good.md <<'EOF'
# A chapter

The whole function:

<!-- excerpt: src/sphere.c quadratic -->
```c
double discriminant(double a, double b, double c)
{
    double d = b * b - 4 * a * c;

    return d;
}
```
*From src/sphere.c*
<!-- end excerpt -->

Its body, dedented:
<!-- excerpt: src/sphere.c body -->
```c
double d = b * b - 4 * a * c;

return d;
```
*From src/sphere.c*
<!-- end excerpt -->

<!-- excerpt: src/rules.mk link -->
```make
$(BUILD)/x: $(BUILD)/x.o
	$(CC) -o $@ $^
```
*From src/rules.mk*
<!-- end excerpt -->

<!-- excerpt: src/fence.sh fence -->
````sh
printf '```\n'
````
*From src/fence.sh*
<!-- end excerpt -->

An example that is not a region, since it is inside a fence:

```markdown
<!-- excerpt: src/nope.c nope -->
<!-- end excerpt -->
```
EOF

# Definitions quoted by name, with no marker: a type, a function whose prototype comes
# first (and is not quoted), a function pointer type; the comment just above each, not
# the starter marker above that.
cat >src/box.c <<'EOF'
/* box.c: a fixture of definitions. */
/* A box. */
typedef struct {
    double lo, hi;
} Box;

double box_width(Box b,
                 int unused);

typedef double (*BoxFn)(Box b);

/* starter: todo */
/* Returns the width of b,
 * which is never negative. */
double box_width(Box b, int unused)
{
    return b.hi - b.lo;
}

/* excerpt: box-width */
static int box_width2(void)
{
    return 2;
}
/* end excerpt: box-width */
int setup(void)
{
    return 0;
}
EOF
cat >defs.md <<'EOF'
<!-- excerpt: src/box.c Box box_width BoxFn -->
```c
/* A box. */
typedef struct {
    double lo, hi;
} Box;

/* Returns the width of b,
 * which is never negative. */
double box_width(Box b, int unused)
{
    return b.hi - b.lo;
}

typedef double (*BoxFn)(Box b);
```
*From src/box.c*
<!-- end excerpt -->
<!-- excerpt: src/box.c box-width setup -->
```c
static int box_width2(void)
{
    return 2;
}

int setup(void)
{
    return 0;
}
```
*From src/box.c*
<!-- end excerpt -->
EOF
expect "definitions are quoted by name, several in one region" 0 "" "$docsnip" --check defs.md
printf '<!-- excerpt: src/box.c box_height -->\n<!-- end excerpt -->\n' >nodef.md
expect "a missing definition fails" 1 "nodef.md:1: no excerpt or definition 'box_height' in src/box.c" \
    "$docsnip" --check nodef.md
# --definitions prints them as they stand, for book/doctables.sh to count: NAME: is a
# function's contract alone (its comment and signature).
expect "--definitions prints a contract and a type" 0 "" "$docsnip" --definitions src/box.c box_width: Box
cat >want.txt <<'EOF'
/* Returns the width of b,
 * which is never negative. */
double box_width(Box b, int unused)
/* A box. */
typedef struct {
    double lo, hi;
} Box;
EOF
same "--definitions prints them as they stand" want.txt out.txt
expect "--definitions of a missing name fails" 1 "src/box.c: no definition of box_height" \
    "$docsnip" --definitions src/box.c box_height
printf '/* excerpt: setup */\nint x;\n/* end excerpt: setup */\n' >>src/box.c
printf '<!-- excerpt: src/box.c setup -->\n<!-- end excerpt -->\n' >both.md
expect "a name both an excerpt and a definition fails" 1 \
    "both.md:1: 'setup' is both an excerpt and a definition in src/box.c" "$docsnip" --check both.md
rm -f src/box.c defs.md nodef.md both.md want.txt

# Only a definition of the name itself is quoted, never a declaration or a mention: a
# function pointer type that mentions Hit before Hit's typedef, forward declarations before
# the definitions (the struct of typedef struct Tracer Tracer; with its comment, a function
# after its prototype), a macro continued over three lines.
cat >src/hooks.h <<'EOF'
/* hooks.h: a fixture of declarations and mentions before definitions. */
#ifndef HOOKS_H
#define HOOKS_H

typedef struct Tracer Tracer;
struct Hit;
struct Scene;

/* A hook: it mentions Hit, Tracer and Ray, and defines LightFn alone. */
typedef double (*LightFn)(Ray r, const Tracer *tr,
                          const struct Hit *hit);

double tracer_trace(const Tracer *tr,
                    const struct Hit *hit);

/* The features, on three lines. */
#define FEATURES                                                                               \
    (FEATURE_SPHERES | FEATURE_PLANES |                                                        \
     FEATURE_LIGHTS)

/* A hit. */
typedef struct Hit {
    double t;
    LightFn light; /* { a brace in a comment */
} Hit;

/* A tracer. */
struct Tracer {
    Hit last;
    LightFn light;
};

/* Traces. */
double tracer_trace(const Tracer *tr, const struct Hit *hit)
{
    return hit->t + (tr->light ? '}' : 0);
}
#endif
EOF
expect "--definitions finds each one's own definition" 0 "" \
    "$docsnip" --definitions src/hooks.h Hit Tracer FEATURES LightFn tracer_trace:
cat >want.txt <<'EOF'
/* A hit. */
typedef struct Hit {
    double t;
    LightFn light; /* { a brace in a comment */
} Hit;
/* A tracer. */
struct Tracer {
    Hit last;
    LightFn light;
};
/* The features, on three lines. */
#define FEATURES                                                                               \
    (FEATURE_SPHERES | FEATURE_PLANES |                                                        \
     FEATURE_LIGHTS)
/* A hook: it mentions Hit, Tracer and Ray, and defines LightFn alone. */
typedef double (*LightFn)(Ray r, const Tracer *tr,
                          const struct Hit *hit);
/* Traces. */
double tracer_trace(const Tracer *tr, const struct Hit *hit)
EOF
same "a typedef not a mention, a struct not its declaration, a macro whole" want.txt out.txt
expect "a name only mentioned is refused" 1 "src/hooks.h: no definition of Ray" \
    "$docsnip" --definitions src/hooks.h Ray
expect "a name only declared is refused" 1 "src/hooks.h: no definition of Scene" \
    "$docsnip" --definitions src/hooks.h Scene
expect "an unknown name is refused" 1 "src/hooks.h: no definition of Missing" \
    "$docsnip" --definitions src/hooks.h Hit Missing
cat >hooks.md <<'EOF'
<!-- excerpt: src/hooks.h FEATURES tracer_trace -->
```c
/* The features, on three lines. */
#define FEATURES                                                                               \
    (FEATURE_SPHERES | FEATURE_PLANES |                                                        \
     FEATURE_LIGHTS)

/* Traces. */
double tracer_trace(const Tracer *tr, const struct Hit *hit)
{
    return hit->t + (tr->light ? '}' : 0);
}
```
*From src/hooks.h*
<!-- end excerpt -->
EOF
expect "a doc quotes a continued macro whole and a function, not its prototype" 0 "" \
    "$docsnip" --check hooks.md
printf '<!-- excerpt: src/hooks.h Hit Scene -->\n<!-- end excerpt -->\n' >nohook.md
expect "a doc naming a name only declared is refused" 1 \
    "nohook.md:1: no excerpt or definition 'Scene' in src/hooks.h" "$docsnip" --update nohook.md
rm -f src/hooks.h hooks.md nohook.md want.txt

# --- Up to date, stale, update ----------------------------------------------

expect "an up-to-date doc passes (nesting, dedent, # markers, long fence)" 0 "" \
    "$docsnip" --root . --check good.md
[ -s out.txt ] && fail "--check printed something for an up-to-date doc"

sed 's/b \* b - 4/b * b - 3/' good.md >stale.md
expect "a stale doc fails with file:line" 1 \
    "stale.md:5: excerpt 'quadratic' from src/sphere.c is stale; run 'make docs'" \
    "$docsnip" --root . --check stale.md
grep -q "stale.md:18: excerpt 'body' from src/sphere.c is stale" out.txt ||
    fail "the second stale region was not reported"
sed 's/b \* b - 4/b * b - 3/' good.md >stale.want
same "--check leaves the doc alone" stale.want stale.md
rm stale.want

chmod 640 stale.md
expect "--update rewrites it" 0 "updated stale.md" "$docsnip" --update stale.md
same "the rewritten doc is exactly the up-to-date one" good.md stale.md
expect "a second --check passes" 0 "" "$docsnip" --check stale.md
expect "--update leaves an up-to-date doc alone" 0 "" "$docsnip" --update stale.md
[ -s out.txt ] && fail "--update said it changed an up-to-date doc"

echo "checking: the rewrite is atomic and keeps the file's mode"
for f in * .[!.]* ..?*; do
    [ -e "$f" ] || continue
    case $f in
    src | good.md | stale.md | out.txt) ;;
    *) fail "left behind: $f" ;;
    esac
done
case $(ls -l stale.md) in
-rw-r-----*) ;;
*) fail "mode of stale.md changed: $(ls -l stale.md)" ;;
esac

# An empty region is filled in, through a symbolic link, which stays a link.
{ sed -n '1,5p' good.md; printf '<!-- end excerpt -->\n'; } >empty.md
sed -n '1,15p' good.md >fill.want
cp empty.md fill.md
ln -s fill.md link.md
expect "--update fills an empty region through a symbolic link" 0 "updated link.md" \
    "$docsnip" --update link.md
same "the filled region" fill.want fill.md
[ -L link.md ] || fail "link.md is no longer a symbolic link"

# Where the temporary file cannot be made, the doc stays as it was (root may write anyway).
if [ "$(id -u)" -ne 0 ]; then
    mkdir locked
    cp empty.md locked/c.md
    chmod 555 locked
    expect "an unwritable folder fails cleanly" 1 \
        "docsnip: cannot write locked/c.md: Permission denied" "$docsnip" --update locked/c.md
    same "the doc in it is untouched" empty.md locked/c.md
    [ "$(ls -A locked)" = c.md ] || fail "files left behind in locked/"
    chmod 755 locked
fi

# --- Line endings -----------------------------------------------------------

awk '{ printf "%s\r\n", $0 }' empty.md >crlf.md
awk '{ printf "%s\r\n", $0 }' fill.want >crlf.want
expect "a CRLF doc is updated" 0 "updated crlf.md" "$docsnip" --update crlf.md
same "the new lines end in CRLF too" crlf.want crlf.md
expect "an up-to-date CRLF doc passes" 0 "" "$docsnip" --check crlf.md

printf '<!-- excerpt: src/sphere.c body -->\nold\n<!-- end excerpt -->' >noeol.md
expect "a doc without a final newline is updated" 0 "updated noeol.md" \
    "$docsnip" --update noeol.md
echo "checking: it still has no final newline"
[ "$(tail -c 3 noeol.md)" = "-->" ] || fail "noeol.md now ends differently"

# --- Problems in the docs ---------------------------------------------------

printf 'Text\n<!-- excerpt: src/sphere.c nope -->\n<!-- end excerpt -->\n' >noname.md
expect "a missing anchor fails" 1 "noname.md:2: no excerpt or definition 'nope' in src/sphere.c" \
    "$docsnip" --check noname.md

printf '<!-- excerpt: src/nope.c body -->\n<!-- end excerpt -->\n' >nofile.md
expect "a missing file fails" 1 \
    "nofile.md:1: cannot read src/nope.c: No such file or directory" \
    "$docsnip" --check nofile.md

printf 'a\n<!-- excerpt: src/sphere.c body -->\nb\n' >open.md
expect "an unclosed region fails" 1 "open.md:2: excerpt region not closed" \
    "$docsnip" --check open.md

printf 'a\n<!-- end excerpt -->\n' >close.md
expect "a region end without a start fails" 1 \
    "close.md:2: end of an excerpt region never opened" "$docsnip" --check close.md

printf '<!-- excerpt: src/sphere.c Bo.dy -->\n<!-- end excerpt -->\n' >bad.md
expect "a malformed marker fails" 1 "" "$docsnip" --check bad.md
grep -q "^bad.md:1: malformed excerpt marker" out.txt || fail "no malformed-marker message"

printf '<!-- excerpt: ../src/sphere.c body -->\n<!-- end excerpt -->\n' >up.md
expect "a path leaving the root fails" 1 "" "$docsnip" --check up.md
grep -q "^up.md:1: excerpt path '../src/sphere.c' must be relative" out.txt ||
    fail "no message about the path"

cp noname.md noname.before
expect "--update does not write a doc with a problem" 1 \
    "noname.md: not updated because of the problems above" "$docsnip" --update noname.md
same "the doc with a problem is untouched" noname.before noname.md

# --- Problems in the sources ------------------------------------------------

printf '/* excerpt: open */\nint x;\n' >src/open.c
printf '<!-- excerpt: src/open.c open -->\n<!-- end excerpt -->\n' >useopen.md
expect "an unclosed source excerpt fails" 1 "src/open.c:1: excerpt 'open' is never closed" \
    "$docsnip" --check useopen.md

printf '/* excerpt: twice */\nint x;\n/* end excerpt: twice */\n/* excerpt: twice */\n/* end excerpt: twice */\n' >src/dup.c
printf '<!-- excerpt: src/dup.c twice -->\n<!-- end excerpt -->\n' >usedup.md
expect "a name defined twice fails" 1 \
    "src/dup.c:4: excerpt 'twice' is defined twice (first on line 1)" \
    "$docsnip" --check usedup.md

printf 'int x;\n    /* end excerpt: lost */\n' >src/lost.c
expect "an excerpt closed but never opened fails" 1 \
    "src/lost.c:2: end of excerpt 'lost', which was never opened" \
    "$docsnip" --list src/lost.c

# --- Listing, long lines, usage ---------------------------------------------

expect "--list names the excerpts" 0 "src/sphere.c:7: body" "$docsnip" --list src/sphere.c

awk 'BEGIN { printf "/* excerpt: long */\nint x = 0"; for (i = 0; i < 20000; i++) printf " + %d", i;
             printf ";\n/* end excerpt: long */\n" }' >src/long.c
printf '<!-- excerpt: src/long.c long -->\n<!-- end excerpt -->\n' >long.md
expect "a 100 kB line is quoted whole" 0 "updated long.md" "$docsnip" --update long.md
echo "checking: the long line survived"
[ "$(sed -n 3p long.md)" = "$(sed -n 2p src/long.c)" ] || fail "the long line differs"

expect "--help succeeds" 0 "" "$docsnip" --help
expect "no mode is bad usage" 2 "" "$docsnip" good.md
expect "an unknown option is bad usage" 2 "" "$docsnip" --check --frobnicate good.md
expect "no files is bad usage" 2 "" "$docsnip" --check
expect "two modes are bad usage" 2 "" "$docsnip" --check --update good.md

echo "checking: no temporary file is left anywhere"
find . -name '*.docsnip-*' | grep -q . && fail "left behind: $(find . -name '*.docsnip-*')"

if [ $failures -ne 0 ]; then
    echo "docsnip.sh: $failures check(s) FAILED"
    exit 1
fi
echo "docsnip.sh: all checks passed"
