#!/usr/bin/env bash
# An experiment as a Slurm job array: one array task per shard, then a merge.
#
#   jid=$(sbatch --parsable --array=1-8 experiments/slurm-array.sh run EXP OUT [run options...])
#   sbatch --dependency=afterok:$jid experiments/slurm-array.sh merge OUT 8
#
# Array task K of N (N = the number of tasks in --array=1-N) runs
# `lumibench run EXP --shard K/N --out OUT/shard-K-of-N` (the scenes with
# index % N == K-1); the merge job writes OUT/results.json, report.md, plots/.
# OUT must be on a file system every node sees. Resubmitting the array after a
# failure resumes: finished cells are skipped. LUMIBENCH overrides the program
# (default build/lumibench, relative to the submit directory).
#
# The array size is given on the command line (--array=1-N), not here, so
# that the merge job submitted with the same script is a single job; add
# --cpus-per-task, --time, --partition as the cluster wants (PoCL then uses
# SLURM_CPUS_PER_TASK threads). experiments/slurm-local.sh starts a one-node
# Slurm for trying this (a test does: tests/experiments/test_runner.cpp).
#SBATCH --job-name=lumibench
#SBATCH --output=lumibench-%A_%a.out
set -euo pipefail
bin=${LUMIBENCH:-build/lumibench}
mode=${1:-}
case "$mode" in
run)
    exp=$2 out=$3
    shift 3
    : "${SLURM_ARRAY_TASK_ID:?run this with sbatch --array=1-N}"
    n=${SLURM_ARRAY_TASK_COUNT:-$((SLURM_ARRAY_TASK_MAX - SLURM_ARRAY_TASK_MIN + 1))}
    k=$((SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN + 1))
    if [ -n "${SLURM_CPUS_PER_TASK:-}" ]; then export POCL_MAX_PTHREAD_COUNT=$SLURM_CPUS_PER_TASK; fi
    exec "$bin" run "$exp" --out "$out/shard-$k-of-$n" --shard "$k/$n" --no-report "$@"
    ;;
merge)
    out=$2 n=$3
    shards=()
    for k in $(seq 1 "$n"); do shards+=("$out/shard-$k-of-$n"); done
    # --force: OUT holds this experiment's own shards; a rerun merges again.
    exec "$bin" merge --force --out "$out" "${shards[@]}"
    ;;
*)
    echo "usage: sbatch --array=1-N $0 run EXP OUT [options] | sbatch $0 merge OUT N" >&2
    exit 2
    ;;
esac
