#!/bin/sh
# slurm.sh: grades a made-up class through platforms/slurm/grade-slurm on a Slurm cluster of one
# node started here, and checks that its report is the one grader/grade writes on this machine.
#
# Usage: platforms/tests/slurm.sh RAYTRA   (make check-slurm runs it)
#   RAYTRA  part 1.1's program: it renders the class's images and plays a correct student
#
# First grade-slurm's refusals and its --dry-run, which need no cluster. Then, as root, with
# Debian's slurm-wlm and munge (apt-get installs them when missing): munged, slurmctld and
# slurmd started by hand, their configuration, key, sockets, state and logs in a temporary
# folder, on ports no one listens on, and stopped by their PIDs at the end, on failure or
# interrupt too. The class is graded in 3 shards, and the report compared with a local run's
# (grader/tests/same-grades.sh); then again with a shard that fails: the merge must refuse, and the
# shard graded again and merged by hand, as grader/docs/at-scale.md says, must give the report.
# Skips the cluster, saying so (exit 0), when not root or when the packages cannot be had.
set -u
[ $# -eq 1 ] || { echo "usage: $0 RAYTRA" >&2; exit 2; }
case $1 in /*) raytra=$1 ;; *) raytra=$(pwd)/$1 ;; esac
top=$(cd "$(dirname "$0")/../.." && pwd)
refs=$top/milestones/1.1-spheres-red/references
# How many scenes part 1.1 grades (renders.txt's lines but comments and illustrations).
n=$(grep -c '^[^#![:space:]]' "$refs/renders.txt")
grade_slurm=$top/platforms/slurm/grade-slurm
tmp=$(mktemp -d)
daemons=""
trap '[ -z "$daemons" ] || stop_cluster; [ -n "${KEEP:-}" ] || rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
cd "$tmp" || exit 2

. "$top/tests/checks.sh"

# Ends the test: the count of checks, and the exit status.
finish() {
    if [ "$failures" -ne 0 ]; then
        echo "slurm.sh: $failures of $checks checks failed${1:+; $1}"
        exit 1
    fi
    echo "slurm.sh: $checks checks passed${1:+; $1}"
    exit 0
}

# Prints the seconds since the epoch, to the nanosecond.
now() {
    date +%s.%N
}

# The class: images right (under a name with a space and a quote), one a little wrong, one
# missing, PFMs, one of the wrong size; programs right, and one that crashes on a scene.
mkdir -p "the class"
for who in "ada lovelace" "grace o'hopper" alan.turing edsger.dijkstra; do
    mkdir -p "the class/$who" && cp "$refs"/*.png "the class/$who/"
done
sed 's/^s 25 -5 -90   10$/s 25.5 -5 -90   10/' "$top/scenes/spheres-three.scn" >moved.scn
"$raytra" -q moved.scn "the class/alan.turing/spheres-three.png" 2>/dev/null || exit 2
rm "the class/grace o'hopper/demo.png"
"$raytra" -q --scale 0.5 "$top/scenes/demo.scn" "the class/edsger.dijkstra/demo.png" 2>/dev/null || exit 2
mkdir -p "the class/john.backus"
for scene in spheres-three demo; do
    "$raytra" -q "$top/scenes/$scene.scn" "the class/john.backus/$scene.pfm" 2>/dev/null || exit 2
done
# Makes submission $1 a program from the shell script on stdin, which runs the model answer
# it carries (the sandbox shows it nothing outside its folder) as $m.
program() {
    mkdir -p "the class/$1" && cat >"the class/$1/raytra.sh" &&
        cp "$raytra" "the class/$1/model" || exit 2
    printf 'raytra: raytra.sh\n\tcp raytra.sh raytra\n\tchmod +x raytra\n' >"the class/$1/Makefile"
}
# shellcheck disable=SC2016 # the students' scripts
m='"$(dirname "$0")/model"'
printf '#!/bin/sh\nexec %s "$@"\n' "$m" | program margaret.hamilton
# shellcheck disable=SC2016 # the student's script
printf '#!/bin/sh\ncase $1 in *demo*) kill -SEGV $$ ;; esac\nexec %s "$@"\n' "$m" |
    program ken.thompson
class="$tmp/the class"

# grade-slurm's refusals, before anything is made or submitted.
# Checks that grade-slurm, run with the arguments after $1 and $2, exits with status 2 and
# says $2 (a grep pattern), and made no folder "$tmp/refused".
refuses() {
    what=$1 said=$2
    shift 2
    checks=$((checks + 1))
    "$grade_slurm" "$@" >refusal.txt 2>&1
    status=$?
    if [ "$status" -ne 2 ] || ! grep -q -- "$said" refusal.txt || [ -e refused ]; then
        fail "$what: exit status $status (2 expected), saying '$said'; said:"
        sed 's/^/    | /' refusal.txt
    fi
}
refuses "no words" "usage: grade-slurm" --dry-run
refuses "a bad part" "no part '0.9'" --dry-run 0.9 "$class" refused
refuses "no class" "no folder $tmp/no class" --dry-run 1.1 "$tmp/no class" refused
refuses "OUT in the class" "inside it" --dry-run 1.1 "$class" "$class/ada lovelace/out"
refuses "OUT the class" "inside it" --dry-run 1.1 "$class" "$class/"
refuses "a bad time limit" "time-limit" --dry-run --time-limit soon 1.1 "$class" refused
refuses "no shards" "--shards takes a whole number" --dry-run --shards 0 1.1 "$class" refused
refuses "a shard a submission at most" "more shards than the 7 submissions" \
    --dry-run --shards 8 1.1 "$class" refused
refuses "--out" "third word" --dry-run --out x 1.1 "$class" refused
refuses "--self" "grader/grade --self" --dry-run --self 1.1 "$class" refused
refuses "an unknown option" "unknown option --bogus" --dry-run --bogus 1.1 "$class" refused
refuses "a value with a double quote" "double quote" --dry-run --partition 'a"b' 1.1 "$class" refused
refuses "OUT with a line break" "line break" --dry-run 1.1 "$class" "$tmp/line
break"
mkdir -p "not empty" && : >"not empty/file"
refuses "an OUT that is not empty" "is not empty" --dry-run 1.1 "$class" "not empty"
check "--help" "$grade_slurm" --help >help.txt
check "--help names --shards" grep -q -- '--shards N' help.txt

# A dry run writes the scripts, one shard for 7 submissions, and submits nothing.
checks=$((checks + 1))
"$grade_slurm" --dry-run --partition short --time 30 --mem 2G --time-limit 20 1.1 "$class" "dry run" \
    >dry.txt 2>&1
status=$?
if [ $status -eq 0 ]; then
    check "the dry run's scripts are sh" sh -n "dry run/slurm/shard.sh"
    check "the dry run's merge is sh" sh -n "dry run/slurm/merge.sh"
    check "the dry run's default: one shard for 7 submissions" grep -q '^# shard.sh: grades the K-th of 1 slice of' \
        "dry run/slurm/shard.sh"
    check "the dry run's directives" grep -qx '#SBATCH --partition="short"' "dry run/slurm/shard.sh"
    check "the dry run's log" grep -qxF "#SBATCH --output=\"$tmp/dry run/slurm/shard-%a.log\"" \
        "dry run/slurm/shard.sh"
    check "the dry run submitted something" test "$(ls -A "dry run")" = slurm
    check "a dry run's folder taken again" \
        "$grade_slurm" --dry-run --time-limit 20 1.1 "$class" "dry run" >/dev/null 2>&1
else
    fail "grade-slurm --dry-run exited with $status"
    sed 's/^/    | /' dry.txt
fi

# The cluster: root, and the packages, or a skip said.
if [ "$(id -u)" -ne 0 ]; then
    finish "the cluster SKIPPED: starting a Slurm cluster of one node needs root"
fi
commands="sbatch squeue sinfo scontrol scancel slurmctld slurmd munged"
missing=false
for c in $commands; do command -v "$c" >/dev/null 2>&1 || missing=true; done
if $missing; then
    echo "slurm.sh: installing slurm-wlm and munge"
    if ! command -v apt-get >/dev/null 2>&1 ||
        ! { DEBIAN_FRONTEND=noninteractive apt-get update -qq &&
            DEBIAN_FRONTEND=noninteractive apt-get install -y -qq slurm-wlm munge; } >apt.txt 2>&1; then
        tail -n 5 apt.txt 2>/dev/null | sed 's/^/    | /'
        finish "the cluster SKIPPED: slurm-wlm and munge cannot be installed (apt-get install -y slurm-wlm munge)"
    fi
fi

# Succeeds when a process listens on TCP port $1 (IPv4 or IPv6).
port_busy() {
    hex=$(printf ':%04X' "$1")
    cat /proc/net/tcp /proc/net/tcp6 2>/dev/null |
        awk -v port="$hex" '$4 == "0A" && substr($2, length($2) - 4) == port { busy = 1 }
                            END { exit !busy }'
}

# Starts munged, slurmctld and slurmd in the foreground, as children of this script, their
# PIDs in $daemons; everything of theirs is in $tmp/cluster. Fails (said) when one does not
# start or the node is not idle within 30 s.
start_cluster() {
    c=$tmp/cluster
    mkdir -p "$c/munge" "$c/run" "$c/state" "$c/spool" "$c/log" || return 1
    # munged wants its key and log private, its socket's folder and those above it open
    # to all (to enter, not to list).
    chmod 711 "$tmp" "$c" && chmod 700 "$c/munge" && chmod 755 "$c/run" || return 1
    dd if=/dev/urandom of="$c/munge/munge.key" bs=1024 count=1 2>/dev/null &&
        chmod 600 "$c/munge/munge.key" || return 1
    munged -F --key-file="$c/munge/munge.key" --socket="$c/run/munge.socket" \
        --pid-file="$c/run/munged.pid" --log-file="$c/munge/munged.log" \
        --seed-file="$c/munge/munged.seed" >"$c/log/munged.out" 2>&1 &
    daemons="$daemons $!"
    tries=0
    until [ -S "$c/run/munge.socket" ]; do
        tries=$((tries + 1))
        [ $tries -le 50 ] || { echo "munged did not start:"; cat "$c/log/munged.out"; return 1; }
        sleep 0.1
    done
    port=$((20000 + $$ % 20000))
    while port_busy "$port" || port_busy $((port + 1)); do port=$((port + 2)); done
    cat >"$c/slurm.conf" <<EOF
# A cluster of one node, for platforms/tests/slurm.sh, everything of it under $c.
ClusterName=raytra$$
SlurmctldHost=localhost
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$c/run/munge.socket
CredType=cred/munge
StateSaveLocation=$c/state
SlurmdSpoolDir=$c/spool
SlurmctldPidFile=$c/run/slurmctld.pid
SlurmdPidFile=$c/run/slurmd.pid
SlurmctldLogFile=$c/log/slurmctld.log
SlurmdLogFile=$c/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
NodeName=localhost CPUs=2 RealMemory=4096 State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
    export SLURM_CONF="$c/slurm.conf"
    slurmctld -D -f "$SLURM_CONF" >"$c/log/slurmctld.out" 2>&1 &
    daemons="$daemons $!"
    slurmd -D -N localhost -f "$SLURM_CONF" >"$c/log/slurmd.out" 2>&1 &
    daemons="$daemons $!"
    tries=0
    until [ "$(sinfo -h -n localhost -o %t 2>/dev/null)" = idle ]; do
        tries=$((tries + 1))
        if [ $tries -gt 300 ]; then
            echo "the node is not idle after 30 s:"
            tail -n 5 "$c/log/slurmctld.log" "$c/log/slurmd.log" 2>&1 | sed 's/^/    | /'
            return 1
        fi
        sleep 0.1
    done
}

# Cancels every job of the cluster, then stops its daemons by their PIDs, killing any that
# lingers after 10 s; then ends whatever the jobs left running (their command lines name
# $tmp, as every path of the class does).
stop_cluster() {
    [ -n "$daemons" ] || return 0
    # timeout: should slurmctld be gone, its clients would try again for a minute.
    jobs=$(timeout 5 squeue -h -o %A 2>/dev/null)
    if [ -n "$jobs" ]; then
        # shellcheck disable=SC2086 # job numbers
        timeout 5 scancel $jobs 2>/dev/null
        tries=0
        while [ -n "$(timeout 5 squeue -h -o %A 2>/dev/null)" ] && [ $tries -lt 50 ]; do
            sleep 0.2
            tries=$((tries + 1))
        done
    fi
    for pid in $daemons; do kill "$pid" 2>/dev/null; done
    tries=0
    for pid in $daemons; do
        while kill -0 "$pid" 2>/dev/null && [ $tries -lt 100 ]; do
            sleep 0.1
            tries=$((tries + 1))
        done
        kill -9 "$pid" 2>/dev/null
        wait "$pid" 2>/dev/null
    done
    daemons=""
    for pid in $(ours); do kill -9 "$pid" 2>/dev/null; done
}

# Prints the PIDs of the processes the cluster's jobs may have left: those whose command
# line names $tmp (awk is given it through its environment, so as not to name it itself),
# and the job steps (slurmstepd) that were not running before the cluster started.
ours() {
    for cmdline in /proc/[0-9]*/cmdline; do
        pid=${cmdline#/proc/}
        pid=${pid%/cmdline}
        [ "$pid" != $$ ] || continue
        line=$(tr '\0' ' ' 2>/dev/null <"$cmdline") || continue
        case " $steps_before " in *" $pid "*) continue ;; esac
        case $line in *"$tmp"* | slurmstepd*) echo "$pid" ;; esac
    done
}

