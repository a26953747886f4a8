#!/bin/sh
# Wall time of one sweep plan with --jobs 1 and --jobs 2, best of RUNS (default 3) each, and the
# ratio. The tables must be the same bytes (checked). Usage: speedup.sh VBIM PLAN [RUNS]
set -eu
vbim=${1:?usage: speedup.sh VBIM PLAN [RUNS]}
plan=${2:?usage: speedup.sh VBIM PLAN [RUNS]}
runs=${3:-3}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vbim-sweep-bench.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

# Best wall time in seconds of `vbim profile --plan PLAN --jobs $1`.
best() {
  b=""
  i=0
  while [ "$i" -lt "$runs" ]; do
    start=$(date +%s.%N)
    "$vbim" profile --plan "$plan" --jobs "$1" --force --out "$tmp/jobs$1" >/dev/null
    t=$(echo "$(date +%s.%N) - $start" | bc)
    if [ -z "$b" ] || [ "$(echo "$t < $b" | bc)" -eq 1 ]; then b=$t; fi
    i=$((i + 1))
  done
  echo "$b"
}

# On a machine shared with other work the ratio says little: the load is printed with it.
load=$(cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo "?")
one=$(best 1)
two=$(best 2)
cmp -s "$tmp/jobs1/cases.csv" "$tmp/jobs2/cases.csv" || { echo "speedup: the tables differ" >&2; exit 1; }
cases=$(($(wc -l <"$tmp/jobs1/cases.csv") - 1))
printf 'sweep of %d cases on %s cores (load average %s at the start): --jobs 1 %.2f s, --jobs 2 %.2f s, speed-up %.2fx\n' \
  "$cases" "$(nproc)" "$load" "$one" "$two" "$(echo "$one / $two" | bc -l)"
