#!/usr/bin/env bash
# CPU time of `vbim decode` writing every picture as a file, per PNG level and for raw RGBA.
# Per batch and per output (PNG at each level of LEVELS, and --format rgba: the decode and the CSC
# with a plain write), the median over RUNS decodes of the command's CPU time (user + system, bash's
# `time`) and of that time per picture. Each decode writes a directory of its own under WORKDIR,
# none removed while the batches run (on ext4 a file created just after many deletions costs more:
# bench/player/image_share.sh says why).
#   decode_files_speed.sh VBIM [BATCHES] [RUNS] [LEVELS] [STREAM] [WORKDIR]
# LEVELS (default "0 1 6"): zlib levels, or "default" for no --png-level (the command's default,
# and the only choice for a vbim from before the option, 2026-12-06). Without STREAM (or with
# "-"), a 512x512 Technique A stream of 60 pictures is authored first (`vbim author --procedural`,
# which needs vbim-full beside VBIM); its lightmap pictures are decoded. WORKDIR keeps that stream
# between invocations; a temporary directory otherwise.
set -euo pipefail
vbim=${1:?usage: decode_files_speed.sh VBIM [BATCHES] [RUNS] [LEVELS] [STREAM] [WORKDIR]}
batches=${2:-3}
runs=${3:-5}
levels=${4:-0 1 6}
stream=${5:--}
work=${6:-}
for level in $levels; do
  case $level in
    default | [0-9]) ;;
    *)
      echo "decode_files_speed.sh: LEVELS '$levels': expected 0 to 9 or 'default', separated by spaces" >&2
      exit 2
      ;;
  esac
done
if [ -z "$work" ]; then
  work=$(mktemp -d "${TMPDIR:-/tmp}/vbim-decode-files.XXXXXX")
  trap 'rm -rf "$work"' EXIT
fi
mkdir -p "$work"
if [ "$stream" = - ]; then
  stream="$work/ta512.vbim"
  [ -f "$stream" ] || "$vbim" author --procedural --size 512 --sky-width 256 --frame-count 60 --fps 1 \
    --out "$stream" >/dev/null
fi

median() { sort -n | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# cpu OUT ARGS...: one decode into OUT; prints its CPU seconds (user + system).
cpu() {
  local out=$1 times
  shift
  TIMEFORMAT='%3U %3S'
  times=$({ time "$vbim" decode "$stream" --out "$out" "$@" >/dev/null 2>"$work/stderr"; } 2>&1) || {
    echo "decode_files_speed.sh: $vbim decode $stream $* failed: $(cat "$work/stderr")" >&2
    exit 1
  }
  echo "$times" | awk '{ printf "%.3f\n", $1 + $2 }'
}

echo "vbim decode of $stream, $runs runs a batch; $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) CPUs, load average $(cut -d' ' -f1 /proc/loadavg)"
n=0
for b in $(seq "$batches"); do
  for output in $levels rgba; do
    case $output in
      default) label="png, default" args=() ;;
      rgba) label="rgba (raw)" args=(--format rgba) ;;
      *) label="png level $output" args=(--png-level "$output") ;;
    esac
    : >"$work/cpu"
    for _ in $(seq "$runs"); do
      n=$((n + 1))
      out="$work/decode.$$.$n"
      cpu "$out" "${args[@]}" >>"$work/cpu"
    done
    pictures=$(find "$out" -name 'frame_*' | wc -l)
    awk -v b="$b" -v l="$label" -v c="$(median <"$work/cpu")" -v p="$pictures" 'BEGIN {
      printf "batch %d, %-13s: %.3f s CPU for %d pictures, %.2f ms a picture\n", b, l, c, p, 1000 * c / (p > 0 ? p : 1) }'
  done
done
