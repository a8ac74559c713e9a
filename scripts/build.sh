#!/usr/bin/env bash
# Configures and builds lumibench into build/ (Release). Extra arguments go to cmake.
# Where ccache is installed it is the compiler launcher, with paths taken relative
# to the source tree so that clones and worktrees share its cache. Then puts the
# Python module (build/python/lumibench, docs/python.md) on the path of the
# project's .venv.
set -euo pipefail
cd "$(dirname "$0")/.."
launcher=()
if command -v ccache >/dev/null; then
    export CCACHE_BASEDIR="$PWD"
    launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" "$@" >/dev/null
cmake --build build -j "$(nproc)"

# The module is importable from .venv through a .pth file naming build/python,
# written when the build made the module and .venv is this checkout's own (a
# worktree whose .venv links to another checkout's leaves that one's path alone).
if compgen -G "build/python/lumibench/_core*.so" >/dev/null && [ -x .venv/bin/python ]; then
    if [[ $(realpath .venv) == "$(realpath .)"/* ]]; then
        site=$(.venv/bin/python -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
        echo "$PWD/build/python" >"$site/lumibench.pth.tmp"
        mv -f "$site/lumibench.pth.tmp" "$site/lumibench.pth"
    else
        echo "build.sh: .venv is another checkout's; import this checkout's module with PYTHONPATH=$PWD/build/python"
    fi
fi
