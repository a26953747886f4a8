#!/bin/sh
# The C block after `<!-- c-example: ref -->` in docs/porting.md compiles as strict C99 against
# ref/vbim_ref.h, runs, and prints a line of tests/vectors/frame_hash.txt exactly.
# Usage: check_porting_example.sh SOURCE_DIR CC
set -eu
root=${1:?usage: check_porting_example.sh SOURCE_DIR CC}
cc=${2:?usage: check_porting_example.sh SOURCE_DIR CC}
work=$(mktemp -d "${TMPDIR:-/tmp}/vbim-ref-example.XXXXXX")
trap 'rm -rf "$work"' EXIT
awk 'marked && /^```c$/ { inside = 1; marked = 0; next }
     inside && /^```$/ { exit }
     inside { print }
     /^<!-- c-example: ref -->$/ { marked = 1 }' "$root/docs/porting.md" >"$work/example.c"
if [ ! -s "$work/example.c" ]; then
  echo "docs/porting.md: no C block after <!-- c-example: ref -->" >&2
  exit 1
fi
"$cc" -std=c99 -Wall -Wextra -Werror -pedantic -I "$root/ref" -o "$work/example" "$work/example.c"
"$work/example" >"$work/out"
cat "$work/out"
first=$(head -n 1 "$work/out")
if ! grep -qxF "$first" "$root/tests/vectors/frame_hash.txt"; then
  echo "the example's first line is not a line of tests/vectors/frame_hash.txt: $first" >&2
  exit 1
fi
echo "docs/porting.md's C example compiles and prints a known answer"
