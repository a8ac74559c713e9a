#!/usr/bin/env bash
# A throw-away one-node Slurm on this machine (Debian's slurmctld, slurmd,
# slurm-client and munge), for testing experiments/slurm-array.sh for real:
#
#   eval "$(experiments/slurm-local.sh start DIR)"   # prints export SLURM_CONF=...
#   sbatch --wait --array=1-2 experiments/slurm-array.sh run EXP OUT
#   experiments/slurm-local.sh stop DIR
#
# Everything (munge key and socket, configuration, state, logs) lives in DIR;
# the daemons run as the calling user (root in CI) with no cgroups.
set -euo pipefail
mode=${1:?usage: $0 start|stop DIR} dir=${2:?usage: $0 start|stop DIR}
case "$mode" in
start)
    for b in munged slurmctld slurmd sbatch; do
        command -v "$b" >/dev/null || { echo "$0: $b missing (apt-get install slurmctld slurmd slurm-client munge)" >&2; exit 3; }
    done
    mkdir -p "$dir/state" "$dir/spool" "$dir/munge"
    chmod 700 "$dir/munge"
    dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 status=none
    chmod 400 "$dir/munge/munge.key"
    munged --force --socket="$dir/munge/munge.socket" --key-file="$dir/munge/munge.key" \
        --pid-file="$dir/munge/munged.pid" --log-file="$dir/munge/munged.log" --seed-file="$dir/munge/seed"
    host=$(hostname -s)
    port=$((20000 + RANDOM % 20000))
    cat >"$dir/slurm.conf" <<CONF
ClusterName=lumibench
SlurmctldHost=$host
SlurmUser=$(id -un)
SlurmdUser=root
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
AuthInfo=socket=$dir/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
    export SLURM_CONF="$dir/slurm.conf"
    slurmctld -f "$SLURM_CONF"
    slurmd -f "$SLURM_CONF"
    # Wait until the node takes jobs.
    for _ in $(seq 1 60); do
        if sinfo -h -o %t 2>/dev/null | grep -qE '^(idle|mix|alloc)'; then
            echo "export SLURM_CONF='$SLURM_CONF'"
            exit 0
        fi
        sleep 0.5
    done
    echo "$0: the node did not come up; logs in $dir" >&2
    exit 1
    ;;
stop)
    # Signal the daemons, then wait (up to 10 s) until they have exited: slurmctld
    # writes its state files on the way out, so a caller that removes $dir right
    # after `stop` must not race with it.
    pids=()
    for f in "$dir/slurmd.pid" "$dir/slurmctld.pid" "$dir/munge/munged.pid"; do
        if [ -f "$f" ]; then
            pid=$(cat "$f")
            kill "$pid" 2>/dev/null && pids+=("$pid")
        fi
    done
    for _ in $(seq 100); do
        alive=0
        for pid in "${pids[@]}"; do kill -0 "$pid" 2>/dev/null && alive=1; done
        [ "$alive" = 0 ] && break
        sleep 0.1
    done
    ;;
esac
