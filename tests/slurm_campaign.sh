#!/bin/sh
# A campaign on a real one-node Slurm cluster started on this machine (issue 13 §4): munged,
# slurmctld and slurmd with their configuration, key, spool, state and logs all in a mktemp folder
# (never /etc), proctrack/linuxproc, task/none, the node at 127.0.0.1; tools/slurm/campaign.sbatch
# submitted as a 3-task array and a merge job that waits for it (afterany); the merged files must be
# byte for byte those of the same campaign run here. Every daemon it started is stopped on exit.
# Installs slurm-wlm and munge with apt-get when they are missing (as root on Debian); where it
# cannot (not root, no apt-get, a daemon that does not start) it says why and skips (exit 0).
# Usage: slurm_campaign.sh path/to/footsim (run from the source folder).
fs=$(realpath "$1")
skip() {
    echo "slurm_campaign: skipped: $*"
    exit 0
}
[ "$(id -u)" -eq 0 ] || skip "starting munged, slurmctld and slurmd needs root"
if ! command -v slurmctld >/dev/null || ! command -v slurmd >/dev/null || ! command -v munged >/dev/null ||
    ! command -v sbatch >/dev/null; then
    command -v apt-get >/dev/null || skip "slurm-wlm and munge are not installed, and there is no apt-get"
    echo "slurm_campaign: installing slurm-wlm and munge (apt-get)"
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends slurm-wlm munge >/dev/null 2>&1 ||
        { apt-get update -q >/dev/null 2>&1 &&
          DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends slurm-wlm munge >/dev/null 2>&1; } ||
        skip "apt-get could not install slurm-wlm and munge"
fi

tmp=$(mktemp -d)
chmod 700 "$tmp"
daemons=""
stop_all() {
    for pid in $daemons; do
        kill "$pid" 2>/dev/null
    done
    for pid in $daemons; do # then wait for each (SIGKILL after 10 s)
        n=0
        while kill -0 "$pid" 2>/dev/null && [ $n -lt 100 ]; do sleep 0.1; n=$((n + 1)); done
        kill -9 "$pid" 2>/dev/null
    done
    rm -rf "$tmp"
}
trap stop_all EXIT
trap 'exit 1' INT TERM HUP
passed=0 failed=0
check() { # check DESCRIPTION COMMAND...: the command must succeed
    what=$1
    shift
    if "$@"; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL: $what" >&2; fi
}
logs() { tail -n 20 "$tmp"/*.log "$tmp"/*.out "$tmp"/munge/munged.out 2>/dev/null; }

# munge: its own key and socket
mkdir -m 700 "$tmp/munge"
dd if=/dev/urandom of="$tmp/munge/munge.key" bs=1024 count=1 2>/dev/null
chmod 400 "$tmp/munge/munge.key"
munged --foreground --force --key-file="$tmp/munge/munge.key" --socket="$tmp/munge/socket" \
    --pid-file="$tmp/munge/munged.pid" --log-file="$tmp/munge/munged.log" --seed-file="$tmp/munge/seed" \
    >"$tmp/munge/munged.out" 2>&1 &
daemons="$daemons $!"
n=0
while [ ! -S "$tmp/munge/socket" ] && [ $n -lt 100 ]; do sleep 0.1; n=$((n + 1)); done
[ -S "$tmp/munge/socket" ] || { logs; skip "munged did not start"; }

# slurm: one node, this machine, on ports of its own
node=$(hostname -s)
port=$((20000 + $$ % 10000))
cpus=$(nproc)
mkdir "$tmp/state" "$tmp/spool"
cat >"$tmp/slurm.conf" <<EOF
ClusterName=footsimtest
SlurmctldHost=$node(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge/socket
SlurmctldPort=$port
SlurmdPort=$((port + 1))
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
MinJobAge=600
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF="$tmp/slurm.conf"
slurmctld -D -i >"$tmp/slurmctld.out" 2>&1 &
daemons="$daemons $!"
slurmd -D >"$tmp/slurmd.out" 2>&1 &
daemons="$daemons $!"
n=0
until sinfo -h -o %T 2>/dev/null | grep -q idle || [ $n -ge 300 ]; do sleep 0.2; n=$((n + 1)); done
sinfo -h -o %T 2>/dev/null | grep -q idle || { logs; skip "the one-node cluster did not come up"; }
echo "slurm_campaign: a one-node cluster is up ($node at 127.0.0.1, $cpus CPUs, SLURM_CONF=$tmp/slurm.conf)"

# the campaign, here and on the cluster (3 shards, then the merge)
. tests/small_campaign.sh
camp -j 2 --out "$tmp/local" >/dev/null 2>&1
check "the local run exits 0" [ $? -eq 0 ]
jid=$(FOOTSIM="$fs" sbatch --parsable --array=1-3 --cpus-per-task=1 -o "$tmp/shard-%a.out" \
    tools/slurm/campaign.sbatch "$tmp/small.ini" "$tmp/cluster" --set run.duration_s=0.15)
check "the array is submitted" [ -n "$jid" ]
mid=$(FOOTSIM="$fs" sbatch --parsable --dependency=afterany:"$jid" -o "$tmp/merge.out" \
    tools/slurm/campaign.sbatch --merge "$tmp/small.ini" "$tmp/cluster")
check "the merge is submitted" [ -n "$mid" ]
dep=$(scontrol -o show job "$mid" | grep -o 'Dependency=[^ ]*')
check "the merge waits for the array with afterany ($dep)" [ -n "$(echo "$dep" | grep "afterany:${jid}")" ]
n=0
while [ -n "$(squeue -h -o %i 2>/dev/null)" ] && [ $n -lt 1800 ]; do sleep 0.2; n=$((n + 1)); done
check "every job ended" [ -z "$(squeue -h -o %i 2>/dev/null)" ]
job() { scontrol -o show job "$1"; } # one line per job (per array task)
last_end=$(job "$jid" | grep -o 'EndTime=[^ ]*' | cut -d= -f2 | sort | tail -n 1)
merge_start=$(job "$mid" | grep -o 'StartTime=[^ ]*' | cut -d= -f2)
check "the array's 3 tasks completed, exit 0" [ "$(job "$jid" | grep 'JobState=COMPLETED' | grep -c 'ExitCode=0:0')" -eq 3 ]
check "the merge started after the last shard ended ($merge_start >= $last_end)" \
    [ -n "$last_end" -a "$(printf '%s\n%s\n' "$last_end" "$merge_start" | sort | tail -n 1)" = "$merge_start" ]
check "the merge job completed, exit 0" [ -n "$(job "$mid" | grep 'JobState=COMPLETED' | grep 'ExitCode=0:0')" ]
for i in 1 2 3; do
    check "shard $i/3 ran as task $i" grep -q "^campaign small, shard $i/3: 2 of 6 trials" "$tmp/shard-$i.out"
done
for f in $files; do
    check "merged on the cluster: $f byte for byte the local run's" cmp -s "$tmp/local/$f" "$tmp/cluster/$f"
done
[ "$failed" -eq 0 ] || { cat "$tmp"/shard-*.out "$tmp/merge.out"; logs; }

echo "slurm_campaign: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
