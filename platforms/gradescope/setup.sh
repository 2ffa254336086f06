#!/bin/sh
# setup.sh: sets up raytra's Gradescope autograder: the packages missing, the grader, its user.
#
# Usage: setup.sh [--build-only | --users]
# Gradescope runs it once, as root, when it builds the autograder's image, from the zip
# that platforms/gradescope/pack.sh writes, unpacked in /autograder/source. It installs make
# and what common/deps.sh names for a build (gcc, pkg-config, libpng-dev, libopenexr-dev,
# bubblewrap, the grader's sandbox) when they are missing, builds grader/build/grade and
# imgdiff as grader/grade does, and,
# as root, makes two users who own nothing: raytra-student, who runs students' builds and
# programs, and raytra-grader, who runs the grader (run_autograder); and leaves the files
# readable by all and writable by root alone. --build-only stops after the build: what
# platforms/tests/gradescope.sh runs; --users only makes the users.
case ${1:-} in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
set -u
here=$(cd "$(dirname "$0")" && pwd) || exit 1
export DEBIAN_FRONTEND=noninteractive

# Makes the system users raytra-student and raytra-grader, when missing: no home, no shell.
make_users() {
    for name in raytra-student raytra-grader; do
        id -u "$name" >/dev/null 2>&1 ||
            useradd --system --user-group --no-create-home --home-dir /nonexistent \
                --shell /usr/sbin/nologin "$name" || return 1
    done
}
if [ "${1:-}" = --users ]; then
    make_users
    exit
fi

# make runs common/deps.sh, which looks for the rest; make itself comes first.
if ! command -v make >/dev/null 2>&1; then
    if [ "$(id -u)" -ne 0 ] || ! command -v apt-get >/dev/null 2>&1; then
        echo "setup.sh: make is missing; install it (Debian and Ubuntu: apt-get install make)" >&2
        exit 1
    fi
    apt-get update -qq && apt-get install -y -qq --no-install-recommends make || exit 1
fi
sh "$here/common/deps.sh" build || exit 1
# SANITIZE= : the grader is built as grader/grade builds it, whatever the environment says.
make --no-print-directory -s -C "$here/grader" SANITIZE= grade || {
    echo "setup.sh: the grader does not build" >&2
    exit 1
}
[ "${1:-}" = --build-only ] && exit 0

if [ "$(id -u)" -eq 0 ]; then
    make_users || exit 1
    chmod -R u+rwX,go-w,a+rX "$here" || exit 1
    # The hidden scenes (make gradescope HIDDEN=DIR): the grader's user's alone.
    if [ -d "$here/hidden" ] && id -u raytra-grader >/dev/null 2>&1; then
        chown -R raytra-grader "$here/hidden" && chmod -R go-rwx "$here/hidden" || exit 1
    fi
fi
echo "setup.sh: the grader is built: $here/grader/build/grade"
