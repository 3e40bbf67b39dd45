#!/usr/bin/env bash
# Installs every Debian 12 package rearm needs, and only those that are missing.
# Runs `apt-get update` first whenever something is missing. Safe to run repeatedly.
set -euo pipefail

PACKAGES=(
  # toolchain
  build-essential cmake git python3 pkg-config ca-certificates
  # faster builds: Ninja (scripts/test.sh's generator) and the lld linker (CMakeLists.txt)
  ninja-build lld
  # libraries (design card)
  libeigen3-dev libcgal-dev libgmp-dev libmpfr-dev libbox2d-dev libompl-dev
  libboost-filesystem-dev libboost-serialization-dev libboost-system-dev
  libtbb-dev libbenchmark-dev libgtest-dev libgmock-dev libyaml-cpp-dev libmimalloc-dev
  # the command line
  libcli11-dev
  # the result files' JSON (metrics.json, trajectory.json, diffeo.json; header-only)
  nlohmann-json3-dev
  # independent LTL translator used by the tests; plotting
  spin python3-matplotlib python3-pil
  # the fuzz targets (tests/fuzz): clang with its sanitizer and libFuzzer runtimes; the code
  # checks of scripts/check_style.sh (clang-format, universal ctags for function lengths)
  clang libclang-rt-14-dev clang-format universal-ctags
  # ompl_benchmark_statistics (the sweep's OMPL benchmark logs into SQLite, tested); the
  # sweep's cluster recipes: a single-node Slurm (experiments/slurm) and GNU parallel
  ompl-demos slurm-wlm munge parallel
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PACKAGES[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "setup: need root (or sudo) to install: ${missing[*]}" >&2; exit 1
  fi
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update
$SUDO apt-get install -y --no-install-recommends "${missing[@]}"
