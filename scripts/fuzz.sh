#!/usr/bin/env bash
# Builds every libFuzzer target with clang-14 (libFuzzer + ASan + UBSan) in its own build directory
# and runs each for a bounded time from its committed seed corpus (new inputs go to a scratch
# directory; the corpora are only read). Prints executions per second per target.
#   scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]
#     default 45 s for each of the 9 targets, FUZZ_JOBS of them side by side (default: one per core;
#     about 4 min of fuzzing in CI on 2 cores);
#     FUZZ_BUILD_DIR overrides build-fuzz/ (and build-fuzz-model/);
#     FUZZ_MAX_RUNS=N also stops a target after N executions (the long campaign of
#     docs/reliability.md: FUZZ_MAX_RUNS=10000000 scripts/fuzz.sh 1800);
#     FUZZ_WORK_DIR keeps the inputs each target finds (default: a scratch directory, removed).
# Targets: ipu_picture_fuzzer (tests/ipu/fuzz) and those of tests/fuzz (stream, descriptor,
# platform_toml, fault_plan_toml, iso, player, image, dem).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-${FUZZ_SECONDS:-45}}"
shift || true
all=(ipu_picture_fuzzer stream_fuzzer descriptor_fuzzer platform_toml_fuzzer fault_plan_toml_fuzzer iso_fuzzer
  player_fuzzer image_fuzzer dem_fuzzer)
if [ $# -gt 0 ]; then targets=("$@"); else targets=("${all[@]}"); fi
build="${FUZZ_BUILD_DIR:-build-fuzz}"
# Targets that link the coroutine-based model (config, iop, player, or the kernel under lighting)
# build without UBSan in their own directory: clang-14 cannot assemble a coroutine frame compiled with -fsanitize=fuzzer-no-link and
# undefined together ("Cannot represent a difference across sections").
model=" platform_toml_fuzzer fault_plan_toml_fuzzer iso_fuzzer player_fuzzer image_fuzzer dem_fuzzer "
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
if [ -n "${FUZZ_WORK_DIR:-}" ]; then
  work="$FUZZ_WORK_DIR"
  mkdir -p "$work"
else
  work="$(mktemp -d)"
  trap 'rm -rf "$work"' EXIT
fi
maxRuns=()
[ -n "${FUZZ_MAX_RUNS:-}" ] && maxRuns=(-runs="$FUZZ_MAX_RUNS")
asanOptions=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# OpenImageIO 2.4's PNG reader leaks its error string when libpng long-jumps out of a truncated file
# (PNGInput::PngReadCallback); the suppression needs full stacks through the uninstrumented library.
declare -A extraAsan=([image_fuzzer]=":fast_unwind_on_malloc=0")
declare -A lsanOptions=([image_fuzzer]="suppressions=$PWD/tests/fuzz/lsan.supp")
# One target: its log, exit status and summary line go to files in $work, so that targets can run
# side by side (each libFuzzer process is single-threaded: one per core halves a CI run's fuzzing
# wall time at the same time and executions per target).
fuzzOne() {
  local t=$1 exe corpus maxLen dir
  if [ "$t" = ipu_picture_fuzzer ]; then
    exe="$build/tests/ipu/$t" corpus=tests/ipu/fuzz/corpus maxLen=65536
  else
    dir="$build"
    [[ "$model" == *" $t "* ]] && dir="$build-model"
    exe="$dir/tests/fuzz/$t" corpus="tests/fuzz/corpus/${t%_fuzzer}" maxLen=400000
    # picture and DEM files: small inputs can still claim (and decompress to) large grids
    case "$t" in image_fuzzer | dem_fuzzer) maxLen=65536 ;; esac
  fi
  mkdir -p "$work/$t"
  local start rc runs elapsed
  start=$(date +%s)
  rc=0
  ASAN_OPTIONS="$asanOptions${extraAsan[$t]:-}" LSAN_OPTIONS="${lsanOptions[$t]:-}" "$exe" "${maxRuns[@]}" \
    -max_total_time="$seconds" -max_len="$maxLen" -timeout=20 -rss_limit_mb=2048 -print_final_stats=1 \
    "$work/$t" "$corpus" >"$work/$t.log" 2>&1 || rc=$?
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/$t.log")
  elapsed=$(($(date +%s) - start))
  [ "$elapsed" -gt 0 ] || elapsed=1
  printf '%-24s %10s executions in %4s s (%s/s)%s\n' "$t" "${runs:-0}" "$elapsed" \
    "$((${runs:-0} / elapsed))" "$([ "$rc" = 0 ] || echo "  FAILED (exit $rc)")" >"$work/$t.summary"
  echo "$rc" >"$work/$t.rc"
}
parallel=${FUZZ_JOBS:-$(nproc)}
for t in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$parallel" ]; do wait -n || true; done
  fuzzOne "$t" &
done
wait
failed=0
for t in "${targets[@]}"; do
  grep -E "^#[0-9]+ +DONE|ERROR|SUMMARY|Test unit" "$work/$t.log" | sed "s/^/$t: /" || true
  if [ "$(cat "$work/$t.rc" 2>/dev/null || echo 1)" != 0 ]; then
    echo "== $t: last 40 lines of its log"
    tail -40 "$work/$t.log"
    failed=1
  fi
done
for t in "${targets[@]}"; do cat "$work/$t.summary"; done
exit "$failed"
