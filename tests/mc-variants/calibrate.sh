#!/bin/sh
# calibrate.sh: measures how often grading by statistics fails correct Monte Carlo renders.
#
# Usage: tests/mc-variants/calibrate.sh RAYTRA VARIANTS REFDIR COUNT [OUT]
#
# Renders every graded scene of REFDIR/renders.txt (~IMAGE lines) COUNT times, at seeds
# from 100000 on (the references were made from 1000 to 1063), with each correct
# program: raytra's part 1.6 and part 1.6 with its random numbers from xorshift64* and
# from drand48, with the strata counted column by column, with the light's strata
# correlated by a random cyclic shift, with multi-jittered and with Latin hypercube
# points in the pixel, and with every number a hash of a counter (all judged by the
# "good" standard), and with
# random points on the light (judged by the "ok" standard); judges each render as the
# PNG, the PFM and the EXR the program would write (VARIANTS/mcjudge; raytra's also as a
# PNG written by truncation, which a student's writer may do), and prints the
# table of failures: per scene, program and format, and per submission (the same seed of
# every scene: a student's hand-in fails when one of its scenes fails).
# MC_SCENES (an extended regular expression) keeps the scenes whose names it matches
# whole: a run of some scenes counts renders, not submissions.
# Seeds are done in batches of MC_BATCH (default 25), every program and scene a batch,
# so that a run cut short still covers them all; a line on stderr after each program of a
# batch says how far it is: "k of N renders (seeds), T elapsed, ETA T", the ETA from the
# mean time a render has taken. The raw verdicts go to OUT/raw.txt
# (default: a temporary folder), a line a render and format; COUNT 0 prints the table
# of the verdicts already in OUT/raw.txt.
# Exit status 0 when the failures are at most 0.1 % of the submissions, 1 otherwise.
set -u
[ $# -ge 4 ] || { echo "usage: $0 RAYTRA VARIANTS REFDIR COUNT [OUT]" >&2; exit 2; }
raytra=$1 variants=$2 refdir=$3 count=$4 out=${5:-}
top=$(cd "$(dirname "$0")/../.." && pwd)
batch=${MC_BATCH:-25}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
[ -n "$out" ] || out=$tmp/out
mkdir -p "$out"
[ "$count" -eq 0 ] || : >"$out/raw.txt"

# The correct programs: NAME PROGRAM STANDARD.
cat >"$tmp/programs" <<PROGRAMS
raytra $raytra good
xorshift $variants/raytra-xorshift good
drand48 $variants/raytra-drand48 good
transposed $variants/raytra-transposed good
shift $variants/raytra-shift good
multi-jitter $variants/raytra-multi-jitter good
latin-hypercube $variants/raytra-latin-hypercube good
hashed $variants/raytra-hashed good
random-light $variants/raytra-random-light ok
PROGRAMS
sed -n 's/^~\([^[:space:]]*\)\.[a-z]*[[:space:]]/\1 /p' "$refdir/renders.txt" |
    grep -E "^(${MC_SCENES:-.*}) " >"$tmp/scenes"
[ -s "$tmp/scenes" ] || { echo "calibrate.sh: no statistical reference in $refdir/renders.txt" >&2; exit 2; }

# Prints a duration of $1 seconds as the grader writes one: 41 s, 5 min 20 s, 1 h 5 min.
duration() {
    if [ "$1" -lt 60 ]; then
        echo "$1 s"
    elif [ "$1" -lt 3600 ]; then
        echo "$(($1 / 60)) min $(($1 % 60)) s"
    else
        echo "$(($1 / 3600)) h $(($1 / 60 % 60)) min"
    fi
}

start=$(date +%s)
scenes=$(wc -l <"$tmp/scenes")
renders=$((count * $(wc -l <"$tmp/programs") * scenes))
rendered=0
first=0
while [ "$first" -lt "$count" ]; do
    last=$((first + batch))
    [ "$last" -le "$count" ] || last=$count
    while read -r program path standard; do
        while read -r name scene options; do
            s=$first
            while [ "$s" -lt "$last" ]; do
                # shellcheck disable=SC2086 # the options are words by design
                "$path" -q -j 2 "$top/$scene" "$tmp/$s.pfm" $options --seed $((100000 + s)) ||
                    { echo "calibrate.sh: $program failed on $name" >&2; exit 2; }
                s=$((s + 1))
            done
            # raytra's renders are judged as a PNG written by truncation too (png-trunc).
            ok=
            [ "$standard" = good ] || ok=--ok
            [ "$program" != raytra ] || ok=--truncate
            # shellcheck disable=SC2046,SC2086 # the renders' names have no spaces
            TMPDIR=$tmp "$variants/mcjudge" $ok "$refdir/$name.stats.exr" $(ls "$tmp"/*.pfm) |
                sed "s|^$tmp/\([0-9]*\)\.pfm |$program $name \1 |" >>"$out/raw.txt" ||
                exit 2
            rm -f "$tmp"/*.pfm
        done <"$tmp/scenes"
        # How far the calibration is, from the clock: the ETA is the mean render's time for
        # each render left.
        rendered=$((rendered + (last - first) * scenes))
        elapsed=$(($(date +%s) - start))
        eta=
        [ "$rendered" -ge "$renders" ] || eta=", ETA $(duration $((elapsed * (renders - rendered) / rendered)))"
        echo "calibrate.sh: $rendered of $renders renders ($program, seeds $first to $((last - 1)) of $count), $(duration "$elapsed") elapsed$eta" >&2
    done <"$tmp/programs"
    first=$last
done

# The table: per program, format and scene, failures of renders; per program and format,
# failures of submissions (a seed whose every scene was judged).
awk -v scenes="$(wc -l <"$tmp/scenes")" '
    { key = $1 " " $4; n[key, $2]++; if ($5 == "FAIL") { f[key, $2]++; why[key, $2] = why[key, $2] " " $6 }
      seen[key, $3]++; if ($5 == "FAIL") bad[key, $3] = 1
      if (!(key in keys)) { keys[key] = 1; order[++k] = key }
      if (!($2 in names)) { names[$2] = 1; scene[++m] = $2 } }
    END {
        printf "| program | format |"; for (j = 1; j <= m; j++) printf " %s |", scene[j]
        printf " submissions |\n|---|---|"; for (j = 1; j <= m; j++) printf "---|"; printf "---|\n"
        for (i = 1; i <= k; i++) {
            key = order[i]; split(key, w, " ")
            printf "| %s | %s |", w[1], w[2]
            for (j = 1; j <= m; j++) printf " %d of %d |", f[key, scene[j]], n[key, scene[j]]
            subs = 0; fails = 0
            for (s in seen) { split(s, x, SUBSEP); if (x[1] == key && seen[s] == scenes) { subs++; fails += bad[s] } }
            printf " %d of %d |\n", fails, subs
            total += subs; failed += fails
        }
        printf "\nall: %d of %d submissions fail (%.3f %%)\n", failed, total, total ? 100 * failed / total : 0
        exit (total > 0 && failed * 1000 <= total) ? 0 : 1
    }' "$out/raw.txt" >"$out/table.md"
status=$?
cat "$out/table.md"
grep FAIL "$out/raw.txt" | sed 's/^/failed: /'
echo "calibrate.sh: $(($(date +%s) - start)) s"
exit $status
