#!/usr/bin/env bash
# Builds every libFuzzer target with clang-14 (libFuzzer + ASan + UBSan) in its own build directory
# and runs each for a bounded time from its committed seed corpus (new inputs go to a scratch
# directory; the corpora are only read). Prints executions per second per target.
#   scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]
#     default 45 s for each of the 7 targets (about 6 min in CI with the build cached);
#     FUZZ_BUILD_DIR overrides build-fuzz/ (and build-fuzz-model/).
# Targets: ipu_picture_fuzzer (tests/ipu/fuzz) and those of tests/fuzz (stream, descriptor,
# platform_toml, fault_plan_toml, iso, player).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-${FUZZ_SECONDS:-45}}"
shift || true
all=(ipu_picture_fuzzer stream_fuzzer descriptor_fuzzer platform_toml_fuzzer fault_plan_toml_fuzzer iso_fuzzer
  player_fuzzer)
if [ $# -gt 0 ]; then targets=("$@"); else targets=("${all[@]}"); fi
build="${FUZZ_BUILD_DIR:-build-fuzz}"
# Targets that link the coroutine-based model (config, iop, player) build without UBSan in their own
# directory: clang-14 cannot assemble a coroutine frame compiled with -fsanitize=fuzzer-no-link and
# undefined together ("Cannot represent a difference across sections").
model=" platform_toml_fuzzer fault_plan_toml_fuzzer iso_fuzzer player_fuzzer "
configure() {  # build dir, sanitizers
  local flags="-fsanitize=fuzzer-no-link,$2 -fno-sanitize-recover=all -fno-omit-frame-pointer"
  cmake -S . -B "$1" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER_LAUNCHER="$(command -v ccache || true)" \
    -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 -DVBIM_FUZZ=ON -DVBIM_BUILD_BENCH=OFF \
    -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=$2" > /dev/null
}
plain=() withModel=()
for t in "${targets[@]}"; do
  if [[ "$model" == *" $t "* ]]; then withModel+=("$t"); else plain+=("$t"); fi
done
if [ ${#plain[@]} -gt 0 ]; then
  configure "$build" address,undefined
  cmake --build "$build" -j2 --target "${plain[@]}"
fi
if [ ${#withModel[@]} -gt 0 ]; then
  configure "$build-model" address
  cmake --build "$build-model" -j2 --target "${withModel[@]}"
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
summary=""
for t in "${targets[@]}"; do
  if [ "$t" = ipu_picture_fuzzer ]; then
    exe="$build/tests/ipu/$t" corpus=tests/ipu/fuzz/corpus maxLen=65536
  else
    dir="$build"
    [[ "$model" == *" $t "* ]] && dir="$build-model"
    exe="$dir/tests/fuzz/$t" corpus="tests/fuzz/corpus/${t%_fuzzer}" maxLen=400000
  fi
  mkdir -p "$work/$t"
  "$exe" -max_total_time="$seconds" -max_len="$maxLen" -timeout=20 -rss_limit_mb=2048 -print_final_stats=1 \
    "$work/$t" "$corpus" 2>&1 | tee "$work/$t.log" | grep -E "^#[0-9]+ +DONE|ERROR|SUMMARY|Test unit" || true
  rc=${PIPESTATUS[0]}
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/$t.log")
  summary+=$(printf '%-24s %10s executions in %3s s (%s/s)%s' "$t" "${runs:-0}" "$seconds" \
    "$(( ${runs:-0} / seconds ))" "$([ "$rc" = 0 ] || echo "  FAILED (exit $rc)")")$'\n'
  if [ "$rc" != 0 ]; then
    tail -40 "$work/$t.log"
    printf '%s' "$summary"
    exit 1
  fi
done
printf '%s' "$summary"
