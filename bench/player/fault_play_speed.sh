#!/bin/sh
# x-real-time of `vbim play` of the 256x256 sample (streams/samples/day_clear.vbim: 256x256 + 128x64,
# the demo's size) with the committed fault plan bench/player/fault-plan.toml (a stall, a read
# error, random stalls: issue #31), and the same play without faults, default options (tracing
# included). The fault play runs a fault-free reference pipeline beside the run for the lag. Runs
# alternate (fault-free, fault, ...) so both see the same machine; prints the medians over RUNS
# (default 9) of the CPU-time and wall-time figures of the play summary (the simulation loop).
#   fault_play_speed.sh VBIM [RUNS] [SECONDS]
# SECONDS (default 600) of simulated time per play; the sample loops every 24 s.
set -eu
vbim=${1:?usage: fault_play_speed.sh VBIM [RUNS] [SECONDS]}
runs=${2:-9}
seconds=${3:-600}
here=$(cd "$(dirname "$0")" && pwd)
sample="$here/../../streams/samples/day_clear.vbim"
work=$(mktemp -d "${TMPDIR:-/tmp}/vbim-fault-speed.XXXXXX")
trap 'rm -rf "$work"' EXIT

median() { sort -n | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

play() {  # NAME ARGS...
  name=$1
  shift
  line=$("$vbim" play "$sample" --duration "${seconds}s" --force --out "$work/run" "$@" | head -n 1)
  # "played ... in W s of host time (..x real time), C s of CPU time (..x real time)"
  echo "$line" | sed -n 's/.* of host time (\([0-9.]*\)x real time).*/\1/p' >>"$work/wall-$name"
  echo "$line" | sed -n 's/.* of CPU time (\([0-9.]*\)x real time).*/\1/p' >>"$work/cpu-$name"
}

load=$(cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo "?")
echo "vbim play of day_clear.vbim, ${seconds} s simulated, default options, $runs runs each; load average $load before"
i=0
while [ "$i" -lt "$runs" ]; do
  play none
  play faults --faults "$here/fault-plan.toml"
  i=$((i + 1))
done
for name in none faults; do
  cpu=$(median <"$work/cpu-$name")
  wall=$(median <"$work/wall-$name")
  awk -v n="$name" -v t="$seconds" -v c="$cpu" -v w="$wall" 'BEGIN {
    printf "%-7s CPU %.3f s (%.0fx real time), wall %.3f s (%.0fx real time)\n", n == "none" ? "none:" : "faults:", t / c, c, t / w, w }'
done
