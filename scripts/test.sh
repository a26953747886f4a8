#!/usr/bin/env bash
# README command 2: install what is missing, build, run the whole test suite through ctest.
#   scripts/test.sh                 Release build in build/
#   VBIM_SANITIZE=1 scripts/test.sh ASan+UBSan build in build-asan/
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
if [ "${VBIM_SANITIZE:-0}" = 1 ]; then
  # -O1 with line tables: readable sanitizer reports at a fraction of a full -g build's compile
  # time (CI builds this tree twice). Benchmarks are not built.
  VBIM_BUILD_TYPE=RelWithDebInfo scripts/build.sh build-asan -DVBIM_SANITIZE=ON -DVBIM_BUILD_BENCH=OFF \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1"
  cd build-asan
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  # Mesa's own leaks only (see the file); ours are never suppressed.
  export LSAN_OPTIONS="suppressions=$PWD/../scripts/lsan.supp:print_suppressions=0"
  # Soak tests (many repetitions of one scenario at random moments) make a quarter of their
  # repetitions here: the Release suite runs them whole (tests/support/soak.hpp).
  export VBIM_TEST_SOAK_SCALE=4
else
  scripts/build.sh build
  cd build
fi
ctest --output-on-failure -j"$(nproc)"
