#!/bin/sh
# debian11.sh: builds and tests raytra in a Debian 11 root, whose OpenEXR 2.5 is Ubuntu 22.04's (Gradescope's).
#
# Usage: tests/debian11.sh   (make check-debian11; as root, else it says so and skips)
#
# Makes a Debian 11 (bullseye) root with debootstrap, from Debian's packages, once: it is
# kept in $RAYTRA_ROOTS (default /var/tmp/raytra-roots) under a name made of what decides
# its packages (common/deps.sh, platforms/gradescope/setup.sh and this script's $base), so that a later
# run starts at once and a change to the packages makes a new root. Into it go `make`
# (the README asks for it) and git (make gradescope packs the files git tracks), then
# everything else as the README and setup.sh install it: by common/deps.sh, run by make,
# with CHROMIUM=/bin/true (the Check suites run here do not open the grading report, so
# Chromium is left out), and `common/deps.sh gradescope-test` (zip, unzip, jq).
#
# The commit checked out (HEAD; uncommitted changes are not tested, and it says so) is
# cloned into the root, and there: `make` builds everything, `make -C tests test` runs
# the Check suites of common/ and the tools (OpenEXR's C++ API writes their test files),
# every part's Check suites are built and part 1.3's run (the others render for minutes,
# and need nothing of Debian 11 that 1.3's do not), and platforms/tests/gradescope.sh packs part
# 1.3's Gradescope autograder, builds it with its setup.sh, and runs run_autograder on a
# correct and a buggy submission, checking results.json field by field. /proc and /dev
# are mounted in the root while it runs and unmounted at the end, whatever happens.
set -u
top=$(cd "$(dirname "$0")/.." && pwd) || exit 2
say() { echo "debian11.sh: $*"; }
if [ "$(id -u)" -ne 0 ]; then
    say "skipped: making a Debian 11 root (debootstrap, chroot, mounts) needs root"
    exit 0
fi
if ! command -v debootstrap >/dev/null 2>&1; then
    command -v apt-get >/dev/null 2>&1 &&
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
            debootstrap >/dev/null 2>&1 ||
        { say "skipped: debootstrap is missing and apt-get cannot install it"; exit 0; }
fi
roots=${RAYTRA_ROOTS:-/var/tmp/raytra-roots}
mirror=${DEBIAN_MIRROR:-http://deb.debian.org/debian}
# What the root gets before raytra's own scripts install the rest.
base="bullseye minbase make git"
key=$({ echo "$base"; cat "$top/common/deps.sh" "$top/platforms/gradescope/setup.sh"; } |
    sha256sum | cut -c 1-12)
root=$roots/bullseye-$key
start=$(date +%s)
mkdir -p "$roots" || exit 2

# One run at a time in a root; the mounts are undone however the run ends.
exec 9>"$root.lock"
flock 9 || exit 2
mounted=""
unmount() {
    for m in $mounted; do umount "$m" || umount -l "$m"; done
    mounted=""
}
trap 'unmount' EXIT
trap 'exit 130' INT TERM
mount_root() { # ROOT
    mount --bind /dev "$1/dev" && mounted="$1/dev" &&
        mount --bind /dev/pts "$1/dev/pts" && mounted="$1/dev/pts $mounted" &&
        mount -t proc proc "$1/proc" && mounted="$1/proc $mounted" &&
        cp /etc/resolv.conf "$1/etc/resolv.conf"
}
# Runs the shell command $2 in root $1, with a clean environment.
in_root() { # ROOT COMMAND
    chroot "$1" /usr/bin/env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
        HOME=/root LANG=C.UTF-8 CHROMIUM=/bin/true DEBIAN_FRONTEND=noninteractive /bin/sh -c "$2"
}

# The root, made once: the base system, make and git.
if [ ! -f "$root/.raytra-root" ]; then
    say "making the Debian 11 root $root (debootstrap from $mirror; once)"
    rm -rf "$root.new" || exit 2
    debootstrap --variant=minbase bullseye "$root.new" "$mirror" >"$roots/debootstrap.log" 2>&1 ||
        { say "debootstrap failed (its log: $roots/debootstrap.log)"; exit 1; }
    mount_root "$root.new" || exit 1
    in_root "$root.new" 'apt-get update -qq && apt-get install -y -qq --no-install-recommends make git' \
        >"$roots/apt.log" 2>&1 ||
        { say "apt-get could not install make and git in the root (its log: $roots/apt.log)"; exit 1; }
    unmount
    echo "Debian 11 root for raytra's tests, key $key" >"$root.new/.raytra-root"
    rm -rf "$root" && mv "$root.new" "$root" || exit 2
    say "the root took $(($(date +%s) - start)) s to make"
fi

mount_root "$root" || exit 1
commit=$(git -C "$top" rev-parse --short HEAD) || exit 2
[ -z "$(git -C "$top" status --porcelain --untracked-files=no)" ] ||
    say "the working tree has uncommitted changes: they are not tested, commit $commit is"
rm -rf "$root/raytra" && git clone -q --no-hardlinks "$top" "$root/raytra" || exit 2
say "testing commit $commit in Debian $(cat "$root/etc/debian_version")"

failed=""
# Runs step $1, the shell command $2 in the root's /raytra, its output in the root's
# /raytra/$1.log (the last lines shown when it fails).
step() { # NAME COMMAND
    t=$(date +%s)
    if in_root "$root" "cd /raytra && ($2) >$1.log 2>&1"; then
        say "$1: passed ($(($(date +%s) - t)) s)"
    else
        say "$1: FAILED ($(($(date +%s) - t)) s); the end of $root/raytra/$1.log:"
        tail -n 25 "$root/raytra/$1.log"
        failed="$failed $1"
    fi
}
step build 'make -j2'
in_root "$root" 'pkg-config --modversion OpenEXR' | sed 's/^/debian11.sh: OpenEXR /'
step unit-tests 'make -C tests test && for part in milestones/*/; do make -C $part test-programs || exit 1; done && make -C milestones/1.3-shadows-mirror unit-test'
step gradescope 'common/deps.sh gradescope-test && sh platforms/tests/gradescope.sh correct buggy'
grep -h '^gradescope.sh: ' "$root/raytra/gradescope.log" | sed 's/^/  /'

unmount
seconds=$(($(date +%s) - start))
if [ -n "$failed" ]; then
    say "failed:$failed ($seconds s)"
    exit 1
fi
say "build, unit tests and the Gradescope autograder pass in Debian 11 ($seconds s)"
