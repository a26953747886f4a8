#!/bin/sh
# Two builds of vbim alternated batch by batch through fault_play_speed.sh, so both see the same
# machine in the same minutes (a shared machine's load moves the figures by tens of percent): for
# each of BATCHES (default 4), the time and load average, then BEFORE's and AFTER's medians of RUNS
# (default 5) plays of SECONDS (default 600) each, with and without the bench fault plan (issue #31).
#   fault_play_ab.sh BEFORE_VBIM AFTER_VBIM [BATCHES] [RUNS] [SECONDS]
set -eu
before=${1:?usage: fault_play_ab.sh BEFORE_VBIM AFTER_VBIM [BATCHES] [RUNS] [SECONDS]}
after=${2:?usage: fault_play_ab.sh BEFORE_VBIM AFTER_VBIM [BATCHES] [RUNS] [SECONDS]}
batches=${3:-4}
runs=${4:-5}
seconds=${5:-600}
here=$(cd "$(dirname "$0")" && pwd)
b=1
while [ "$b" -le "$batches" ]; do
  for name in before after; do
    if [ "$name" = before ]; then vbim=$before; else vbim=$after; fi
    echo "== batch $b, $name ($vbim), $(date -u +%H:%M:%S) UTC"
    sh "$here/fault_play_speed.sh" "$vbim" "$runs" "$seconds"
  done
  b=$((b + 1))
done