# Prints the state of job $1 (COMPLETED, FAILED, PENDING...).
job_state() {
    timeout 5 scontrol show job "$1" 2>/dev/null | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' |
        head -n 1
}

# Waits, at most 120 s, for job $1 to end; sets $seen to the time at which the file $2
# appeared (empty if it did not). Fails when the job did not end.
wait_job() {
    seen="" deadline=$(($(date +%s) + 120))
    while :; do
        [ -z "$seen" ] && [ -e "$2" ] && seen=$(now)
        case $(job_state "$1") in
        COMPLETED | FAILED | CANCELLED | TIMEOUT | NODE_FAIL | OUT_OF_MEMORY) break ;;
        esac
        [ "$(date +%s)" -le "$deadline" ] || { fail "job $1 did not end within 120 s"; return 1; }
        sleep 0.1
    done
    [ -z "$seen" ] && [ -e "$2" ] && seen=$(now)
    return 0
}

steps_before=$(for cmdline in /proc/[0-9]*/cmdline; do
    case $(tr '\0' ' ' 2>/dev/null <"$cmdline") in slurmstepd*) pid=${cmdline#/proc/} && echo "${pid%/cmdline}" ;; esac
done)
started=$(now)
checks=$((checks + 1))
if ! start_cluster; then
    fail "the cluster of one node did not start"
    finish
