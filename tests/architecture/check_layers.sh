#!/bin/sh
# Dependencies run one way (docs/architecture.md, "Layers"). The table (layers.txt beside this script
# unless given) puts every folder of product sources in exactly one layer; this fails when
#  - a folder is listed twice, or holds sources and is not listed;
#  - a folder holds two layers: a folder of the model (layers 0 to 2) with a file in a library outside
#    the model (a vbim_library(...) without MODEL in a CMakeLists.txt);
#  - a file includes a header of a folder in a layer above its own;
#  - a chip (layer 1) includes another chip's header, except the EE (`ee`), which meets them all;
#  - two top-level folders, each with its subfolders, include each other (or more close a loop):
#    one of them holds two layers, one below and one above the other (streams/disc including ee/,
#    which includes streams/, was one).
# Reads every #include "folder/..." of the listed folders' C++ files.
#   check_layers.sh [repository root] [layer table] [least number of includes expected]
set -eu
root="${1:-.}"
table="${2:-$(cd "$(dirname "$0")" && pwd)/layers.txt}"
least="${3:-100}"
case "$table" in /*) ;; *) table="$(pwd)/$table" ;; esac
cd "$root"

bad=0
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The table, one "folder layer" per line; a folder listed twice is a folder of two layers.
if ! awk '!/^[[:space:]]*(#|$)/ {
            if (NF != 2 || $2 !~ /^[0-9]+$/) { print FILENAME ":" NR ": expected \"folder layer\": " $0; bad = 1; next }
            if ($1 in layer) { print $1 ": listed twice in the layer table (layers " layer[$1] " and " $2 "): a folder holds one layer"; bad = 1 }
            layer[$1] = $2; print $1, $2 > "/dev/stderr"
          }
          END { exit bad }' "$table" 2>"$work/layers"; then
  bad=$((bad + 1))
fi
sort -u "$work/layers" -o "$work/layers"
roots=$(cut -d' ' -f1 "$work/layers" | cut -d/ -f1 | sort -u)

# layer_of FOLDER: the folder's layer, empty if the table does not list it.
layer_of() {
  awk -v d="$1" '$1 == d { print $2; exit }' "$work/layers"
}

# Every folder holding sources is in the table.
# shellcheck disable=SC2086
find $roots \( -name '*.cpp' -o -name '*.hpp' \) 2>/dev/null | sort >"$work/files"
sed 's|/[^/]*$||' "$work/files" | sort -u >"$work/folders"
while read -r d; do
  if [ -z "$(layer_of "$d")" ]; then
    echo "$d: holds sources but has no layer in the table"
    bad=$((bad + 1))
  fi
done <"$work/folders"

# A folder of the model holds model libraries only: each source of each vbim_library(...), with the
# library's name and whether it is MODEL.
# shellcheck disable=SC2086
find $roots -name CMakeLists.txt 2>/dev/null | sort | while read -r cm; do
  awk -v dir="${cm%/CMakeLists.txt}" '
    { sub(/#.*/, ""); text = text " " $0 }
    END {
      while ((i = index(text, "vbim_library(")) > 0) {
        text = substr(text, i + 13)
        j = index(text, ")"); call = substr(text, 1, j - 1); text = substr(text, j + 1)
        n = split(call, t, /[[:space:]]+/)
        name = ""; model = "other"; insrc = 0
        for (k = 1; k <= n; ++k) {
          if (t[k] == "") continue
          if (name == "") { name = t[k]; continue }
          if (t[k] == "MODEL") { model = "model"; continue }
          if (t[k] == "SOURCES") { insrc = 1; continue }
          if (t[k] ~ /^(PUBLIC|PRIVATE|INTERFACE)$/) { insrc = 0; continue }
          if (insrc) print dir "/" t[k], name, model
        }
      }
    }' "$cm"
done >"$work/libraries"
while read -r src lib kind; do
  d=${src%/*}
  l=$(layer_of "$d")
  if [ -n "$l" ] && [ "$l" -le 2 ] && [ "$kind" != model ]; then
    echo "$d: holds two layers: it is in layer $l (the model), and $src builds $lib, a library outside the model"
    bad=$((bad + 1))
  fi
done <"$work/libraries"

# The includes, in one pass: "checked N" last, each finding before it.
awk -v layers="$work/layers" '
  BEGIN { while ((getline line < layers) > 0) { split(line, a, " "); layer[a[1]] = a[2] } }
  function folder(p) { sub(/\/[^\/]*$/, "", p); return p }
  {
    f = $0; d = folder(f)
    if (!(d in layer)) next
    while ((getline line < f) > 0) {
      if (line !~ /^[[:space:]]*#[[:space:]]*include[[:space:]]*"/) continue
      inc = line; sub(/^[^"]*"/, "", inc); sub(/".*$/, "", inc)
      if (inc !~ /\//) continue
      e = folder(inc)
      if (!(e in layer)) continue
      ++checked
      if (layer[e] > layer[d]) {
        print f ": includes " inc ", a header of a layer above its own (" layer[e] " > " layer[d] ")"
      } else if (layer[d] == 1 && layer[e] == 1 && d != e && d != "ee") {
        print f ": includes " inc ": a chip meets another chip only through the EE or the kernel"
      }
    }
    close(f)
  }
  END { print "checked " checked + 0 }' "$work/files" >"$work/includes"

# The includes between top-level folders (each with its subfolders) run one way: "from to file inc"
# for each include across them, then every pair that runs both ways, and any longer loop.
awk -v layers="$work/layers" '
  BEGIN { while ((getline line < layers) > 0) { split(line, a, " "); sub(/\/.*$/, "", a[1]); root[a[1]] = 1 } }
  {
    f = $0; r = f; sub(/\/.*$/, "", r)
    if (!(r in root)) next
    while ((getline line < f) > 0) {
      if (line !~ /^[[:space:]]*#[[:space:]]*include[[:space:]]*"/) continue
      inc = line; sub(/^[^"]*"/, "", inc); sub(/".*$/, "", inc)
      if (inc !~ /\//) continue
      e = inc; sub(/\/.*$/, "", e)
      if (e != r && (e in root) && !((r, e) in seen)) { seen[r, e] = 1; print r, e, f, inc }
    }
    close(f)
  }' "$work/files" >"$work/roots"
awk '{ first[$1 " " $2] = $3 " includes " $4 }
     END { for (k in first) { split(k, p, " ")
             if ((p[2] " " p[1]) in first && p[1] < p[2])
               print p[1] " and " p[2] " include each other (" first[k] "; " first[p[2] " " p[1]] \
                     "): one of them holds two layers" } }' "$work/roots" >>"$work/includes"
if ! grep -q ' include each other ' "$work/includes" && ! cut -d' ' -f1,2 "$work/roots" | tsort >/dev/null 2>"$work/loop"; then
  echo "the top-level folders include one another in a loop: $(grep -v '^tsort: -: input contains a loop' "$work/loop" | sed 's/^tsort: //' | tr '\n' ' ')" >>"$work/includes"
fi
checked=$(sed -n 's/^checked //p' "$work/includes")
grep -v '^checked ' "$work/includes" || true
bad=$((bad + $(grep -vc '^checked ' "$work/includes" || true)))
if [ "$checked" -lt "$least" ]; then
  echo "check_layers: only $checked includes read from $root: wrong directory?"
  exit 1
fi
if [ "$bad" -ne 0 ]; then
  echo "check_layers: $bad finding(s) against the layering"
  exit 1
fi
echo "check_layers: $(wc -l <"$work/folders") folders in one layer each; $checked includes follow the layers"
