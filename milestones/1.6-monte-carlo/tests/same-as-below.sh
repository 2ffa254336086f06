#!/bin/sh
# same-as-below.sh: at "1 1", part 1.6 draws a scene without area lights exactly as the part below it.
#
# Usage: tests/same-as-below.sh RAYTRA BELOW
#   Renders every scene of scenes/ that has no area light (`l s`) with RAYTRA (part 1.6)
#   at its defaults and at "1 1", and with BELOW (the part it builds on), as PFM at a
#   quarter of their size, and requires the files to be the same byte for byte: one
#   ray through each pixel's centre, and the same shading, to the last bit.
set -u
[ $# -eq 2 ] || { echo "usage: $0 RAYTRA BELOW" >&2; exit 2; }
raytra=$1 below=$2
top=$(cd "$(dirname "$0")/../../.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

count=0 failed=0
for scene in "$top"/scenes/*.scn; do
    grep -q '^[[:space:]]*l[[:space:]]\{1,\}s[[:space:]]' "$scene" && continue
    name=$(basename "$scene" .scn)
    count=$((count + 1))
    "$below" -q --scale 0.25 "$scene" "$tmp/below.pfm" 2>/dev/null ||
        { echo "FAIL $name: the part below failed"; failed=$((failed + 1)); continue; }
    for arguments in "" "1 1"; do
        # shellcheck disable=SC2086 # the arguments are words by design
        if ! "$raytra" -q --scale 0.25 "$scene" "$tmp/this.pfm" $arguments 2>/dev/null ||
            ! cmp -s "$tmp/below.pfm" "$tmp/this.pfm"; then
            echo "FAIL $name: '$arguments' differs from the part below"
            failed=$((failed + 1))
        fi
    done
done
if [ $failed -gt 0 ]; then
    echo "same-as-below: $failed of $count scenes differ"
    exit 1
fi
echo "same-as-below: $count scenes without area lights, the same bytes as the part below"
