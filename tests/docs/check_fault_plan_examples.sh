#!/bin/sh
# Every fault plan shown in docs/fault-plans.md plays as written: each ```toml block is played by
# `vbim play` on an ISO 9660 image (made with xorriso) that holds the files the examples name
# (\DATA\LEVEL2.BIN;1, \AUDIO\MUSIC.PSS;1) beside the sample stream, and the blocks that name no
# file also on the bare sample stream. A plan the disc cannot take (a file it lacks, an LBA past its
# end) fails the play, and so this test.
# Usage: check_fault_plan_examples.sh VBIM SOURCE_DIR
set -eu
vbim=${1:?usage: check_fault_plan_examples.sh VBIM SOURCE_DIR}
root=${2:?usage: check_fault_plan_examples.sh VBIM SOURCE_DIR}
doc=$root/docs/fault-plans.md
sample=$root/streams/samples/day_clear.vbim
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vbim-fault-plans.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

awk -v dir="$tmp" '
  /^```toml/ { inside = 1; n++; printf "" > (dir "/plan" n ".toml"); next }
  inside && /^```/ { inside = 0; close(dir "/plan" n ".toml"); next }
  inside { print > (dir "/plan" n ".toml") }
' "$doc"
plans=$(ls "$tmp"/plan*.toml 2>/dev/null | wc -l)
[ "$plans" -ge 4 ] || { echo "$doc: only $plans toml blocks found"; exit 1; }

mkdir -p "$tmp/disc/DATA" "$tmp/disc/AUDIO"
cp "$sample" "$tmp/disc/DATA/DAY.VBI"
head -c 4194304 /dev/zero >"$tmp/disc/DATA/LEVEL2.BIN"
head -c 1048576 /dev/zero >"$tmp/disc/AUDIO/MUSIC.PSS"
xorriso -as mkisofs -quiet -o "$tmp/disc.iso" "$tmp/disc" >"$tmp/xorriso.log" 2>&1 ||
  { cat "$tmp/xorriso.log"; exit 1; }

status=0
named=0
for plan in "$tmp"/plan*.toml; do
  n=$(basename "$plan" .toml)
  if ! "$vbim" play "$tmp/disc.iso" --file '\DATA\DAY.VBI;1' --faults "$plan" --duration 40s --no-trace \
    --out "$tmp/run-iso-$n" >"$tmp/$n.log" 2>&1; then
    echo "$doc: toml block ${n#plan} does not play on a disc image:"; sed 's/^/  /' "$plan" "$tmp/$n.log"
    status=1
  fi
  if grep -q '^file *=' "$plan"; then
    named=$((named + 1))
  elif ! "$vbim" play "$sample" --faults "$plan" --duration 40s --no-trace --out "$tmp/run-bare-$n" \
    >"$tmp/$n-bare.log" 2>&1; then
    echo "$doc: toml block ${n#plan} does not play on $sample:"; sed 's/^/  /' "$plan" "$tmp/$n-bare.log"
    status=1
  fi
done
[ "$named" -ge 1 ] || { echo "$doc: no example names a file on the disc"; exit 1; }
[ "$status" -eq 0 ] && echo "$doc: $plans fault plans play as written ($named naming files on a disc image)"
exit "$status"
