#!/bin/sh
# The share of a play's CPU that goes to its pictures (issue #31: at most 10 % at the default
# settings). The 256x256 + 128x64 sample (streams/samples/day_clear.vbim, the demo's stream), 60 s
# simulated, the demo's pictures (--every 240 --at 6s,7s,8s: 17 lightmap + sky pairs), with and
# without the demo's fault plan (a 6 s stall at 0.2 s, a read error at LBA 2090). Per batch, the
# medians over RUNS plays of:
#   - the play's CPU time (std::clock: every thread) and its x-real-time;
#   - the CPU time of the picture thread ("pictures: ... ms of CPU time on their own thread"), as a
#     share of the play's;
#   - the same play without pictures, and the share of the difference (which also counts the copy
#     each picture costs the simulation's thread).
# Then, for each PNG level, the bytes of the 34 files and the picture thread's CPU per pair.
#   image_share.sh VBIM [BATCHES] [RUNS] [WORKDIR]
# WORKDIR (default: a temporary directory under TMPDIR) is where the plays write: the file system
# counts (creating and filling 34 files is most of the pictures' cost at level 0), so the script
# prints which one it is. Each play writes a directory of its own (play.PID.N), none replacing
# another (--force) and none removed while plays run: ext4 without a journal (this machine's root)
# skips, at every file it creates, each free inode of the directory's block group deleted in the
# last 60 s, or 360 s while that inode's table block is not yet written back (fs/ext4/ialloc.c,
# recently_deleted(), RECENTCY_MIN and RECENTCY_DIRTY). After a few thousand deletions there, a
# play's pictures took 3-10x the CPU (perf: 25-40 % of the picture thread in that search,
# 2026-12-05), so plays that replaced each other measured their own deletions. With a WORKDIR
# given the plays' directories stay (remove WORKDIR after the last run of a comparison: deleting
# them is what would cost the next runs); without one they go with the temporary directory at the
# end. Other programs deleting files in the same group (tests under /tmp) still count: a new
# directory at the file system's top level gets a group of its own (ext4's Orlov allocator).
set -eu
vbim=${1:?usage: image_share.sh VBIM [BATCHES] [RUNS] [WORKDIR]}
batches=${2:-3}
runs=${3:-5}
work=${4:-}
if [ -z "$work" ]; then
  work=$(mktemp -d "${TMPDIR:-/tmp}/vbim-image-share.XXXXXX")
  trap 'rm -rf "$work"' EXIT
fi
mkdir -p "$work"
sample="$(cd "$(dirname "$0")/../.." && pwd)/streams/samples/day_clear.vbim"
shots="--every 240 --at 6s,7s,8s"
cat >"$work/faults.toml" <<'TOML'
[[fault]]
kind = "stall"
at = "200ms"
duration = "6s"

[[fault]]
kind = "read_error"
lba = 2090
attempts = 300
TOML

median() { sort -n | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# play NAME ARGS...: RUNS plays, each into a new directory ($last: the last one's); appends the CPU
# seconds to $work/NAME.cpu and the picture thread's milliseconds to $work/NAME.pic (0 without
# pictures).
n=0
play() {
  name=$1
  shift
  : >"$work/$name.cpu"
  : >"$work/$name.pic"
  i=0
  while [ "$i" -lt "$runs" ]; do
    n=$((n + 1))
    last="$work/play.$$.$n"
    out=$("$vbim" play "$sample" --duration 60s "$@" --force --out "$last")
    # "played 60.0 s of X (N vsyncs) in W s of host time (..x real time), C s of CPU time (Rx real time)":
    # the seconds from the x-real-time figure, finer than the printed time.
    echo "$out" | sed -n 's/.* of CPU time (\([0-9.]*\)x real time).*/\1/p' | awk '{ printf "%.6f\n", 60 / $1 }' >>"$work/$name.cpu"
    pic=$(echo "$out" | sed -n 's/^  pictures: \([0-9.]*\) ms of CPU time.*/\1/p')
    echo "${pic:-0}" >>"$work/$name.pic"
    i=$((i + 1))
  done
}

echo "vbim play of day_clear.vbim (256x256 + 128x64), 60 s simulated, pictures $shots; $runs runs a batch"
echo "date $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) CPUs, load average $(cut -d' ' -f1 /proc/loadavg), output on $(stat -f -c %T "$work")"
for b in $(seq "$batches"); do
  for faults in none demo; do
    f=""
    [ "$faults" = demo ] && f="--faults $work/faults.toml"
    # shellcheck disable=SC2086 # $f and $shots are lists of arguments
    play bare $f
    # shellcheck disable=SC2086
    play shots $f $shots
    bare=$(median <"$work/bare.cpu")
    cpu=$(median <"$work/shots.cpu")
    pic=$(median <"$work/shots.pic")
    awk -v b="$b" -v f="$faults" -v bare="$bare" -v cpu="$cpu" -v pic="$pic" 'BEGIN {
      printf "batch %d, faults %-4s: play %.1f ms CPU (%.0fx real time), pictures thread %.1f ms (%.1f %%); " \
             "without pictures %.1f ms (%.0fx): difference %.1f %%\n",
             b, f, cpu * 1000, 60 / cpu, pic, pic / (cpu * 10), bare * 1000, 60 / bare, 100 * (cpu - bare) / cpu }'
  done
done

echo "PNG level: bytes of the 34 files, picture thread's CPU per lightmap + sky pair (median of $runs, no faults)"
for level in 0 1 2 3 4 6 9; do
  # shellcheck disable=SC2086
  play level $shots --png-level "$level"
  bytes=$(cat "$last"/frames/*.png | wc -c)
  pic=$(median <"$work/level.pic")
  awk -v l="$level" -v b="$bytes" -v p="$pic" 'BEGIN { printf "level %2d: %8d bytes, %.2f ms a pair\n", l, b, p / 17 }'
done
