#!/usr/bin/env bash
# Builds the IPU picture-decoder fuzzer with clang-14 (libFuzzer + ASan + UBSan) in its own build
# directory and runs it for a bounded time from the committed seed corpus.
#   scripts/fuzz-ipu.sh [SECONDS]      default 60; FUZZ_BUILD_DIR overrides build-fuzz-ipu/
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-${FUZZ_SECONDS:-60}}"
build="${FUZZ_BUILD_DIR:-build-fuzz-ipu}"
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
  -DVBIM_FUZZ=ON -DVBIM_BUILD_BENCH=OFF -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" > /dev/null
cmake --build "$build" -j2 --target ipu_picture_fuzzer
# New inputs go to a scratch directory; the committed corpus is only read.
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
"$build/tests/ipu/ipu_picture_fuzzer" -max_total_time="$seconds" -max_len=65536 -timeout=10 -rss_limit_mb=2048 \
  -print_final_stats=1 "$work" tests/ipu/fuzz/corpus
