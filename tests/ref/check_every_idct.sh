#!/bin/sh
# vbim_ref.h against the vectors of every IDCT vbim models (its header names the one it holds), and
# a changed answer in each stage file it computes makes the check fail.
# Usage: check_every_idct.sh VBIM VBIM_REF_CHECK
set -eu
vbim=${1:?usage: check_every_idct.sh VBIM VBIM_REF_CHECK}
check=${2:?usage: check_every_idct.sh VBIM VBIM_REF_CHECK}
work=$(mktemp -d "${TMPDIR:-/tmp}/vbim-ref.XXXXXX")
trap 'rm -rf "$work"' EXIT
for idct in pcsx2 libmpeg2 exact; do
  "$vbim" vectors --idct "$idct" --out "$work/$idct" >/dev/null
  grep -q "^# IDCT: $idct " "$work/$idct/idct.txt"
  "$check" "$work/$idct"
done
# A stream with P and B pictures: its vectors add non-intra blocks (the IDCT of their residuals).
"$vbim" author --synthetic clear --synthetic-frames 6 --synthetic-size 64x64 --synthetic-sky-size 32x16 \
  --q 2 --gop 4 --b-frames 1 --out "$work/gop.vbim" >/dev/null
"$vbim" vectors --stream "$work/gop.vbim" --out "$work/gop" >/dev/null
grep -q '^vlc/.*,macroblock_type=' "$work/gop/vlc.txt"
grep -q '^idct/gop/lightmap/.*/result ' "$work/gop/idct.txt"
"$check" "$work/gop"
# One value changed per file: the last digit of its first answer line (not a setup, input or source).
for file in frame_hash blend idct csc draw; do
  rm -rf "$work/bad" && cp -r "$work/pcsx2" "$work/bad"
  awk '!done && !/^#/ && $1 !~ /\/(in|ycbcr|setup|source|destination)$/ {
         n = length($2); c = substr($2, n, 1); c = (c == "1") ? "2" : "1"
         $2 = substr($2, 1, n - 1) c; done = 1 }
       { print }' "$work/pcsx2/$file.txt" >"$work/bad/$file.txt"
  if "$check" "$work/bad" >"$work/out" 2>&1; then
    echo "a changed answer in $file.txt was not found:" >&2
    cat "$work/out" >&2
    exit 1
  fi
  grep -q "^$file.txt: .* match" "$work/out"
done
echo "vbim_ref.h matches the vectors of every IDCT, and finds a changed answer in each file"
