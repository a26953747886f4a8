#!/usr/bin/env bash
# Proof that the model is portable (issue #14, "The portable model is enforced by the build"):
# configures and builds -DVBIM_MODEL_ONLY=ON in BUILD_DIR (default build-model/) with no third-party
# header reachable and no package of this machine findable by CMake, runs the model's tests, and
# fails if any program links more than the C and C++ runtime.
#
# No third-party header: the compiler runs with -nostdinc -nostdinc++ and, as -isystem, the
# directories `g++ -xc++ -E -v` searches, in the same order, each replaced by a copy made of symbolic
# links that holds only the files of the C library, kernel, libstdc++ and libgcc development
# packages (dpkg -L). GoogleTest's headers come from a second such copy that only the test programs
# see. A model file that includes anything else (toml++, OpenImageIO, ...) fails to compile.
#   scripts/check-model.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-model}
mkdir -p "$build"
build=$(cd "$build" && pwd)
farm=$build/include-farm
jobs=$(nproc)

step() { echo "check-model: $*"; }
fail() {
  echo "check-model: FAILED: $*" >&2
  exit 1
}

gccv=$(g++ -dumpversion)
gccv=${gccv%%.*}
system_packages=(libc6-dev linux-libc-dev "libstdc++-$gccv-dev" "libgcc-$gccv-dev")
test_packages=(libgtest-dev libgmock-dev)

# link_headers DEST PACKAGE...: DEST/<path> -> <path> for each header file the packages install.
link_headers() {
  local dest=$1
  shift
  mkdir -p "$dest"
  dpkg -L "$@" | grep -E '^/usr/(include|lib/gcc)/' | while IFS= read -r p; do
    if [ -L "$p" ] || [ -f "$p" ]; then printf '%s\0' "$p"; fi
  done | xargs -0 cp -P -s --parents -t "$dest" || fail "dpkg -L $*"
}

step "header farm from ${system_packages[*]} in $farm"
rm -rf "$farm"
link_headers "$farm/system" "${system_packages[@]}"
link_headers "$farm/gtest" "${test_packages[@]}"

# search_dirs LANG: the compiler's own #include <...> directories, in order.
search_dirs() {
  g++ -x"$1" -E -v - </dev/null 2>&1 |
    sed -n '/^#include <\.\.\.> search starts here:/,/^End of search list\./p' | sed '1d;$d' |
    while read -r d; do realpath -m "$d"; done
}
# farm_flags LANG: -nostdinc (-nostdinc++) and -isystem <farm>/<dir> for each of them.
farm_flags() {
  local flags="-nostdinc"
  [ "$1" = c++ ] && flags="$flags -nostdinc++"
  local d
  for d in $(search_dirs "$1"); do
    mkdir -p "$farm/system$d"  # e.g. /usr/local/include: searched, but nothing of it is copied
    flags="$flags -isystem $farm/system$d"
  done
  echo "$flags"
}
cxx_flags=$(farm_flags c++)
c_flags=$(farm_flags c)
[ -f "$farm/system/usr/include/c++/$gccv/vector" ] || fail "libstdc++ headers missing from the farm"
[ ! -e "$farm/system/usr/include/toml++" ] || fail "the farm holds toml++"

lib_of() { dpkg -L "$1" | grep -E "/$2\$" | head -1; }
gtest_libs=(-DGTEST_INCLUDE_DIR="$farm/gtest/usr/include"
  -DGTEST_LIBRARY="$(lib_of libgtest-dev libgtest.a)" -DGTEST_MAIN_LIBRARY="$(lib_of libgtest-dev libgtest_main.a)"
  -DGMOCK_LIBRARY="$(lib_of libgmock-dev libgmock.a)" -DGMOCK_MAIN_LIBRARY="$(lib_of libgmock-dev libgmock_main.a)")
launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi

step "configuring the model only in $build"
# CMake finds nothing on this machine by itself (no system prefixes, no PATH-derived prefixes, no
# registries): the tools and GoogleTest are handed over explicitly; the model must need nothing else.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DVBIM_MODEL_ONLY=ON -DVBIM_BUILD_BENCH=OFF \
  -DCMAKE_C_COMPILER="$(command -v gcc)" -DCMAKE_CXX_COMPILER="$(command -v g++)" "${launcher[@]}" \
  -DCMAKE_MAKE_PROGRAM="$(command -v make)" \
  -DCMAKE_CXX_FLAGS="$cxx_flags" -DCMAKE_C_FLAGS="$c_flags" \
  -DCMAKE_FIND_USE_CMAKE_SYSTEM_PATH=OFF -DCMAKE_FIND_USE_SYSTEM_ENVIRONMENT_PATH=OFF \
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF \
  "${gtest_libs[@]}" >"$build/check-model-configure.log" 2>&1 ||
  { cat "$build/check-model-configure.log" >&2; fail "configure -DVBIM_MODEL_ONLY=ON"; }

step "building"
cmake --build "$build" -j"$jobs" || fail "build -DVBIM_MODEL_ONLY=ON without third-party headers"

step "running the model's tests"
ctest --test-dir "$build" -j"$jobs" --output-on-failure --no-tests=error || fail "the model's tests"

step "checking what the programs link"
allowed='^(libc|libm|libstdc\+\+|libgcc_s|libpthread)\.so\.[0-9]+$|^ld-linux[-a-z0-9_.]*\.so\.[0-9]+$'
programs=0
bad=""
while IFS= read -r -d '' exe; do
  readelf -h "$exe" >/dev/null 2>&1 || continue  # scripts, not programs
  programs=$((programs + 1))
  while read -r lib; do
    [[ "$lib" =~ $allowed ]] || bad="$bad"$'\n'"  ${exe#"$build"/}: $lib"
  done < <(readelf -d "$exe" | sed -n 's/.*(NEEDED).*Shared library: \[\(.*\)\]/\1/p')
done < <(find "$build" -path "$build/CMakeFiles" -prune -o -type f -perm -u+x -print0)
[ -z "$bad" ] || fail "programs of the model link libraries beyond the C and C++ runtime:$bad"
[ -x "$build/tests/model_only/model_only_play_sample" ] || fail "tests/model_only/model_only_play_sample was not built"
[ "$programs" -ge 5 ] || fail "found only $programs programs to check in $build"
step "$programs programs link only libc, libm, libstdc++, libgcc_s, libpthread and the loader"

step "compiling every installed model header without third-party headers"
prefix=$build/check-model-install
rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null || fail "cmake --install of the model"
[ ! -e "$prefix/include/vbim/config" ] || fail "a model-only install holds config/"
all=$build/check-model-headers.cpp
(cd "$prefix/include/vbim" && find . -name '*.hpp' | sort | sed -E 's|^\./(.*)$|#include "\1"|') >"$all"
# shellcheck disable=SC2086 # the flags are words
g++ -std=c++20 $cxx_flags -I"$prefix/include/vbim" -fsyntax-only "$all" || fail "installed model headers"
step "$(wc -l <"$all") installed headers compile with the C and C++ runtime headers alone"
step "passed"
