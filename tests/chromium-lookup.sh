#!/bin/sh
# chromium-lookup.sh: common/deps.sh finds Chromium by any of its names on PATH, or by $CHROMIUM.
#
# Usage: tests/chromium-lookup.sh
# Makes folders of stand-in programs and checks what `common/deps.sh chromium` prints
# with each as PATH: the Chromium that grader/tests/grade-report.sh runs.
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
failures=0

# Makes an executable stand-in at each path given.
program() {
    for p in "$@"; do
        mkdir -p "$(dirname "$p")" && printf '#!/bin/sh\n' >"$p" && chmod +x "$p"
    done
}
# Checks that with PATH=$1 (and the environment given before the call) deps.sh prints $2,
# or fails when $2 is empty.
expect() {
    got=$(PATH=$1 "$top/common/deps.sh" chromium)
    status=$?
    if [ -z "$2" ] && [ $status -ne 0 ] && [ -z "$got" ]; then
        echo "ok   nothing found with PATH=$1${CHROMIUM:+ and CHROMIUM=$CHROMIUM}"
    elif [ -n "$2" ] && [ $status -eq 0 ] && [ "$got" = "$2" ]; then
        echo "ok   $got${CHROMIUM:+ (CHROMIUM=$CHROMIUM)}"
    else
        echo "FAIL PATH=$1${CHROMIUM:+ CHROMIUM=$CHROMIUM}: expected '${2:-nothing}', got '$got' (status $status)"
        failures=$((failures + 1))
    fi
}

program "$tmp/debian/chromium" "$tmp/ubuntu/chromium-browser" "$tmp/chrome/google-chrome" \
    "$tmp/stable/google-chrome-stable" "$tmp/both/google-chrome" "$tmp/both/chromium" \
    "$tmp/my chromium/chrome"
mkdir -p "$tmp/none"
printf 'not a program\n' >"$tmp/none/chromium" # not executable: not a Chromium
unset CHROMIUM
expect "$tmp/debian" "$tmp/debian/chromium"
expect "$tmp/ubuntu" "$tmp/ubuntu/chromium-browser"
expect "$tmp/chrome" "$tmp/chrome/google-chrome"
expect "$tmp/stable" "$tmp/stable/google-chrome-stable"
expect "$tmp/none:$tmp/ubuntu" "$tmp/ubuntu/chromium-browser"
expect "$tmp/both" "$tmp/both/chromium"
expect "$tmp/none" ""
# $CHROMIUM wins, as a name on PATH or as a path (spaces and all); one that is not there fails.
CHROMIUM=google-chrome expect "$tmp/both" "$tmp/both/google-chrome"
CHROMIUM="$tmp/my chromium/chrome" expect "$tmp/debian" "$tmp/my chromium/chrome"
CHROMIUM=no-such-browser expect "$tmp/debian" ""

if [ $failures -gt 0 ]; then
    echo "chromium-lookup: $failures failed"
    exit 1
fi
echo "chromium-lookup: Chromium is found by every name"
