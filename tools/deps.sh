#!/bin/sh
# deps.sh: makes sure the packages raytra builds with are installed.
#
# Usage: tools/deps.sh [build|test|bench|gradescope|gradescope-test|chromium]
#   build  needs a C compiler, make, pkg-config, and the headers of libpng and of
#          OpenEXR 3 (its C API, openexr.h);
#   test   needs, in addition, the Check unit-test framework, a C++ compiler (for
#          tests/exr_writer.cpp, which writes OpenEXR test files with the library's C++
#          API), and Chromium, in which tests/grade-report.sh opens the grading report
#          (headless);
#   bench  needs, in addition to build, Embree 3 for the benchmark's baseline;
#   gradescope  needs, in addition to build, zip, to pack a Gradescope autograder;
#   gradescope-test  needs, in addition, unzip and jq, with which tests/gradescope.sh
#          unpacks the autograder and reads the results.json it writes;
#   chromium  prints the path of the Chromium to run and installs nothing: $CHROMIUM
#          when set (a path, or a name on PATH), else the first of chromium,
#          chromium-browser, google-chrome and google-chrome-stable on PATH; fails when
#          there is none.
#
# On Debian and Ubuntu it installs what is missing with apt-get when it may
# (as root, or through sudo without a password); otherwise it names the exact
# command to run and fails.

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
if [ "${1:-}" = chromium ]; then
    find_chromium
    exit
fi

need_check=no
[ "${1:-build}" = test ] && need_check=yes
need_embree=no
[ "${1:-build}" = bench ] && need_embree=yes

missing=""
# The Gradescope autograder's tools, as COMMAND:PACKAGE.
case ${1:-build} in
gradescope) tools="zip:zip" ;;
gradescope-test) tools="zip:zip unzip:unzip jq:jq" ;;
*) tools="" ;;
esac
for tool in $tools; do
    command -v "${tool%%:*}" >/dev/null 2>&1 || missing="$missing ${tool#*:}"
done
command -v cc >/dev/null 2>&1 || missing="$missing gcc"
command -v pkg-config >/dev/null 2>&1 || missing="$missing pkg-config"
if ! pkg-config --exists libpng 2>/dev/null && [ ! -f /usr/include/png.h ]; then
    missing="$missing libpng-dev"
fi
if ! pkg-config --exists 'OpenEXR >= 3' 2>/dev/null && [ ! -f /usr/include/OpenEXR/openexr.h ]; then
    missing="$missing libopenexr-dev"
fi
if [ $need_check = yes ] && ! pkg-config --exists check 2>/dev/null; then
    missing="$missing check"
fi
if [ $need_check = yes ] && ! command -v c++ >/dev/null 2>&1; then
    missing="$missing g++"
fi
if [ $need_embree = yes ] && [ ! -f /usr/include/embree3/rtcore.h ]; then
    missing="$missing libembree-dev"
fi
if [ $need_check = yes ] && ! find_chromium >/dev/null && command -v apt-get >/dev/null 2>&1; then
    missing="$missing chromium"
fi
[ -z "$missing" ] && exit 0

if ! command -v apt-get >/dev/null 2>&1; then
    echo "raytra needs these packages (Debian names):$missing" >&2
    echo "Install them with your system's package manager, then run make again." >&2
    exit 1
fi

if [ "$(id -u)" -eq 0 ]; then
    as_root=""
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    as_root="sudo"
else
    echo "raytra needs these packages:$missing" >&2
    echo "Install them with:  sudo apt-get install -y$missing" >&2
    exit 1
fi

echo "raytra: installing$missing (apt-get)" >&2
export DEBIAN_FRONTEND=noninteractive
$as_root apt-get update -qq >/dev/null &&
    $as_root apt-get install -y -qq --no-install-recommends $missing >/dev/null || {
    echo "raytra: apt-get could not install$missing" >&2
    echo "Install them with:  sudo apt-get install -y$missing" >&2
    exit 1
}
