#!/bin/sh
# Fails when a file of the repository cites something its reader cannot open: the private notes and
# article copies the project was first written from. Facts from them live in docs/ (hardware.md,
# lighting.md, dependencies.md, references.md) with their original sources; cite those instead.
# Usage: check_citations.sh SOURCE_DIR
set -eu
root=${1:?usage: check_citations.sh SOURCE_DIR}
self=tests/docs/check_citations.sh
# Case-insensitive extended regular expression of the forbidden citations.
pattern='notes/|notes ?§|notes [0-9]+\.[0-9]|\.\./shared|seeds/|ps2-hardware\.md|lighting-math\.md|performance-anchors\.md|style-anchors\.md'

cd "$root"
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  files() { git ls-files -z; }
else
  # A source tree without git (an unpacked archive): every file outside build trees.
  files() { find . -name .git -prune -o -name 'build*' -prune -o -type f -print0; }
fi

hits=$(files | xargs -0 grep -I -n -i -E -e "$pattern" -- 2>/dev/null |
  grep -v -e "^$self:" -e "^\./$self:" || true)
if [ -n "$hits" ]; then
  echo "These lines cite files that are not in the repository; cite docs/ or the original source:" >&2
  echo "$hits" >&2
  exit 1
fi
echo "no citation of files outside the repository"
