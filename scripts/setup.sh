#!/usr/bin/env bash
# Installs the Debian 12 packages vbim needs, only the ones that are missing.
# Idempotent and non-interactive; run as root (or with sudo available). --with-slurm adds a
# single-node Slurm's packages (scripts/slurm-local.sh); --with-bench adds SystemC for the
# scheduler-cost benchmark.
set -euo pipefail

PACKAGES=(
  # toolchain (ccache: every build tree of scripts/build.sh, check-model.sh and fuzz.sh compiles through it)
  build-essential cmake pkg-config git ccache clang libclang-rt-14-dev clang-format clang-tidy
  # command line, config, JSON (header-only)
  libcli11-dev libtomlplusplus-dev nlohmann-json3-dev
  # SHA-256 of a run's inputs in stats.json (runs/provenance.cpp)
  libssl-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev
  # `man -l` checks the generated man page (tests/cli/habits_test.cpp, scripts/check-install.sh);
  # the generated completions are loaded in real shells by the same test
  man-db bash-completion zsh
  # media around the model: images, encoding, the comparison decoders, ffprobe
  libopenimageio-dev libpng-dev libdeflate-dev libopenexr-dev
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev ffmpeg
  libmpeg2-4-dev
  # libmpeg2 as a program: `vbim decode` is checked against `mpeg2dec -c` (tests/ipu/cli_decode_test.cpp)
  mpeg2dec
  # DEMs (GeoTIFF, ASCII grid, SRTM .hgt) and GeoTIFF debug layers for the lighting generator
  libgdal-dev
  # disc images
  xorriso
  # pictures
  libosmesa6-dev libglm-dev
  # plots (PLplot draws PNG and SVG through its cairo driver)
  libplplot-dev plplot-driver-cairo
  # portable SIMD with run-time dispatch
  libhwy-dev
)

# Only for the CI step that runs sweeps as Slurm job arrays (scripts/ci-slurm-sweep.sh).
if [[ " $* " == *" --with-slurm "* ]]; then
  PACKAGES+=(slurm-wlm munge)
fi
# Only for benchmark builds: bench_scheduler_cost compares the kernel with SystemC 2.3.4.
if [[ " $* " == *" --with-bench "* ]]; then
  PACKAGES+=(libsystemc-dev)
fi

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
  command -v sudo >/dev/null 2>&1 || { echo "setup: missing packages (${missing[*]}) and not root" >&2; exit 1; }
  SUDO="sudo"
fi
echo "setup: installing ${#missing[@]} missing packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
# Refresh the package lists once if they are empty or older than a day.
if [ -z "$(find /var/lib/apt/lists -maxdepth 1 -name '*Packages*' -mtime -1 2>/dev/null | head -1)" ]; then
  $SUDO apt-get update -qq
fi
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup: done"
