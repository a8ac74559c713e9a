#!/usr/bin/env bash
# The main job: installs the dependencies, builds, lists the OpenCL devices
# and runs point, SCT (cubature), robust, tuned, engine and sh at equal time
# against four Monte Carlo baselines on the seven luminaires, then names the
# report.
#
#   bash scripts/run-main.sh           experiments/main.json: a subset of the
#                                      published evaluation that answers in
#                                      minutes (3 heights x 2 rotations, 32 x 32
#                                      pixels, timed at 128 x 128; run and
#                                      report 502 s of CPU without engine and
#                                      sh; the runs that added engine's and
#                                      sh's cells, each with its report, 108 s
#                                      and 358 s:
#                                      docs/studies/main-job-baselines.md)
#   FULL=1 bash scripts/run-main.sh    experiments/paper.json: the whole
#                                      published evaluation (6 heights x 5
#                                      rotations, MCI curve to N = 1024)
#
# Luminaires: the seven Zumtobel files of the paper in ../shared/luminaires/zumtobel
# when present, else the suite's own in luminaires/. RES (default 32) and
# TIME_RES (default 128; the equal-time protocol's own default is 512) set the
# error images' and the timed launches' pixels per side. Results, table and
# report: OUT (default out/main, with FULL=1 out/paper)/{results.json,
# results.csv,report.html,report.md,plots/,images/}. Rerunning resumes.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
./build/lumibench devices
if [ "${FULL:-0}" = 1 ]; then
  exp=experiments/paper.json
  out=${OUT:-out/paper}
else
  exp=experiments/main.json
  out=${OUT:-out/main}
fi
lum=()
if [ -d ../shared/luminaires/zumtobel ]; then lum=(--luminaires ../shared/luminaires/zumtobel); fi
echo "run-main: $exp -> $out (progress with ETA below, one line per scene)"
./build/lumibench run "$exp" --out "$out" --res "${RES:-32}" --time-res "${TIME_RES:-128}" "${lum[@]}"
echo "report: $out/report.html (open it in a browser; also $out/report.md, the records as a table: $out/results.csv)"
