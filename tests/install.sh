#!/bin/sh
# install.sh: make install and make uninstall into a temporary DESTDIR, with a PREFIX of its own.
#
# Usage: tests/install.sh MAKE   (make check-install)
# The installed renderers render a scene from there; uninstall leaves the folder empty.
set -u
make=${1:-make}
top=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
fail() { echo "install: $*"; exit 1; }
cd "$top" || exit 2
$make --no-print-directory -s install DESTDIR="$tmp/stage" PREFIX=/opt/raytra >"$tmp/out.txt" 2>&1 ||
    { cat "$tmp/out.txt"; fail "make install failed"; }
bin=$tmp/stage/opt/raytra/bin
count=0
for program in "$bin"/raytra-1.*; do
    [ -x "$program" ] || fail "no renderer installed in $bin"
    "$program" -q scenes/demo-tour.scn "$tmp/demo.png" >/dev/null 2>&1 && [ -s "$tmp/demo.png" ] ||
        fail "${program##*/} does not render from $bin"
    count=$((count + 1))
done
for tool in raytra-imgdiff raytra-mcstats raytra-grade; do
    "$bin/$tool" --help >/dev/null || fail "$tool --help fails"
done
[ "$count" -eq "$(ls -d milestones/*/ | wc -l)" ] || fail "$count renderers installed"
$make --no-print-directory -s uninstall DESTDIR="$tmp/stage" PREFIX=/opt/raytra >/dev/null 2>&1 ||
    fail "make uninstall failed"
[ -z "$(ls -A "$bin")" ] || fail "make uninstall left $(ls "$bin")"
echo "install: make install put $count renderers and 3 tools in DESTDIR/PREFIX/bin; make uninstall took them away"
