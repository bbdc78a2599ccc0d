#!/usr/bin/env bash
# Installs the Debian packages granmc needs, skipping those already present.
# Used by `make run`, `make test` and `make bench`; safe to run again (it does nothing when all are there).
# MPI (OpenMPI, for replicas over ranks, docs/user-guide/parallel-runs.md) is opt-in: `scripts/setup-deps.sh --mpi` or
# GRANMC_MPI=1 (also ON) adds openmpi-bin and libopenmpi-dev; `make mpi` and `make test` ask for it.
set -euo pipefail

with_mpi=0
case "${GRANMC_MPI:-0}" in 1|ON|on|On|YES|yes|TRUE|true) with_mpi=1 ;; esac
for arg in "$@"; do
  case "$arg" in
    --mpi) with_mpi=1 ;;
    *) echo "setup: unknown argument $arg (only --mpi)" >&2; exit 2 ;;
  esac
done

packages=(
  cmake g++ make libgomp1
  libxsimd-dev libhdf5-dev librandom123-dev libtomlplusplus-dev libcli11-dev
  nlohmann-json3-dev libgtest-dev libbenchmark-dev
  python3 python3-matplotlib python3-h5py python3-pytest python3-pip python3-venv python3-setuptools python3-wheel
  clang-format python3-pyflakes
)
if [ "$with_mpi" = 1 ]; then packages+=(openmpi-bin libopenmpi-dev); fi

missing=()
for p in "${packages[@]}"; do
  if dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then :; else missing+=("$p"); fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} Debian packages present"
  exit 0
fi

echo "setup: missing Debian packages: ${missing[*]}"
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    SUDO=sudo
  else
    echo "setup: installing them needs root. Run as root, or install them yourself:" >&2
    echo "  sudo apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
else
  SUDO=
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq "${missing[@]}"
echo "setup: installed ${missing[*]}"
