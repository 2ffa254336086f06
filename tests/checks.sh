# checks.sh: counting the checks of a test script; sourced by the scripts, never run alone.
#
# Usage: . tests/checks.sh   then `check MESSAGE COMMAND [ARG...]` counts a check that
# fails, saying "FAIL: MESSAGE", unless the command succeeds; `fail MESSAGE` fails one.
# $checks and $failures hold the counts for the script's last line.
checks=0
failures=0

# Reports a failed check.
fail() {
    failures=$((failures + 1))
    echo "FAIL: $1"
}

# Counts a check, failing it with message $1 unless the rest of the line succeeds.
check() {
    message=$1
    shift
    checks=$((checks + 1))
    "$@" || fail "$message"
}
