#!/usr/bin/env bash
# Configures and builds lumibench into build/ (Release). Extra arguments go to cmake.
# Where ccache is installed it is the compiler launcher, with paths taken relative
# to the source tree so that clones and worktrees share its cache. Then puts the
# Python module (build/python/lumibench, docs/python.md) on the path of the
# project's .venv (scripts/python-path.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
launcher=()
if command -v ccache >/dev/null; then
    export CCACHE_BASEDIR="$PWD"
    launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
python=()  # the Python module is built for the project's .venv (python/CMakeLists.txt)
[ -x .venv/bin/python ] && python=(-DPython_EXECUTABLE="$PWD/.venv/bin/python")
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" "${python[@]}" "$@" >/dev/null
cmake --build build -j "$(nproc)"

bash scripts/python-path.sh