fi
echo "slurm.sh: a cluster of one node is up ($(awk -v a="$started" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }') s)"

# The class through Slurm, in 3 shards, into a folder whose name has a space and a %.
out="$tmp/slurm out%1"
submitted=$(now)
checks=$((checks + 1))
"$grade_slurm" --shards 3 --time-limit 20 --junit "$tmp/slurm.xml" 1.1 "$class" "$out" >submit.txt 2>&1
status=$?
returned=$(now)
if [ $status -ne 0 ]; then
    fail "grade-slurm exited with $status"
    sed 's/^/    | /' submit.txt
    finish
fi
shards_job=$(sed -n 's/^shards //p' "$out/slurm/job-ids")
merge_job=$(sed -n 's/^merge //p' "$out/slurm/job-ids")
check "grade-slurm says where the report will be" grep -qF "$out/report.html" submit.txt
wait_job "$merge_job" "$out/report.html"
finished=$(now)
check "the merge job completed: $(job_state "$merge_job")" test "$(job_state "$merge_job")" = COMPLETED
check "the 3 shards completed" \
    test "$(scontrol show job "$shards_job" 2>/dev/null | grep -c 'JobState=COMPLETED')" -eq 3
check "a report written" test -n "$seen"
seconds=$(awk -v a="$submitted" -v b="${seen:-$finished}" 'BEGIN { printf "%.1f", b - a }')
echo "slurm.sh: 7 submissions in 3 shards through Slurm: $seconds s from grade-slurm to the report"
# Where the time went, from the times the jobs' logs give to the second.
stamps=$(for log in "$out"/slurm/shard-*.log "$out/slurm/merge.log"; do
    sed -n 's/^grade-slurm: .*, \([0-9-]* [0-9:]* UTC\)$/\1/p' "$log" | while read -r stamp; do
        echo "$(basename "$log") $(date -d "$stamp" +%s)"
    done
done)
echo "$stamps" | awk -v t0="$submitted" -v back="$returned" '
    /^shard/ { first = first == "" || $2 < first ? $2 : first; last = $2 > last ? $2 : last }
    /^merge/ { merge = $2 }
    END { printf "slurm.sh: grade-slurm returned after %.1f s; the shards ran from %.0f to %.0f s, " \
                 "the merge started at %.0f s\n", back - t0, first - t0, last - t0, merge - t0 }'
