#!/bin/sh
# Runs every ```sh block of a doc as written, in order, with the build's vbim first on PATH, in a
# scratch directory that sees the repository's examples/, streams/, tests/ and scripts/ (so the
# outputs do not land in the source tree). A block right after a line
# `<!-- not run by the tests: REASON -->` is skipped (it needs a cluster, root, ...).
# Usage: run_doc_commands.sh SOURCE_DIR BIN_DIR DOC
set -eu
root=$(cd "${1:?usage: run_doc_commands.sh SOURCE_DIR BIN_DIR DOC}" && pwd)
bin=$(cd "${2:?usage: run_doc_commands.sh SOURCE_DIR BIN_DIR DOC}" && pwd)
doc=${3:?usage: run_doc_commands.sh SOURCE_DIR BIN_DIR DOC}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vbim-doc-commands.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

awk -v dir="$tmp" '
  inside && /^```/ { inside = 0; close(file); next }
  inside { print > file; next }
  /^```sh$/ {
    inside = 1; n++
    file = dir "/block" n (skip ? ".skip" : ".sh")
    printf "" > file
    skip = 0
    next
  }
  /^```/ { inside = 2; file = "/dev/null"; skip = 0; next }
  /^<!-- not run by the tests: .* -->$/ { skip = 1; next }
  { skip = 0 }
' "$root/$doc"

mkdir "$tmp/work"
for d in examples streams tests scripts; do ln -s "$root/$d" "$tmp/work/$d"; done
ran=0
skipped=0
for block in $(ls "$tmp" | grep '^block' | sort -t k -k 2 -n); do
  case "$block" in
    *.skip)
      skipped=$((skipped + 1))
      continue
      ;;
  esac
  echo "$doc: running $block:"
  sed 's/^/  /' "$tmp/$block"
  if ! (cd "$tmp/work" && PATH="$bin:$PATH" sh -eu "$tmp/$block" >"$tmp/$block.out" 2>&1); then
    cat "$tmp/$block.out" >&2
    echo "$doc: $block failed (output above)" >&2
    exit 1
  fi
  ran=$((ran + 1))
done
[ "$ran" -gt 0 ] || { echo "$doc: no sh block found" >&2; exit 1; }
echo "$doc: $ran sh blocks ran as written ($skipped marked not run)"
