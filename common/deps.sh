#!/bin/sh
# deps.sh: makes sure the packages raytra builds with are installed, or names the command that installs them.
#
# Usage: common/deps.sh [build|test|bench|gradescope|gradescope-test|platforms-test|chromium]
#   build  needs a C compiler with its C library's headers, pkg-config, and the headers
#          of libpng and zlib; in raytra's repository (not in a student's starter, whose
#          parts only write images) also bubblewrap (bwrap) on Linux, the grader's
#          sandbox, and OpenEXR 2 or 3, whose C interface to RGBA files
#          (ImfCRgbaFile.h) the tools read OpenEXR files through (Ubuntu 22.04 and Debian
#          11 have OpenEXR 2.5, Debian 12 has 3.1: either will do);
#   test   needs, in addition, the Check unit-test framework, a C++ compiler (for
#          tests/exr_writer.cpp, which writes OpenEXR test files with the library's C++
#          API), and Chromium, in which grader/tests/grade-report.sh opens the grading report
#          (headless);
#   bench  needs, in addition to build, Embree 3 and a C++ compiler for the benchmark's
#          baselines (bench/baseline_tinybvh.cpp binds tinybvh, a C++ header);
#   gradescope  needs, in addition to build, zip, to pack a Gradescope autograder;
#   gradescope-test  needs, in addition, unzip and jq, with which platforms/tests/gradescope.sh
#          unpacks the autograder and reads the results.json it writes;
#   platforms-test  needs, in addition to build, jq, zip, unzip, xmllint and a python3
#          with jsonschema, with which platforms/tests/formats.sh converts and validates
#          the platforms' formats;
#   chromium  prints the path of the Chromium to run and installs nothing: $CHROMIUM
#          when set (a path, or a name on PATH), else the first of chromium,
#          chromium-browser, google-chrome and google-chrome-stable on PATH; fails when
#          there is none.
#
# It knows three package managers, and the packages' names in each: apt-get (Debian and
# Ubuntu), dnf (Fedora) and brew (macOS). With apt-get it installs what is missing when it
# may (as root, or through sudo without a password); otherwise, and with dnf and brew, it
# prints the exact command to run and fails.

set -u

# Prints the path of the Chromium to run, as the usage says; false when there is none.
find_chromium() {
    if [ -n "${CHROMIUM:-}" ]; then
        set -- "$CHROMIUM"
    else
        set -- chromium chromium-browser google-chrome google-chrome-stable
    fi
    for name in "$@"; do
        found=$(command -v "$name" 2>/dev/null) && [ -x "$found" ] && echo "$found" && return 0
    done
    return 1
}
case ${1:-build} in
-h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;;
build | test | bench | gradescope | gradescope-test | platforms-test | chromium) ;;
*) echo "deps.sh: no need '$1': build, test, bench, gradescope, gradescope-test, platforms-test" \
       "or chromium" >&2
   exit 2 ;;
esac
if [ "${1:-}" = chromium ]; then
    find_chromium
    exit
fi

need_check=no
[ "${1:-build}" = test ] && need_check=yes
need_embree=no
[ "${1:-build}" = bench ] && need_embree=yes

missing="" missing_dnf="" missing_brew="" missing_what=""
# Records that WHAT is missing, and its package for apt-get, dnf and brew (- for brew: the
# command line tools of Xcode bring it, or macOS has it).
need() { # WHAT DEBIAN FEDORA BREW
    missing_what="$missing_what, $1"
    missing="$missing $2"
    missing_dnf="$missing_dnf $3"
    [ "$4" = - ] || missing_brew="$missing_brew $4"
}
# The Gradescope autograder's tools (unzip is macOS's own).
case ${1:-build} in
gradescope | gradescope-test) command -v zip >/dev/null 2>&1 || need zip zip zip zip ;;
esac
if [ "${1:-build}" = gradescope-test ]; then
    command -v unzip >/dev/null 2>&1 || need unzip unzip unzip -
    command -v jq >/dev/null 2>&1 || need jq jq jq jq
fi
# What platforms/tests/formats.sh converts and validates with.
if [ "${1:-build}" = platforms-test ]; then
    command -v jq >/dev/null 2>&1 || need jq jq jq jq
    command -v zip >/dev/null 2>&1 || need zip zip zip zip
    command -v unzip >/dev/null 2>&1 || need unzip unzip unzip -
    command -v xmllint >/dev/null 2>&1 || need xmllint libxml2-utils libxml2 libxml2
    /usr/bin/python3 -c 'import jsonschema' 2>/dev/null ||
        python3 -c 'import jsonschema' 2>/dev/null ||
        need "python3's jsonschema" python3-jsonschema python3-jsonschema -
