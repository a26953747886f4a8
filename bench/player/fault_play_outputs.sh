#!/bin/sh
# The SHA-256 of every file of several fault plays' run directories (hashes.txt, timeline.csv,
# stats.json, arrivals.csv, trace.json, signals.vcd, pictures), one line per file: run it with two
# builds and diff the listings to show that a speed change moved no output byte (issue #31).
# The plays: the samples with the committed fault plan of fault_play_speed.sh, the example plans,
# several seeds, a branch, --threads 2, each catch-up policy, the blender without its
# convergence shortcut, a catch-up FIX, a 512x512 stream in strip mode, and streams of GOPs of 12
# with 2 B pictures (whose decodes the run's and the reference's IPUs share): 256x256, 512x512 in
# strip mode (the run's strips come after the reference's: the mirror's queue), two variants with a
# branch, and the IPU command log (its IPU leaves the sharing).
#   fault_play_outputs.sh VBIM [WORKDIR]  > listing.txt
# WORKDIR keeps the authored streams between invocations; a temporary directory otherwise.
set -eu
vbim=${1:?usage: fault_play_outputs.sh VBIM [WORKDIR]}
work=${2:-}
if [ -z "$work" ]; then
  work=$(mktemp -d "${TMPDIR:-/tmp}/vbim-fault-outputs.XXXXXX")
  trap 'rm -rf "$work"' EXIT
fi
mkdir -p "$work"
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
clear="$top/streams/samples/day_clear.vbim"
weather="$top/streams/samples/day_weather.vbim"
plan="$here/fault-plan.toml"
printf '[gs]\nconvergence_aware = false\n' >"$work/unaware.toml"
printf '[gs]\ncatchup_fix = 96\n' >"$work/catchup.toml"
printf '[gs]\nupload_mode = "strips"\nsky_height = 128\n' >"$work/strips.toml"
[ -f "$work/ta512.vbim" ] || "$vbim" author --procedural --size 512 --sky-width 256 --frame-count 12 --fps 1 \
  --out "$work/ta512.vbim" >/dev/null
[ -f "$work/gop12.vbim" ] || "$vbim" author --procedural --size 256 --sky-width 128 --frame-count 24 --fps 1 \
  --gop 12 --b-frames 2 --out "$work/gop12.vbim" >/dev/null
[ -f "$work/gop512.vbim" ] || "$vbim" author --procedural --size 512 --sky-width 256 --frame-count 24 --fps 1 \
  --gop 12 --b-frames 2 --out "$work/gop512.vbim" >/dev/null
[ -f "$work/gop-weather.vbim" ] || "$vbim" author --procedural --size 256 --sky-width 128 --frame-count 24 --fps 1 \
  --weather clear,overcast --gop 12 --b-frames 2 --out "$work/gop-weather.vbim" >/dev/null

play() {  # NAME DISC ARGS...
  name=$1 disc=$2
  shift 2
  "$vbim" play "$disc" "$@" --force --out "$work/$name" >/dev/null
  (cd "$work/$name" && find . -type f | LC_ALL=C sort | xargs sha256sum) | sed "s|^|$name |"
}

play plan-s1 "$clear" --faults "$plan" --seed 1 --duration 600s --every 3000
play plan-s2 "$clear" --faults "$plan" --seed 2 --duration 300s
play stall-s7 "$clear" --faults "$top/examples/fault-plans/stall.toml" --seed 7 --duration 60s --at 25s,31s
play flaky-s3-t2 "$clear" --faults "$top/examples/fault-plans/flaky-drive.toml" --seed 3 --duration 150s --threads 2
play weather-branch "$weather" --faults "$plan" --seed 4 --duration 120s --branch 30s=1 --branch 70s=0
play hard-skip-unaware "$clear" --faults "$plan" --seed 5 --duration 90s --policy hard-skip --config "$work/unaware.toml"
play play-late-catchup "$clear" --faults "$plan" --seed 6 --duration 90s --policy play-late --config "$work/catchup.toml"
play strips512 "$work/ta512.vbim" --faults "$plan" --seed 8 --duration 60s --config "$work/strips.toml"
play gop12 "$work/gop12.vbim" --faults "$plan" --seed 9 --duration 90s
play gop512-strips "$work/gop512.vbim" --faults "$plan" --seed 10 --duration 90s --config "$work/strips.toml"
play gop-branch "$work/gop-weather.vbim" --faults "$plan" --seed 11 --duration 90s --branch 30s=1 --branch 60s=0
play gop12-ipu-log "$work/gop12.vbim" --faults "$plan" --seed 12 --duration 60s --trace-detail ipu
