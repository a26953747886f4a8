#!/bin/sh
# Wall time of one sweep plan with --jobs 1 and --jobs 2, in BATCHES (default 5) batches: each batch
# times RUNS (default 1) runs of each, alternating which goes first, and gives the ratio of the best
# --jobs 1 to the best --jobs 2; the last line is the range of the ratios over the batches (lowest
# included) and their median. The machine's load average is printed with every batch: on a shared
# machine the ratio says little without it. The tables must be the same bytes (checked).
#   speedup.sh VBIM PLAN [BATCHES] [RUNS]
set -eu
vbim=${1:?usage: speedup.sh VBIM PLAN [BATCHES] [RUNS]}
plan=${2:?usage: speedup.sh VBIM PLAN [BATCHES] [RUNS]}
batches=${3:-5}
runs=${4:-1}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vbim-sweep-bench.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

# Wall time in seconds of `vbim profile --plan PLAN --jobs $1`.
once() {
  start=$(date +%s.%N)
  "$vbim" profile --plan "$plan" --jobs "$1" --force --out "$tmp/jobs$1" >/dev/null
  echo "$(date +%s.%N) - $start" | bc
}

# The smaller of $1 and $2 (either may be empty).
least() {
  if [ -z "$1" ] || [ "$(echo "$2 < $1" | bc)" -eq 1 ]; then echo "$2"; else echo "$1"; fi
}

b=1
: >"$tmp/ratios"
while [ "$b" -le "$batches" ]; do
  load=$(cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo "?")
  one=""
  two=""
  i=0
  while [ "$i" -lt "$runs" ]; do
    if [ $(((b + i) % 2)) -eq 1 ]; then
      one=$(least "$one" "$(once 1)")
      two=$(least "$two" "$(once 2)")
    else
      two=$(least "$two" "$(once 2)")
      one=$(least "$one" "$(once 1)")
    fi
    i=$((i + 1))
  done
  cmp -s "$tmp/jobs1/cases.csv" "$tmp/jobs2/cases.csv" || { echo "speedup: the tables differ" >&2; exit 1; }
  ratio=$(echo "$one / $two" | bc -l)
  echo "$ratio" >>"$tmp/ratios"
  printf 'batch %d (load average %s at its start): --jobs 1 %.2f s, --jobs 2 %.2f s, speed-up %.2fx\n' \
    "$b" "$load" "$one" "$two" "$ratio"
  b=$((b + 1))
done
cases=$(($(wc -l <"$tmp/jobs1/cases.csv") - 1))
sort -g "$tmp/ratios" -o "$tmp/ratios"
lo=$(head -n 1 "$tmp/ratios")
hi=$(tail -n 1 "$tmp/ratios")
median=$(awk '{ r[NR] = $1 } END { if (NR % 2) print r[(NR + 1) / 2]; else print (r[NR / 2] + r[NR / 2 + 1]) / 2 }' \
  "$tmp/ratios")
printf 'sweep of %d cases on %s cores, %s: speed-up of --jobs 2 over --jobs 1 %.2fx-%.2fx over %d batches (best of %d each), median %.2fx\n' \
  "$cases" "$(nproc)" "$vbim" "$lo" "$hi" "$batches" "$runs" "$median"
