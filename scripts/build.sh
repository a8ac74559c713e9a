#!/usr/bin/env bash
# Configures and builds lumibench into build/ (Release). Extra arguments go to cmake.
# Where ccache is installed it is the compiler launcher, with paths taken relative
# to the source tree so that clones and worktrees share its cache.
set -euo pipefail
cd "$(dirname "$0")/.."
launcher=()
if command -v ccache >/dev/null; then
    export CCACHE_BASEDIR="$PWD"
    launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" "$@" >/dev/null
cmake --build build -j "$(nproc)"
