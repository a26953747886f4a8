#!/bin/sh
# Start-up of the commands (issue #31): the wall time of `vbim CMD --help` (the program and its
# shared libraries loaded, the command line built, nothing run), for profile, play and info, with the
# shared libraries each process maps (an exec of vbim-full counted with it). BATCHES (default 5)
# batches of RUNS (default 20) runs each, the commands interleaved; per command the range of the
# batches' medians in milliseconds, lowest included, with the load average.
#   startup.sh VBIM [BATCHES] [RUNS]
set -eu
vbim=${1:?usage: startup.sh VBIM [BATCHES] [RUNS]}
batches=${2:-5}
runs=${3:-20}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vbim-startup.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
commands="profile play info"

# Milliseconds of one `vbim $1 --help`.
once() {
  start=$(date +%s%N)
  "$vbim" "$1" --help >/dev/null
  echo "$((($(date +%s%N) - start) / 1000))" | awk '{ printf "%.1f\n", $1 / 1000 }'
}

median() {
  sort -g "$1" | awk '{ r[NR] = $1 } END { if (NR % 2) print r[(NR + 1) / 2]; else print (r[NR / 2] + r[NR / 2 + 1]) / 2 }'
}

b=1
while [ "$b" -le "$batches" ]; do
  load=$(cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo "?")
  for c in $commands; do : >"$tmp/$c.batch"; done
  i=0
  while [ "$i" -lt "$runs" ]; do
    for c in $commands; do once "$c" >>"$tmp/$c.batch"; done
    i=$((i + 1))
  done
  line="batch $b (load average $load):"
  for c in $commands; do
    m=$(median "$tmp/$c.batch")
    echo "$m" >>"$tmp/$c.medians"
    line="$line $c $m ms"
  done
  echo "$line"
  b=$((b + 1))
done
# The shared libraries of the process that runs the command: vbim's own, or vbim-full's when vbim
# hands the command over (then both were loaded).
libraries() {
  LD_TRACE_LOADED_OBJECTS=1 "$1" 2>/dev/null | grep -c '=>' || true
}
core=$(libraries "$vbim")
full=$(libraries "$(dirname "$vbim")/vbim-full")
for c in $commands; do
  sort -g "$tmp/$c.medians" -o "$tmp/$c.medians"
  printf 'vbim %s --help: %s-%s ms (medians of %d runs, %d batches)\n' "$c" "$(head -n 1 "$tmp/$c.medians")" \
    "$(tail -n 1 "$tmp/$c.medians")" "$runs" "$batches"
done
echo "shared libraries: vbim $core, vbim-full $full"