fi
# The compiler and pkg-config the Makefiles run ($(CC), $(PKG_CONFIG), passed on by them): the
# first word, so that CC="ccache gcc" is looked for as ccache.
compiler=${CC:-cc}
pkg_config=${PKG_CONFIG:-pkg-config}
command -v "${compiler%% *}" >/dev/null 2>&1 || need "a C compiler ($compiler)" gcc gcc -
# gcc does not bring the C library's headers when installed without what it recommends.
if [ "$(uname -s)" != Darwin ] && [ ! -f /usr/include/stdio.h ]; then
    need "the C library's headers" libc6-dev glibc-devel -
fi
command -v "${pkg_config%% *}" >/dev/null 2>&1 || need pkg-config pkg-config pkgconf-pkg-config pkg-config
if ! $pkg_config --exists libpng 2>/dev/null && [ ! -f /usr/include/png.h ]; then
    need libpng libpng-dev libpng-devel libpng
fi
if [ "$(uname -s)" != Darwin ] && ! $pkg_config --exists zlib 2>/dev/null &&
    [ ! -f /usr/include/zlib.h ]; then
    need zlib zlib1g-dev zlib-devel -
fi
# compare/exr_rgba.c reads through OpenEXR's library; a starter has none (compare/Makefile).
if [ -f "$(dirname "$0")/../compare/exr_rgba.c" ] && ! $pkg_config --exists 'OpenEXR >= 2' 2>/dev/null &&
    [ ! -f /usr/include/OpenEXR/ImfCRgbaFile.h ]; then
    need "OpenEXR (2 or 3)" libopenexr-dev openexr-devel openexr
fi
# The grader runs students' builds and programs in bubblewrap's namespaces (Linux only;
# without it, grader/grade falls back to walls of its own: grader/docs/containment.md);
# a starter, which grades with imgdiff alone, needs none.
if [ "$(uname -s)" = Linux ] && [ -f "$(dirname "$0")/../compare/exr_rgba.c" ] &&
    ! command -v bwrap >/dev/null 2>&1; then
    need "bubblewrap (the grader's sandbox)" bubblewrap bubblewrap -
fi
if [ $need_check = yes ] && ! $pkg_config --exists check 2>/dev/null; then
    need Check check check-devel check
fi
# The chapters' tables "What a student reads" are made from the code by universal-ctags
# (book/studentreads.sh); a starter, which has them made, needs none.
if [ $need_check = yes ] && [ -f "$(dirname "$0")/../book/studentreads.sh" ] &&
    ! ctags --version 2>/dev/null | grep -q 'Universal Ctags'; then
    need universal-ctags universal-ctags ctags universal-ctags
fi
if { [ $need_check = yes ] || [ $need_embree = yes ]; } && ! command -v "${CXX:-c++}" >/dev/null 2>&1; then
    need "a C++ compiler" g++ gcc-c++ -
fi
if [ $need_embree = yes ] && [ ! -f /usr/include/embree3/rtcore.h ] &&
    ! $pkg_config --exists 'embree >= 3' 2>/dev/null; then
    need "Embree 3" libembree-dev embree-devel embree
fi
if [ $need_check = yes ] && ! find_chromium >/dev/null && command -v apt-get >/dev/null 2>&1; then
    need Chromium chromium chromium -
fi
[ -z "$missing" ] && exit 0

# The command that installs them, for the package manager this machine has (all three when
# it has none of them).
if command -v apt-get >/dev/null 2>&1; then
    commands="sudo apt-get install -y$missing"
elif command -v dnf >/dev/null 2>&1; then
    commands="sudo dnf install -y$missing_dnf"
elif command -v brew >/dev/null 2>&1; then
    commands="brew install$missing_brew"
    [ -n "$missing_brew" ] || commands="xcode-select --install"
else
    commands="sudo apt-get install -y$missing   (Debian, Ubuntu)
    sudo dnf install -y$missing_dnf   (Fedora)
    brew install$missing_brew   (macOS; a compiler: xcode-select --install)"
fi

if ! command -v apt-get >/dev/null 2>&1; then
    echo "raytra needs ${missing_what#, }." >&2
    echo "Install them with:  $commands" >&2
    exit 1
fi

if [ "$(id -u)" -eq 0 ]; then
    as_root=""
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    as_root="sudo"
else
    echo "raytra needs ${missing_what#, }." >&2
    echo "Install them with:  $commands" >&2
    exit 1
fi

echo "raytra: installing$missing (apt-get)" >&2
export DEBIAN_FRONTEND=noninteractive
$as_root apt-get update -qq >/dev/null &&
    $as_root apt-get install -y -qq --no-install-recommends $missing >/dev/null || {
    echo "raytra: apt-get could not install$missing" >&2
    echo "Install them with:  $commands" >&2
    exit 1
}
