#!/bin/sh
# Dependencies run one way (docs/architecture.md, "Layers"): no file includes a header of a layer
# above its own, and of the chips only the EE meets its siblings (the IOP's ring, the stream reader,
# the GS's frame source). Reads every #include "folder/..." of the project's C++ files.
#   check_layers.sh <repository root>
set -eu
root="${1:-.}"
cd "$root"

# The layer of a path (longest folder prefix first); empty for folders the rule does not cover.
layer_of() {
  case "$1" in
    streams/authoring/* | streams/disc/* | streams/decode/*) echo 3 ;;
    lighting/authoring/*) echo 3 ;;
    runtime/*) echo 0 ;;
    iop/* | ipu/* | gs/* | ee/* | streams/*) echo 1 ;;
    player/*) echo 2 ;;
    sweep/* | config/* | lighting/* | render/* | plots/* | imageio/*) echo 3 ;;
    cli/*) echo 4 ;;
    *) echo "" ;;
  esac
}
# The component of a path, for the rule between chips.
component_of() {
  case "$1" in
    streams/*) echo streams ;;
    *) echo "${1%%/*}" ;;
  esac
}

bad=0
checked=0
files=$(find runtime iop ipu gs ee streams player sweep config lighting render plots imageio cli \
             \( -name '*.cpp' -o -name '*.hpp' \) 2>/dev/null | sort)
for f in $files; do
  from=$(layer_of "$f")
  [ -n "$from" ] || continue
  for inc in $(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$f"); do
    to=$(layer_of "$inc")
    [ -n "$to" ] || continue
    checked=$((checked + 1))
    if [ "$to" -gt "$from" ]; then
      echo "$f: includes $inc, a header of a layer above its own ($to > $from)"
      bad=$((bad + 1))
    elif [ "$from" = 1 ] && [ "$to" = 1 ]; then
      a=$(component_of "$f")
      b=$(component_of "$inc")
      if [ "$a" != "$b" ] && [ "$a" != ee ]; then
        echo "$f: includes $inc: a chip meets another chip only through the EE or the kernel"
        bad=$((bad + 1))
      fi
    fi
  done
done
if [ "$checked" -lt 100 ]; then
  echo "check_layers: only $checked includes read from $root: wrong directory?"
  exit 1
fi
if [ "$bad" -ne 0 ]; then
  echo "check_layers: $bad include(s) against the layering"
  exit 1
fi
echo "check_layers: $checked includes follow the layers"
