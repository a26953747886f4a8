#!/bin/sh
# Fails when docs/test-api.md shows code that is not in the repository as shown. A code block right
# after a line `<!-- file: PATH -->` must be exactly the file PATH; every C++ block must carry such
# a line (the C++ is then compiled and run: examples/stall-test/ is built by tests/examples/ and by
# scripts/check-install.sh); and every C++ file of examples/stall-test/ must be shown.
# Usage: check_doc_examples.sh SOURCE_DIR
set -eu
root=${1:?usage: check_doc_examples.sh SOURCE_DIR}
doc=docs/test-api.md
cd "$root"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vbim-doc-examples.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

# Each block n goes to $tmp/n; $tmp/list gets "n path lang" (path "-" when unmarked).
awk -v dir="$tmp" '
  inside && /^```/ { inside = 0; close(dir "/" n); next }
  inside { print > (dir "/" n); next }
  /^```/ {
    inside = 1; n++
    lang = substr($0, 4)
    print n, (marked == "" ? "-" : marked), (lang == "" ? "-" : lang) > (dir "/list")
    printf "" > (dir "/" n)
    marked = ""
    next
  }
  /^<!-- file: [^ ]+ -->$/ { marked = $3; next }
  { marked = "" }
' "$doc"

status=0
shown=""
while read -r n path lang; do
  if [ "$path" = "-" ]; then
    if [ "$lang" = cpp ]; then
      echo "$doc: C++ block $n is not marked with the file it is (<!-- file: PATH -->)" >&2
      status=1
    fi
    continue
  fi
  shown="$shown $path"
  if [ ! -f "$path" ]; then
    echo "$doc: block $n claims to be $path, which does not exist" >&2
    status=1
  elif ! diff -u "$path" "$tmp/$n" >&2; then
    echo "$doc: block $n differs from $path (diff above: - the file, + the doc)" >&2
    status=1
  fi
done <"$tmp/list"

for f in examples/stall-test/*.cpp; do
  case " $shown " in
    *" $f "*) ;;
    *)
      echo "$doc does not show $f" >&2
      status=1
      ;;
  esac
done
[ "$status" -eq 0 ] && echo "$doc shows the example files as they are"
exit "$status"
