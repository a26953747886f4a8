#!/bin/sh
# Two builds of vbim alternated batch by batch through play_speed.sh, so both see the same machine
# in the same minutes (on a shared machine the load moves the figures by tens of percent): for each
# of BATCHES (default 4), the time and load average, then BEFORE's and AFTER's medians of RUNS
# (default 5) plays (issue #31: the 512x512 + 256x128 play's goal is 1,000x real time in CPU time).
#   play_speed_ab.sh BEFORE_VBIM AFTER_VBIM [BATCHES] [RUNS] [WORKDIR]
# PLAY_SPEED_STREAMS (default "512") picks the streams, as in play_speed.sh; WORKDIR keeps the
# authored streams (a temporary directory otherwise). Both builds must author the same streams.
set -eu
before=${1:?usage: play_speed_ab.sh BEFORE_VBIM AFTER_VBIM [BATCHES] [RUNS] [WORKDIR]}
after=${2:?usage: play_speed_ab.sh BEFORE_VBIM AFTER_VBIM [BATCHES] [RUNS] [WORKDIR]}
batches=${3:-4}
runs=${4:-5}
work=${5:-}
if [ -z "$work" ]; then
  work=$(mktemp -d "${TMPDIR:-/tmp}/vbim-play-ab.XXXXXX")
  trap 'rm -rf "$work"' EXIT
fi
here=$(cd "$(dirname "$0")" && pwd)
PLAY_SPEED_STREAMS=${PLAY_SPEED_STREAMS:-512}
export PLAY_SPEED_STREAMS
b=1
while [ "$b" -le "$batches" ]; do
  for name in before after; do
    if [ "$name" = before ]; then vbim=$before; else vbim=$after; fi
    echo "== batch $b, $name ($vbim), $(date -u +%H:%M:%S) UTC"
    sh "$here/play_speed.sh" "$vbim" "$runs" "$work" | sed 's/^/  /'
  done
  b=$((b + 1))
done
