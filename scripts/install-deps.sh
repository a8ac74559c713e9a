#!/usr/bin/env bash
# Installs every Debian package lumibench needs to build, test and plot.
# Idempotent: re-running it on a machine that has everything only checks.
set -euo pipefail
PKGS=(
  build-essential cmake pkg-config
  pocl-opencl-icd ocl-icd-opencl-dev opencl-headers opencl-clhpp-headers clinfo
  libglm-dev libopenexr-dev libnlopt-cxx-dev libnlopt-dev
  googletest libgtest-dev
  libcli11-dev nlohmann-json3-dev libfmt-dev libpng-dev jq
  python3 python3-matplotlib python3-numpy
  parallel
  slurmctld slurmd slurm-client munge
)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PKGS[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO=sudo
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
