#!/usr/bin/env bash
# clang-tidy over every product source file the build compiles (not tests/: their test macros and
# fixtures are left to the compiler's warnings), with the checks of .clang-tidy (bench/.clang-tidy
# adds Google Benchmark's BM_ names); any warning fails. Uses the compile commands of a configured
# build, BUILD_DIR (default build/, which scripts/test.sh makes).
#   scripts/check-tidy.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
if [ ! -f "$build/compile_commands.json" ]; then
  echo "check-tidy: no $build/compile_commands.json; configure a build first (bash scripts/test.sh)" >&2
  exit 1
fi
mapfile -t files < <(python3 - "$build/compile_commands.json" "$PWD" <<'PY'
import json, os, sys
root = os.path.realpath(sys.argv[2])
dirs = ("runtime", "iop", "ee", "ipu", "gs", "player", "sweep", "streams", "config", "cli", "lighting", "render",
        "imageio", "plots", "bench")
seen = set()
for entry in json.load(open(sys.argv[1])):
    path = os.path.realpath(os.path.join(entry["directory"], entry["file"]))
    rel = os.path.relpath(path, root)
    if rel.split(os.sep)[0] in dirs and rel.endswith(".cpp") and rel not in seen:
        seen.add(rel)
        print(rel)
PY
)
echo "check-tidy: ${#files[@]} files"
# -Wno-unknown-warning-option: the build's GCC-only flags (-Wno-restrict) are unknown to clang.
# run-clang-tidy 14 has no -warnings-as-errors: the diagnostics are read from its output.
status=0
run-clang-tidy -quiet -j "$(nproc)" -p "$build" -extra-arg=-Wno-unknown-warning-option "${files[@]}" \
  >"$build/clang-tidy.log" 2>&1 || status=$?
findings=$(sed 's/\x1b\[[0-9;]*m//g' "$build/clang-tidy.log" | grep -E "^[^ ]+:[0-9]+:[0-9]+: (warning|error):" | sort -u || true)
if [ "$status" -ne 0 ] || [ -n "$findings" ]; then
  [ -z "$findings" ] || echo "$findings" >&2
  echo "check-tidy: FAILED (run-clang-tidy exit $status; full output in $build/clang-tidy.log)" >&2
  exit 1
fi
echo "check-tidy: clean"
