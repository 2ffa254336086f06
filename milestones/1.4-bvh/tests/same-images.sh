#!/bin/sh
# same-images.sh: modes 0 and 3 of part 1.4 render exactly the images of part 1.3.
#
# Usage: tests/same-images.sh RAYTRA_1_4 RAYTRA_1_3
#
# It also checks that the course's positional MODE and --mode render the same, and
# that a MODE other than 0-3 is a usage error (exit status 2).
#
# Every reference scene of parts 1.1 to 1.3 (their references/renders.txt, with the
# options given there) and every scene of the course's corpus (../shared/course-scenes,
# at --scale 0.05 as tests/course-scenes.sh renders it) is rendered as PFM by part 1.3
# and by part 1.4 in modes 0 and 3; the files must be the same, byte for byte. The
# corpus is skipped, saying so, when it is not beside the repository.
set -u
[ $# -eq 2 ] || { echo "usage: $0 RAYTRA_1_4 RAYTRA_1_3" >&2; exit 2; }
new=$1 old=$2
top=$(cd "$(dirname "$0")/../../.." && pwd)
corpus=$top/../shared/course-scenes
tmp=$(mktemp -d)
# A heartbeat beside the renders, which take half a minute: every 3 s, while this script
# runs, it says how far they are (from $tmp/now, which compare keeps up to date), so that
# no render, however long, looks like a hang.
(while sleep 3 >/dev/null 2>&1 && kill -0 $$ 2>/dev/null; do
    # Empty for a moment while compare writes it.
    now=$(cat "$tmp/now" 2>/dev/null) && [ -n "$now" ] && echo "same-images:   $now"
done) &
heartbeat=$!
trap 'kill $heartbeat 2>/dev/null; rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

count=0 failed=0 skipped=0
# Renders scene ($1, a path) with the extra options $2 by both parts and compares.
compare() {
    scene=$1 options=$2
    echo "$count checks so far; now ${scene#"$top"/}" >"$tmp/now"
    # shellcheck disable=SC2086 # options are words by design
    if ! "$old" -q -j 2 "$scene" "$tmp/old.pfm" $options 2>"$tmp/err"; then
        # A mesh missing from the corpus: part 1.3 cannot render it either.
        skipped=$((skipped + 1))
        return
    fi
    for mode in 0 3; do
        count=$((count + 1))
        # shellcheck disable=SC2086
        if ! "$new" -q -j 2 "$scene" "$tmp/new.pfm" $mode $options 2>"$tmp/err"; then
            echo "FAIL mode $mode: raytra failed on $scene $options:"
            sed 's/^/    /' "$tmp/err"
            failed=$((failed + 1))
        elif ! cmp -s "$tmp/old.pfm" "$tmp/new.pfm"; then
            echo "FAIL mode $mode: $scene $options differs from part 1.3's image"
            failed=$((failed + 1))
        fi
    done
}

# The course's positional MODE and --mode are the same; any other MODE is a usage error.
demo=$top/scenes/demo.scn
for mode in 1 2; do
    count=$((count + 1))
    "$new" -q --scale 0.25 "$demo" "$tmp/a.pfm" $mode && "$new" -q --scale 0.25 --mode $mode "$demo" "$tmp/b.pfm" &&
        cmp -s "$tmp/a.pfm" "$tmp/b.pfm" || { echo "FAIL: MODE $mode and --mode $mode differ"; failed=$((failed + 1)); }
done
for bad in 4 7 x 1.5; do
    count=$((count + 1))
    "$new" -q "$demo" "$tmp/a.pfm" "$bad" 2>"$tmp/err"
    status=$?
    [ $status -eq 2 ] && grep -q MODE "$tmp/err" ||
        { echo "FAIL: MODE '$bad' gave exit status $status:"; sed 's/^/    /' "$tmp/err"; failed=$((failed + 1)); }
done

for part in 1.1-spheres-red 1.2-shading 1.3-shadows-mirror; do
    echo "same-images: the reference scenes of part ${part%%-*}, in modes 0 and 3 against part 1.3..."
    while read -r image scene options; do
        case $image in '' | '#'*) continue ;; esac
        compare "$top/$scene" "$options"
    done <"$top/milestones/$part/references/renders.txt"
done
if [ -d "$corpus" ]; then
    echo "same-images: the course's scenes, in modes 0 and 3 against part 1.3..."
    for scene in $(cd "$corpus" && find . \( -name '*.scn' -o -name '*.txt' \) | sort); do
        scene=${scene#./}
        case $scene in fall2016*) convention=fall2016 ;; *) convention=lecture ;; esac
        compare "$corpus/$scene" "--scale 0.05 --convention $convention"
    done
else
    echo "same-images: SKIPPED the course corpus: $corpus does not exist"
fi
echo "same-images: $count checks (renders in modes 0 and 3 against part 1.3, MODE against --mode), $failed failed;" \
    "$skipped scenes part 1.3 cannot render (missing meshes, OBJ files) skipped"
[ $failed -eq 0 ]
