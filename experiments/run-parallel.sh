#!/usr/bin/env bash
# Runs an experiment as N independent shards with GNU parallel on one machine
# (or several, with parallel's --sshlogin), then merges them:
#
#   experiments/run-parallel.sh EXP OUT N [lumibench run options...]
#   e.g. experiments/run-parallel.sh experiments/paper.json out/paper 4 --res 64
#
# Shard K of N runs the scenes with index % N == K-1 (lumibench run --shard)
# into OUT/shard-K-of-N/; `lumibench merge` then writes OUT/results.json,
# OUT/report.md and OUT/plots/. A shard that was interrupted resumes when this
# script is run again (finished cells are skipped). Environment: LUMIBENCH
# (the program, default build/lumibench), JOBS (shards at a time, default N),
# POCL_MAX_PTHREAD_COUNT (threads per shard on PoCL: cores / JOBS is fair).
set -euo pipefail
if [ $# -lt 3 ]; then
    echo "usage: $0 EXP OUT N [lumibench run options...]" >&2
    exit 2
fi
exp=$1 out=$2 n=$3
shift 3
bin=${LUMIBENCH:-build/lumibench}
jobs=${JOBS:-$n}
command -v parallel >/dev/null || { echo "$0: GNU parallel is missing (apt-get install parallel)" >&2; exit 2; }
mkdir -p "$out"
# -q quotes every argument, so paths with spaces survive; {} is the shard number.
seq 1 "$n" | parallel --will-cite --halt now,fail=1 -j "$jobs" -q \
    "$bin" run "$exp" --out "$out/shard-{}-of-$n" --shard "{}/$n" --no-report "$@"
shards=()
for k in $(seq 1 "$n"); do shards+=("$out/shard-$k-of-$n"); done
# --force: OUT holds this experiment's own shards, so a rerun (which resumes
# them) merges again over the earlier merge.
"$bin" merge --force --out "$out" "${shards[@]}"
echo "report: $out/report.md"
