#!/usr/bin/env bash
# Installs every Debian package lumibench needs to build (ccache: scripts/build.sh
# uses it where present, so clones share compiled objects), test and plot
# (python3-pandas and python3-seaborn: the tests that results.csv loads and that
# the docs' examples run on it; chromium: the test that
# opens report.html in a headless browser), and
# the project-local Python environment .venv/ (PyPI packages the tests use as
# independent peers, and flip-evaluator for the flip metric). Idempotent:
# re-running it on a machine that has everything only checks.
#
# --oidn also installs pyoidn (Intel Open Image Denoise, ~90 MB) and OpenEXR's
# Python bindings into .venv: only experiments/mc-baselines/oidn_ceiling.py
# needs them (no test does).
set -euo pipefail
cd "$(dirname "$0")/.."
OIDN=0
for arg in "$@"; do
  case "$arg" in
    --oidn) OIDN=1 ;;
    *) echo "install-deps: unknown option '$arg' (expected --oidn)" >&2; exit 2 ;;
  esac
done
PKGS=(
  build-essential cmake pkg-config ccache
  pocl-opencl-icd ocl-icd-opencl-dev opencl-headers opencl-clhpp-headers clinfo
  libglm-dev libopenexr-dev libnlopt-cxx-dev libnlopt-dev
  googletest libgtest-dev
  libcli11-dev nlohmann-json3-dev libfmt-dev libpng-dev jq clang-format-14
  python3 python3-matplotlib python3-numpy python3-pandas python3-seaborn python3-venv
  python3-dev  # the Python module's extension (python/, docs/python.md)
  chromium
  parallel
  slurmctld slurmd slurm-client munge
)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PKGS[@]} packages present"
else
  echo "install-deps: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO=sudo
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# .venv: Debian's python3 with its site packages (matplotlib, numpy, pandas) plus the
# pinned PyPI packages: eulumdat-py (the LDT reader's peer test), pyradiance
# (Radiance's ies2rad, oconv and rtrace: the reference's peer test) and
# flip-evaluator (NVIDIA's FLIP, the `flip` metric: host/metrics/flip.h).
# Without PyPI the peer and FLIP tests skip and say so, and flip is null.
PYPI=(eulumdat-py==1.0.0 flip-evaluator==1.7 pyradiance==1.3.1)
if [ "$OIDN" -eq 1 ]; then PYPI+=(pyoidn==2.5.1.0 OpenEXR==3.5.3); fi
# The Python module (python/, docs/python.md): nanobind and scikit-build-core build it,
# pytest runs its tests; it uses Debian's numpy and pandas (python3-numpy, python3-pandas).
PYPI+=(nanobind==3.1.0 scikit-build-core==1.1.2 pytest==8.4.2)
VENV=.venv
if [ ! -x "$VENV/bin/python" ]; then
  /usr/bin/python3 -m venv --system-site-packages "$VENV"
fi
# (pip asks no index when the pinned versions are already there)
if "$VENV/bin/python" -m pip install -q --disable-pip-version-check "${PYPI[@]}"; then
  echo "install-deps: $VENV has ${PYPI[*]}"
else
  echo "install-deps: WARNING: could not install ${PYPI[*]} into $VENV; the peer and FLIP tests will skip" \
       "and flip will be null" >&2
fi
"$VENV/bin/python" -c 'import pandas' || { echo "install-deps: $VENV cannot import pandas (python3-pandas)" >&2; exit 1; }
# The Python module: build/python on .venv's path (filled by scripts/build.sh).
bash scripts/python-path.sh