for k in 1 2 3; do
    check "shard $k's log says it ended well" grep -q "shard $k ended with exit status 0" \
        "$out/slurm/shard-$k.log"
done
check "the merge's log names the report" grep -qF "the report: $out/report.html;" "$out/slurm/merge.log"

# The same class on this machine, with the same options.
local_started=$(now)
"$top/grader/grade" -q --time-limit 20 --junit "$tmp/local.xml" --out "$tmp/local" 1.1 "$class" \
    2>local.txt ||
    { fail "the local grade failed"; sed 's/^/    | /' local.txt; }
local_seconds=$(awk -v a="$local_started" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }')
check "the CSV has a line a submission and scene" test "$(wc -l <"$tmp/local/grades.csv")" -eq $((7 * n + 1))
checks=$((checks + 1))
if ! sh "$top/grader/tests/same-grades.sh" "$tmp/local" "$out" >same.txt 2>&1; then
    fail "the report through Slurm differs from the local one"
    sed 's/^/    | /' same.txt | head -n 20
fi

# The JUnit XML of the merge (--junit), the local run's apart from times.
untimed() {
    sed -E 's/time="[0-9.]+"/time="T"/g; s/[0-9]+(\.[0-9]+)? ([kMG] )?rays\/s/T rays\/s/g
            s/[0-9]+(\.[0-9]+)? m?s([^a-zA-Z0-9]|$)/T s\2/g' "$1"
}
check "the merge's JUnit XML: a test case a submission and scene" \
    test "$(grep -c '<testcase ' "$tmp/slurm.xml" 2>/dev/null)" -eq $((7 * n))
