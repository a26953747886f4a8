#!/usr/bin/env bash
# vbim as a library, tried the way a user tries it (issue #14, "Consumable as a library"):
#   1. builds vbim in BUILD_DIR (default build/; configured first if it is not) and installs it
#      into a temporary prefix with `cmake --install`;
#   2. checks the installed tree: the package files, the samples, no path back into this source
#      tree, every `#include "..."` of an installed header found under include/vbim, and the man
#      page (man -l), the bash and zsh completions and the docs;
#   3. configures examples/stall-test against the installed vbim (find_package), builds it and runs
#      its tests with ctest;
#   4. configures the same example with -DVBIM_EXAMPLE_FROM_SOURCE=ON (add_subdirectory of this
#      tree, the model only) with pkg-config and every tool library's CMake package disabled, so
#      that configuring must not look for a media library; builds and runs its test.
# Stops with "check-install: FAILED: ..." at the first step that fails.
#   scripts/check-install.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
build=${1:-build}
jobs=$(nproc)
work=$(mktemp -d "${TMPDIR:-/tmp}/vbim-check-install.XXXXXX")
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix

step() { echo "check-install: $*"; }
# has_test BUILD NAME: ctest in BUILD lists the test NAME.
has_test() {
  local list
  list=$(ctest --test-dir "$1" -N)  # whole, not piped into grep -q (pipefail would see SIGPIPE)
  grep -q -F "$2" <<<"$list"
}
fail() {
  echo "check-install: FAILED: $*" >&2
  exit 1
}

step "building $build"
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DVBIM_BUILD_BENCH=OFF >/dev/null || fail "configure $build"
fi
cmake --build "$build" -j"$jobs" >"$work/build.log" 2>&1 || { tail -50 "$work/build.log" >&2; fail "build $build"; }
step "installing into $prefix"
cmake --install "$build" --prefix "$prefix" >"$work/install.log" || fail "cmake --install $build"

step "checking the installed tree"
for f in lib/cmake/vbim/vbimConfig.cmake lib/cmake/vbim/vbimConfigVersion.cmake \
  lib/cmake/vbim/vbimModelTargets.cmake lib/cmake/vbim/vbimConfigTargets.cmake \
  lib/libvbim_kernel.a lib/libvbim_player.a lib/libvbim_config.a \
  include/vbim/player/scenario.hpp include/vbim/config/fault_plan_toml.hpp \
  share/vbim/samples/day_clear.vbim share/vbim/samples/day_weather.vbim bin/vbim bin/vbim-full; do
  [ -e "$prefix/$f" ] || fail "$f was not installed (a full build, not VBIM_MODEL_ONLY, is expected)"
done
if grep -rl -F "$root" "$prefix/lib/cmake/vbim"; then
  fail "the package files above point into the source tree $root"
fi
missing=$(cd "$prefix/include/vbim" && grep -rhoE '^#include "[^"]+"' . | sed -E 's/^#include "(.*)"$/\1/' | sort -u |
  while IFS= read -r h; do [ -f "$h" ] || echo "$h"; done)
[ -z "$missing" ] || fail "installed headers include headers that were not installed: $missing"

# The installed vbim finds the installed samples (its vectors default), run from elsewhere.
(cd "$work" && "$prefix/bin/vbim" vectors --check "$root/tests/vectors" >/dev/null) ||
  fail "the installed vbim's vectors (from share/vbim/samples) differ from tests/vectors"

# The man page, the completions and the docs (generated from --help's definitions: cli/generate_docs.hpp).
for f in share/man/man1/vbim.1 share/bash-completion/completions/vbim share/zsh/site-functions/_vbim \
  share/doc/vbim/cli.md share/doc/vbim/README.md; do
  [ -s "$prefix/$f" ] || fail "$f was not installed"
done
man_warnings=$(MANWIDTH=80 man -l "$prefix/share/man/man1/vbim.1" 2>&1 >/dev/null) || fail "man -l vbim.1"
[ -z "$man_warnings" ] || fail "man -l vbim.1 warns: $man_warnings"
bash -c "source '$prefix/share/bash-completion/completions/vbim' && complete -p vbim" >/dev/null ||
  fail "the bash completion does not register for vbim"
grep -q '^#compdef vbim' "$prefix/share/zsh/site-functions/_vbim" || fail "_vbim is not a zsh completion for vbim"

step "examples/stall-test against the installed vbim"
example=$work/example
cmake -S examples/stall-test -B "$example" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
  >"$work/example-configure.log" 2>&1 || { cat "$work/example-configure.log" >&2; fail "configure the example"; }
found=$(sed -n 's/^vbim_DIR:PATH=//p' "$example/CMakeCache.txt")
[ "$found" = "$prefix/lib/cmake/vbim" ] || fail "the example found vbim in '$found', not in $prefix"
cmake --build "$example" -j"$jobs" || fail "build the example against the installed vbim"
ctest --test-dir "$example" --output-on-failure --no-tests=error || fail "the example's tests"
for t in StallTest.FallsBehindDuringADriveStallThenCatchesUp FaultPlanTest.ReadErrorAndSeekAwayAreAbsorbedByTheRing; do
  has_test "$example" "$t" || fail "the example did not run $t"
done

step "examples/stall-test with add_subdirectory of the model only"
from_source=$work/from-source
# Disabled, each of these fails the configure if the model-only tree asks for it.
no_media=(-DCMAKE_DISABLE_FIND_PACKAGE_PkgConfig=ON -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON
  -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON -DCMAKE_DISABLE_FIND_PACKAGE_glm=ON
  -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON -DCMAKE_DISABLE_FIND_PACKAGE_OpenImageIO=ON)
cmake -S examples/stall-test -B "$from_source" -DCMAKE_BUILD_TYPE=Release -DVBIM_EXAMPLE_FROM_SOURCE=ON \
  -DVBIM_SOURCE_DIR="$root" "${no_media[@]}" >"$work/from-source-configure.log" 2>&1 ||
  { cat "$work/from-source-configure.log" >&2; fail "configure the example with add_subdirectory"; }
if grep -E '^(TOMLPP|LIBAV|LIBMPEG2|OSMESA|HWY|PNG|OPENEXR|OIIO)_' "$from_source/CMakeCache.txt"; then
  fail "the model-only configure looked up the libraries above"
fi
cmake --build "$from_source" -j"$jobs" || fail "build the example with add_subdirectory"
ctest --test-dir "$from_source" --output-on-failure --no-tests=error || fail "the example's test (add_subdirectory)"
has_test "$from_source" StallTest.FallsBehindDuringADriveStallThenCatchesUp ||
  fail "the add_subdirectory example did not run its stall test"

step "passed"
