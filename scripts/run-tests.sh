#!/usr/bin/env bash
# Installs the dependencies, checks the C++ formatting (scripts/check-format.sh),
# that no host function exceeds 80 lines (scripts/long-functions.py) and no
# kernel function exceeds 80 lines or 8 parameters (scripts/kernel-limits.py),
# that every file, section and anchor README.md and docs/ link to exists
# (scripts/check-links.py), that a method is looked up by name only in the
# registry and the SPEC parser (scripts/family-lookup.py), that the README's
# headline is the one its committed results give (scripts/readme-headline.py
# --check), builds, and runs the whole test suite on the default OpenCL device
# (PoCL): the GoogleTest suite, then the Python module's pytest suite (python/tests).
# Tests that need a device fail rather than skip.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/check-format.sh
python3 scripts/long-functions.py --check 80 $(git ls-files 'host/*.cpp' 'host/*.h' 'python/*.cpp' 'python/*.h')
python3 scripts/kernel-limits.py --self-test
python3 scripts/kernel-limits.py $(git ls-files 'kernels/*.h' 'kernels/*.inc' 'kernels/*.cl')
python3 scripts/check-links.py --self-test
python3 scripts/check-links.py
python3 scripts/family-lookup.py --self-test
python3 scripts/family-lookup.py $(git ls-files 'host/*.cpp' 'host/*.h')
python3 scripts/readme-headline.py --self-test
python3 scripts/readme-headline.py --check
bash scripts/build.sh
export LUMIBENCH_REQUIRE_DEVICE=1
export POCL_MAX_PTHREAD_COUNT="${POCL_MAX_PTHREAD_COUNT:-$(nproc)}"
cd build
ctest --output-on-failure -j "$(nproc)" --timeout 900
cd ..
# The Python module on this checkout's build (PYTHONPATH, whatever .venv's
# .pth names); pytest's exit code 5 (no tests collected) fails like any other.
PYTHONPATH="$PWD/build/python" .venv/bin/python -m pytest -q -p no:cacheprovider python/tests
# and importable from .venv as the README's set-up leaves it, where .venv is this checkout's
if [[ $(realpath .venv) == "$(realpath .)"/* ]]; then
    venv_python="$PWD/.venv/bin/python"
    (cd /tmp && "$venv_python" -c 'import lumibench; print("run-tests: lumibench from", lumibench.__file__)')
fi