checks=$((checks + 1))
untimed "$tmp/local.xml" >local.xml.txt
untimed "$tmp/slurm.xml" >slurm.xml.txt 2>&1
if ! cmp -s local.xml.txt slurm.xml.txt; then
    fail "the merge's JUnit XML differs from the local run's"
    diff local.xml.txt slurm.xml.txt | head -n 10 | sed 's/^/    | /'
fi

# A shard that fails (of a grading with --jobs 2): its folder taken by a file while the
# jobs wait in a partition that is down. The merge must refuse, say why, and write nothing; graded again by hand and
# merged again, as the merge's log says, the shard gives the report.
broken="$tmp/broken"
scontrol update PartitionName=debug State=DOWN
"$grade_slurm" --quiet --jobs 2 --shards 3 --time-limit 20 1.1 "$class" "$broken" >broken.txt 2>&1 ||
    { fail "grade-slurm (the broken shard) exited with $?"; sed 's/^/    | /' broken.txt; }
: >"$broken/shards/2"
scontrol update PartitionName=debug State=UP
merge_job=$(sed -n 's/^merge //p' "$broken/slurm/job-ids")
wait_job "$merge_job" "$broken/report.html"
check "a failed shard: the merge job failed: $(job_state "$merge_job")" test "$(job_state "$merge_job")" = FAILED
check "a failed shard: no report" test ! -e "$broken/report.html"
check "a failed shard: no grades" test ! -e "$broken/grades.csv"
check "a failed shard: its log says so" grep -q "shard 2 ended with exit status 2" "$broken/slurm/shard-2.log"
check "a failed shard: the merge's log says why" grep -qF "grade: no shard folder $broken/shards/2" \
    "$broken/slurm/merge.log"
