#!/usr/bin/env bash
# Configures and builds vbim into a build directory (default: build/, Release).
#   scripts/build.sh [build-dir] [extra cmake args...]
set -euo pipefail
cd "$(dirname "$0")/.."
dir="${1:-build}"
shift || true
# Through ccache when it is there (scripts/setup.sh installs it): a rebuild of an unchanged file, in
# this tree or in another clone (CCACHE_BASEDIR makes the cached paths relative), is a cache hit.
launcher=()
if command -v ccache >/dev/null 2>&1; then
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE="${VBIM_BUILD_TYPE:-Release}" "${launcher[@]}" "$@" >/dev/null
cmake --build "$dir" -j"$(nproc)"
