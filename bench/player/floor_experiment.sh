#!/bin/sh
# How fast the 512x512 + 256x128 Technique A play (play_speed.sh's first line, issue #31's 1,000x)
# could be if the GS blend and the frame hash cost nothing: an upper bound for any work on them.
# Builds `vbim` from this checkout's HEAD with floor_experiment.patch applied, in a temporary git
# worktree (through ccache when there is one: mostly cache hits after a build of this checkout). The
# patch adds three switches read from the environment, in that build only (never in the product):
#   VBIM_FLOOR_NO_HASH    the player takes no frame hash (hashes.txt holds zeros);
#   VBIM_FLOOR_NO_BLEND   every lightmap and sky blend returns at once, having moved nothing (so no
#                         vsync has a changed frame to hash either);
#   VBIM_FLOOR_TILE_HASH  the cost of a frame hash kept per tile (a definition the planners could
#                         choose; hashes.txt is then wrong): a changed vsync folds only the tiles it
#                         blended, and the sky only when it moved.
# Then plays the stream with the patched build as it is, with the per-tile hash's cost, without the
# hash, and without both, run by run in turn so all four see the same machine; per batch, the
# medians over RUNS of the CPU-time x-real-time figure of the play summary.
#   floor_experiment.sh VBIM [BATCHES] [RUNS] [WORKDIR]
# VBIM authors the stream (`vbim author` runs in vbim-full beside it); WORKDIR keeps it between
# invocations (play_speed.sh's layout: the same WORKDIR serves both). PLAY_SPEED_SECONDS as there.
set -eu
vbim=${1:?usage: floor_experiment.sh VBIM [BATCHES] [RUNS] [WORKDIR]}
batches=${2:-3}
runs=${3:-5}
work=${4:-}
if [ ! -f "$vbim" ] || [ ! -x "$vbim" ]; then
  echo "floor_experiment: $vbim is not an executable file (expected a built vbim, e.g. build/cli/vbim)" >&2
  exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
seconds=${PLAY_SPEED_SECONDS:-600}
scratch=$(mktemp -d "${TMPDIR:-/tmp}/vbim-floor.XXXXXX")
cleanup() {
  git -C "$repo" worktree remove --force "$scratch/src" 2>/dev/null || true
  rm -rf "$scratch"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM  # the EXIT trap removes the worktree on Ctrl-C too
[ -n "$work" ] || work="$scratch/streams"
mkdir -p "$work"

git -C "$repo" worktree add --quiet --detach "$scratch/src" HEAD
if ! git -C "$scratch/src" apply "$here/floor_experiment.patch"; then
  echo "floor_experiment: $here/floor_experiment.patch no longer applies to HEAD (player/player.cpp or" >&2
  echo "gs/tiled_blender.cpp changed): make the same two switches there again and refresh the patch" >&2
  exit 1
fi
launcher=""
command -v ccache >/dev/null 2>&1 && launcher="-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache"
echo "building the patched vbim from $(git -C "$repo" rev-parse --short HEAD) in $scratch/src/build"
# shellcheck disable=SC2086
(cd "$scratch/src" && CCACHE_BASEDIR="$scratch/src" cmake -S . -B build -DCMAKE_BUILD_TYPE=Release $launcher >/dev/null &&
  CCACHE_BASEDIR="$scratch/src" cmake --build build -j"$(nproc)" --target vbim >/dev/null)
patched="$scratch/src/build/cli/vbim"

# The stream and its platform config, as play_speed.sh makes them.
printf '[gs]\nupload_mode = "strips"\nsky_height = 128\n' >"$work/512.toml"
[ -f "$work/ta512.vbim" ] || "$vbim" author --procedural --size 512 --sky-width 256 --frame-count "$seconds" --fps 1 \
  --out "$work/ta512.vbim" >/dev/null

median() { sort -n | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

play() {  # NAME ENV...
  name=$1
  shift
  line=$(env "$@" "$patched" play "$work/ta512.vbim" --config "$work/512.toml" --duration "${seconds}s" --force \
    --out "$scratch/run" | head -n 1)
  echo "$line" | sed -n 's/.* of CPU time (\([0-9.]*\)x real time).*/\1/p' >>"$scratch/cpu-$name"
}

echo "vbim play of a 512x512 + 256x128 Technique A stream, ${seconds} s simulated, default options; $runs runs a batch"
echo "date $(date -u '+%Y-%m-%d %H:%M') UTC, $(nproc) CPUs, $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')"
b=1
while [ "$b" -le "$batches" ]; do
  rm -f "$scratch"/cpu-*
  load=$(cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo "?")
  i=0
  while [ "$i" -lt "$runs" ]; do
    play built VBIM_FLOOR_NONE=1
    play tilehash VBIM_FLOOR_TILE_HASH=1
    play nohash VBIM_FLOOR_NO_HASH=1
    play neither VBIM_FLOOR_NO_HASH=1 VBIM_FLOOR_NO_BLEND=1
    i=$((i + 1))
  done
  printf 'batch %d (load average %s): as built %.0fx, hashing per tile %.0fx, without the frame hash %.0fx, without the hash and the blend %.0fx (CPU time)\n' \
    "$b" "$load" "$(median <"$scratch/cpu-built")" "$(median <"$scratch/cpu-tilehash")" "$(median <"$scratch/cpu-nohash")" \
    "$(median <"$scratch/cpu-neither")"
  b=$((b + 1))
done
