#!/bin/sh
# mcref.sh: renders a scene with COUNT independent seeds and makes its statistical reference.
#
# Usage: compare/mcref.sh RAYTRA MCSTATS OUT.exr SCENE COUNT FIRST_SEED [raytra options...]
#
# Renders SCENE COUNT times as PFM (linear, exact), with --seed FIRST_SEED, FIRST_SEED + 1,
# ..., and the options (the part's --samples P --light-samples S among them), and writes
# OUT.exr with mcstats: the renders' mean and variance per pixel (grader/docs/statistics.md).
case ${1:-} in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
set -eu
[ $# -ge 6 ] || { echo "usage: $0 RAYTRA MCSTATS OUT.exr SCENE COUNT FIRST_SEED [options...]" >&2; exit 2; }
raytra=$1 mcstats=$2 out=$3 scene=$4 count=$5 first=$6
shift 6
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

# P and S as the options give them (1 unless given), recorded in the file's header.
p=1 s=1 previous=
for word in "$@"; do
    case $previous in --samples) p=$word ;; --light-samples) s=$word ;; esac
    previous=$word
done
k=0
while [ "$k" -lt "$count" ]; do
    "$raytra" -q -j 2 "$scene" "$tmp/$k.pfm" "$@" --seed $((first + k))
    k=$((k + 1))
done
last=$((first + count - 1))
# shellcheck disable=SC2046 # the renders' names have no spaces
"$mcstats" --p "$p" --s "$s" --seeds "$first-$last" "$out" $(ls "$tmp"/*.pfm)
