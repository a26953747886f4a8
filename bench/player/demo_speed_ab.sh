#!/bin/sh
# The x-real-time figures `vbim demo` prints for its play (60 s of its 256x256 + 128x64 stream with
# its fault plan and 17 lightmap + sky pictures: issue #31 asks 1,000x in CPU time), for two builds
# alternated run by run so both see the same machine: per batch, the time, the load average, and each
# build's medians over RUNS demos of the CPU and wall figures. Each demo also authors its stream
# (not counted in the play's figures).
#   demo_speed_ab.sh BEFORE_VBIM AFTER_VBIM [BATCHES] [RUNS]
# Each demo writes a directory of its own under the temporary directory (TMPDIR), none replacing
# another and none removed while demos run: on ext4 without a journal, every file created skips the
# inodes of its block group freed in the last minutes (image_share.sh says more), so demos that
# replaced the last one's 34 pictures with --force measured their own deletions.
set -eu
before=${1:?usage: demo_speed_ab.sh BEFORE_VBIM AFTER_VBIM [BATCHES] [RUNS]}
after=${2:?usage: demo_speed_ab.sh BEFORE_VBIM AFTER_VBIM [BATCHES] [RUNS]}
batches=${3:-3}
runs=${4:-5}
work=$(mktemp -d "${TMPDIR:-/tmp}/vbim-demo-speed.XXXXXX")
trap 'rm -rf "$work"' EXIT

median() { sort -n | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

demo() {  # NAME VBIM
  # "played 60.0 s of day.vbim (N vsyncs) in W s of host time (..x real time), C s of CPU time (..x real time)"
  n=$((n + 1))
  line=$("$2" demo --out "$work/demo.$n" | grep '^played ' | head -n 1)
  echo "$line" | sed -n 's/.* of host time (\([0-9.]*\)x real time).*/\1/p' >>"$work/wall-$1"
  echo "$line" | sed -n 's/.* of CPU time (\([0-9.]*\)x real time).*/\1/p' >>"$work/cpu-$1"
}

n=0
b=1
while [ "$b" -le "$batches" ]; do
  rm -f "$work"/wall-* "$work"/cpu-*
  echo "== batch $b, $(date -u +%H:%M:%S) UTC, load average $(cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo '?')"
  i=0
  while [ "$i" -lt "$runs" ]; do
    demo before "$before"
    demo after "$after"
    i=$((i + 1))
  done
  for name in before after; do
    printf '%-7s CPU %.0fx real time, wall %.0fx real time (medians of %s demo plays)\n' "$name:" \
      "$(median <"$work/cpu-$name")" "$(median <"$work/wall-$name")" "$runs"
  done
  b=$((b + 1))
done
