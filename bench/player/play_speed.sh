#!/bin/sh
# x-real-time of `vbim play` on Technique A streams (issue #17): a 512x512 lightmap + 256x128 sky and
# a 256x256 + 128x64 one (the demo's size), one lightmap frame per simulated second, 600 s
# simulated, default options (tracing included). Reports the medians over RUNS (default 5) of the
# x-real-time figures in CPU time and in wall time that the play summary gives (the simulation
# loop, every thread), and the times they stand for.
#   play_speed.sh VBIM [RUNS] [WORKDIR] [THREADS]
# THREADS (default 1) is passed as `vbim play --threads`: the IPU's picture decode split by slice
# rows over that many host threads (same bytes; less wall time, a little more CPU time).
# WORKDIR keeps the authored streams between invocations (authoring the 512x512 one takes ~30 s of
# CPU); a temporary directory otherwise.
# PLAY_SPEED_SECONDS (default 600) shortens the streams and the plays: the test suite runs the script
# with 5 (Docs.PlaySpeedScriptRunsShortened). A WORKDIR holds streams of one length only.
# A third line plays the 512x512 stream authored with GOPs of 12 and two B pictures (issue #29: P and
# B pictures through the BDEC flow; the goal is 500x real time in CPU time).
# PLAY_SPEED_STREAMS (default "512 256 512gop") picks the lines, e.g. "512" for the first alone
# (play_speed_ab.sh alternates two builds on it).
# PLAY_SPEED_FAULTS, a fault plan file (e.g. bench/player/fault-plan.toml), is given to every play as
# --faults: the fault plays, with their fault-free reference run beside the run (issue #31).
set -eu
vbim=${1:?usage: play_speed.sh VBIM [RUNS] [WORKDIR] [THREADS]}
runs=${2:-5}
work=${3:-}
threads=${4:-1}
if [ -z "$work" ]; then
  work=$(mktemp -d "${TMPDIR:-/tmp}/vbim-play-speed.XXXXXX")
  trap 'rm -rf "$work"' EXIT
fi
mkdir -p "$work"
seconds=${PLAY_SPEED_SECONDS:-600}
faults=${PLAY_SPEED_FAULTS:-}
if [ -n "$faults" ] && [ ! -f "$faults" ]; then
  echo "play_speed.sh: PLAY_SPEED_FAULTS: no fault plan file at '$faults'" >&2
  exit 2
fi

# A 512x512 lightmap next to two 640x448 frame buffers fits VRAM only with strip uploads and a
# 256x128 sky texture (docs/player.md, "Speed and memory").
printf '[gs]\nupload_mode = "strips"\nsky_height = 128\n' >"$work/512.toml"
: >"$work/256.toml"

author() {  # NAME SIZE SKY_WIDTH [AUTHOR OPTIONS]
  out="$work/ta$1.vbim"
  size=$2
  sky=$3
  shift 3
  [ -f "$out" ] || "$vbim" author --procedural --size "$size" --sky-width "$sky" --frame-count "$seconds" --fps 1 \
    "$@" --out "$out" >/dev/null
}

median() { sort -n | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

load=$(cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo "?")
faultNote=""
[ -n "$faults" ] && faultNote=", --faults $faults"
echo "vbim play, ${seconds} s simulated, default options, --threads $threads$faultNote, $runs runs each; load average $load before"
cp "$work/512.toml" "$work/512gop.toml"
for name in ${PLAY_SPEED_STREAMS:-512 256 512gop}; do
  size=${name%gop}
  if [ "$name" = 512gop ]; then
    author "$name" "$size" $((size / 2)) --gop 12 --b-frames 2
  else
    author "$name" "$size" $((size / 2))
  fi
  : >"$work/cpu$name"
  : >"$work/wall$name"
  i=0
  while [ "$i" -lt "$runs" ]; do
    # ${faults:+...} unquoted: two words (--faults and the path, kept whole by its quotes) or none
    line=$("$vbim" play "$work/ta$name.vbim" --config "$work/$name.toml" --duration "${seconds}s" --force \
      --threads "$threads" ${faults:+--faults "$faults"} --out "$work/run$name" | head -n 1)
    # "played 600.0 s of X (N vsyncs) in W s of host time (..x real time), C s of CPU time (..x real time)"
    # The x-real-time figures, not the times: those are printed to 10 ms, too coarse for short plays.
    echo "$line" | sed -n 's/.* of host time (\([0-9.]*\)x real time).*/\1/p' >>"$work/wall$name"
    echo "$line" | sed -n 's/.* of CPU time (\([0-9.]*\)x real time).*/\1/p' >>"$work/cpu$name"
    i=$((i + 1))
  done
  cpu=$(median <"$work/cpu$name")
  wall=$(median <"$work/wall$name")
  gop=""
  [ "$name" = 512gop ] && gop=", GOP 12 with 2 B pictures"
  [ -n "$faults" ] && gop="$gop, with the fault plan"
  awk -v s="$size" -v g="$gop" -v t="$seconds" -v c="$cpu" -v w="$wall" 'BEGIN {
    printf "%dx%d + %dx%d%s: CPU %.3f s (%.0fx real time), wall %.3f s (%.0fx real time)\n", s, s, s / 2, s / 4, g, t / c, c, t / w, w }'
done
