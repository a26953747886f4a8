#!/bin/sh
# The route of a sector and the layer table in docs/architecture.md name files and folders by path:
# each must exist, so the guide a new reader follows cannot point at a file that moved.
#   check_paths.sh <repository root>
set -eu
cd "${1:-.}"
doc=docs/architecture.md
bad=0
n=0
for p in $(grep -o '`[a-z_]*/[a-z_/]*[a-z_.]*`' "$doc" | tr -d '`' | sort -u); do
  case "$p" in
    x/* | include/*) continue ;;  # placeholders ("folder x/") and installed paths
    */) [ -d "$p" ] || { echo "$doc: no folder $p"; bad=$((bad + 1)); } ;;
    *.*) [ -f "$p" ] || [ -d "$p" ] || { echo "$doc: no file $p"; bad=$((bad + 1)); } ;;
    *) [ -e "$p" ] || [ -e "$p.hpp" ] || { echo "$doc: no file or folder $p"; bad=$((bad + 1)); } ;;
  esac
  n=$((n + 1))
done
[ "$n" -ge 20 ] || { echo "check_paths: only $n paths found in $doc"; exit 1; }
[ "$bad" -eq 0 ] || exit 1
echo "check_paths: the $n paths named in $doc exist"
