#!/bin/sh
# run.sh: fuzzes the scene, OBJ or OpenEXR reader for a given time, then minimises the kept corpus.
#
# Usage: tests/fuzz/run.sh scene|obj|exr SECONDS [libFuzzer options...]
#
# Builds the fuzzers (make -C tests/fuzz), then runs one on a corpus that grows in
# tests/fuzz/build-fuzz/corpus-HARNESS/ (kept between runs, not in git), seeded with the
# project's scenes or meshes, the bad-input corpus (for OpenEXR: the files tests/exr_writer
# writes with OpenEXR's C++ API), the committed corpus and every regression. Crashes are written to build-fuzz/crash-HARNESS/. At the end the grown corpus
# is merged (-merge=1: the fewest inputs that keep all coverage) into the committed
# tests/fuzz/corpus-HARNESS/. The log is build-fuzz/HARNESS.log; its last lines are
# libFuzzer's final statistics. Exit status: 0 when no crash was found.
# The fuzzers need clang with its libFuzzer runtime (Debian: clang and libclang-rt-dev).
set -u
[ $# -ge 2 ] || { echo "usage: $0 scene|obj|exr SECONDS [libFuzzer options...]" >&2; exit 2; }
harness=$1 seconds=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
work=$here/build-fuzz
max_len=8192
case $harness in
scene) seeds="$top/scenes $top/tests/bad-input" dict=$here/scene.dict ;;
obj) seeds="$top/scenes/meshes $here/seed-obj $top/tests/bad-input" dict=$here/obj.dict ;;
exr)
    seeds=$work/seed-exr dict=$here/exr.dict max_len=32768
    make -s -C "$top/tests" build/exr_writer || exit 2
    mkdir -p "$seeds" && "$top/tests/build/exr_writer" "$seeds" || exit 2
    rm -f "$seeds"/*.rgba
    ;;
*) echo "run.sh: no harness '$harness' (scene, obj or exr)" >&2; exit 2 ;;
esac
make -s -C "$here" fuzzers || exit 2
fuzzer=$work/fuzz-$harness
grown=$work/corpus-$harness
crashes=$work/crash-$harness
log=$work/$harness.log
mkdir -p "$grown" "$crashes" "$work/tmp"
# The scene harness makes its folder of meshes in $TMPDIR; a crash leaves it behind there.
export TMPDIR="$work/tmp"
folders=""
for dir in "$here/corpus-$harness" "$here/regressions/$harness" $seeds; do
    [ -d "$dir" ] && folders="$folders $dir"
done

echo "run.sh: fuzzing $harness for $seconds s; log in $log"
# shellcheck disable=SC2086 # the folders are words by design (paths without blanks)
"$fuzzer" -max_total_time="$seconds" -dict="$dict" -max_len=$max_len -timeout=10 \
    -print_final_stats=1 -artifact_prefix="$crashes/" "$@" "$grown" $folders >"$log" 2>&1
status=$?
tail -n 20 "$log" | grep -e '^stat::' -e 'DONE' -e 'ERROR' -e 'Test unit written'

# Minimise: the committed corpus becomes the smallest set with all the coverage found.
merged=$work/merged-$harness
rm -rf "$merged"
mkdir -p "$merged"
"$fuzzer" -merge=1 -max_len=$max_len -timeout=10 "$merged" "$here/corpus-$harness" "$grown" \
    >"$work/$harness-merge.log" 2>&1 || {
    echo "run.sh: the merge failed; see $work/$harness-merge.log" >&2
    exit 1
}
rm -rf "$TMPDIR"/raytra-fuzz.*
rm -f "$here/corpus-$harness"/*
find "$merged" -type f -exec cp {} "$here/corpus-$harness/" \;
count=$(find "$here/corpus-$harness" -type f | wc -l)
bytes=$(find "$here/corpus-$harness" -type f -exec cat {} + | wc -c)
echo "run.sh: corpus-$harness: $count inputs, $((bytes / 1024)) KB"
if [ $status -ne 0 ]; then
    echo "run.sh: the fuzzer stopped with status $status; crashing inputs are in $crashes:" >&2
    ls "$crashes" >&2
fi
exit $status
