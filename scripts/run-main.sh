#!/usr/bin/env bash
# Installs the dependencies, builds, and runs the main job: lists the OpenCL
# devices and renders one small image of the evaluation scene.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
./build/lumibench devices
