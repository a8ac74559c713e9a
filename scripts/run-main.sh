#!/usr/bin/env bash
# Installs the dependencies, builds, lists the OpenCL devices and runs the
# published evaluation (experiments/paper.json) at a resolution that finishes
# in minutes on 2 cores (RES, default 32, about 23 min on the 7 Zumtobel files;
# the published figures use 512), every method timed at TIME_RES x TIME_RES
# pixels (default 128 here; the equal-time protocol's own default is 512).
# Luminaires: the seven Zumtobel files of the paper in ../shared/luminaires/zumtobel
# when present, else the suite's own in luminaires/. Results, report and plots:
# OUT (default out/paper)/{results.json,report.md,plots/}. Rerunning resumes.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
./build/lumibench devices
out=${OUT:-out/paper}
lum=()
if [ -d ../shared/luminaires/zumtobel ]; then lum=(--luminaires ../shared/luminaires/zumtobel); fi
./build/lumibench run experiments/paper.json --out "$out" --res "${RES:-32}" --time-res "${TIME_RES:-128}" "${lum[@]}"
echo "report: $out/report.md"
