#!/usr/bin/env bash
# clang-tidy over the product source files the build compiles (not tests/: their test macros and
# fixtures are left to the compiler's warnings), with the checks of .clang-tidy (bench/.clang-tidy
# adds Google Benchmark's BM_ names); any warning fails. Uses the compile commands and the header
# dependencies of a built tree, BUILD_DIR (default build/, which scripts/test.sh makes).
#   scripts/check-tidy.sh [BUILD_DIR] [--all] [--list]   (--list: print the files it would check)
# By default only the files that can have changed since scripts/tidy-baseline (the last commit
# checked whole and clean) are checked: a file whose bytes changed or one of whose included headers
# changed (from the build's dependency lists), every file under a changed CMakeLists.txt, and every
# file when .clang-tidy, this script, the top-level CMakeLists.txt or cmake/ changed, or when the
# baseline is not in this clone's history (a shallow clone). clang-tidy is deterministic, so a file
# none of whose inputs changed has the baseline's result: clean. The whole check costs ~16 min on
# the 2-core CI machine, most of a CI run's budget; --all runs it (before moving the baseline).
set -euo pipefail
cd "$(dirname "$0")/.."
build=build
all=0
list=0
for arg in "$@"; do
  case "$arg" in
    --all) all=1 ;;
    --list) list=1 ;;
    -*) echo "check-tidy: unknown option $arg (expected --all or --list)" >&2; exit 2 ;;
    *) build=$arg ;;
  esac
done
if [ ! -f "$build/compile_commands.json" ]; then
  echo "check-tidy: no $build/compile_commands.json; configure a build first (bash scripts/test.sh)" >&2
  exit 1
fi
baseline=$(grep -E '^[0-9a-f]{40}$' scripts/tidy-baseline | tail -1)
changed=""
if [ "$all" = 0 ]; then
  if git cat-file -e "$baseline^{commit}" 2>/dev/null; then
    # Committed and uncommitted changes since the baseline, and new files not yet added.
    changed=$( (git diff --name-only "$baseline" --; git ls-files --others --exclude-standard) | sort -u)
  else
    echo "check-tidy: baseline $baseline is not in this clone's history; checking every file"
    all=1
  fi
fi
mapfile -t files < <(CHANGED="$changed" python3 - "$build" "$PWD" "$all" <<'PY'
import glob, json, os, re, sys
build, root, check_all = sys.argv[1], os.path.realpath(sys.argv[2]), sys.argv[3] == "1"
dirs = ("runtime", "iop", "ee", "ipu", "gs", "player", "sweep", "streams", "config", "runs", "cli", "lighting",
        "render", "help", "imageio", "plots", "bench")
sources = []
for entry in json.load(open(os.path.join(build, "compile_commands.json"))):
    path = os.path.realpath(os.path.join(entry["directory"], entry["file"]))
    rel = os.path.relpath(path, root)
    if rel.split(os.sep)[0] in dirs and rel.endswith(".cpp") and rel not in sources:
        sources.append(rel)
changed = set(filter(None, os.environ["CHANGED"].split("\n")))
everything = {".clang-tidy", "bench/.clang-tidy", "CMakeLists.txt", "scripts/check-tidy.sh"}
if check_all or changed & everything or any(c.startswith("cmake/") for c in changed):
    print("\n".join(sources))
    sys.exit(0)
# Each object's dependencies (the source and every header it included), from the build's depfiles:
# the compiler's own (OBJECT.o.d, written by every compile; its paths are relative to the directory
# the compile ran in, the target's binary directory), and CMake's consolidated compiler_depend.make,
# which stays empty in these trees (CMake 3.25, Makefiles): reading only that, every check found no
# dependencies and checked every file.
deps = {}
def add(files):
    if files:
        deps.setdefault(files[0], set()).update(files)
for depfile in glob.glob(os.path.join(build, "**", "*.o.d"), recursive=True):
    cwd = depfile.split(os.sep + "CMakeFiles" + os.sep)[0]
    rule = open(depfile).read().replace("\\\n", " ").split("\n")[0]  # the object's rule comes first
    m = re.match(r"^\S+\.o:\s+(.*)$", rule)
    if m:
        add([os.path.relpath(os.path.realpath(os.path.join(cwd, f)), root) for f in m.group(1).split()])
for make in glob.glob(os.path.join(build, "**", "compiler_depend.make"), recursive=True):
    text = open(make).read().replace("\\\n", " ")
    for line in text.splitlines():
        m = re.match(r"^(\S+\.cpp\.o):\s+(.*)$", line)
        if m:
            add([os.path.relpath(os.path.realpath(f), root) for f in m.group(2).split()])
cmake_dirs = [os.path.dirname(c) for c in changed if os.path.basename(c) == "CMakeLists.txt"]
for rel in sources:
    if rel not in deps:  # no dependency list (not built yet): check it
        print(rel)
    elif deps[rel] & changed or any(rel.startswith(d + os.sep) for d in cmake_dirs):
        print(rel)
PY
)
if [ "$all" = 1 ]; then scope="every file"; else scope="the files that changed since ${baseline:0:12}"; fi
echo "check-tidy: ${#files[@]} files ($scope)"
if [ "$list" = 1 ]; then
  [ ${#files[@]} -eq 0 ] || printf '%s\n' "${files[@]}"
  exit 0
fi
[ ${#files[@]} -gt 0 ] || { echo "check-tidy: clean"; exit 0; }
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