check "a failed shard: the merge's log does not name shard 2" \
    grep -q "^It writes no report. Shard 2 of 3 wrote no results" "$broken/slurm/merge.log"
# The recipe as the merge's log prints it: its two sbatch lines, JOBID the first one's.
rerun=$(sed -n 's/^    \(sbatch --parsable --array=2 .*shard\.sh\) .*/\1/p' "$broken/slurm/merge.log")
remerge=$(sed -n 's/^    \(sbatch --dependency=afterany:JOBID .*merge\.sh\)$/\1/p' "$broken/slurm/merge.log")
check "a failed shard: the merge's log says no sbatch line for shard 2" test -n "$rerun"
check "a failed shard: the merge's log says no sbatch line for the merge" test -n "$remerge"
check "--jobs 2: 2 CPUs a shard" grep -qx '#SBATCH --cpus-per-task="2"' "$broken/slurm/shard.sh"
cp "$broken/slurm/shard-2.log" "$broken/slurm/merge.log" "$tmp/"
rm "$broken/shards/2"
again=$(cd "$broken/slurm" && eval "$rerun")
merge_job=$(cd "$broken/slurm" && eval "$(echo "$remerge" | sed "s/JOBID/$again/; s/^sbatch /sbatch --parsable /")")
wait_job "$merge_job" "$broken/report.html"
check "the shard graded again: the merge job completed" test "$(job_state "$merge_job")" = COMPLETED
check "the first run's shard log was overwritten" cmp -s "$tmp/shard-2.log" "$broken/slurm/shard-2.log"
check "the first run's merge log was overwritten" cmp -s "$tmp/merge.log" "$broken/slurm/merge.log"
check "the shard graded again has no log of its own" test -s "$broken/slurm/shard-2-again-$again.log"
check "the merge again has no log of its own" test -s "$broken/slurm/merge-again-$merge_job.log"
checks=$((checks + 1))
if ! sh "$top/grader/tests/same-grades.sh" "$tmp/local" "$broken" >same.txt 2>&1; then
    fail "the report merged again differs from the local one"
    sed 's/^/    | /' same.txt | head -n 20
fi

stop_cluster
leftovers=$(ours)
check "nothing left running: $leftovers" test -z "$leftovers"
finish "7 submissions in 3 shards: $seconds s from submission to report (locally, one run: $local_seconds s)"
