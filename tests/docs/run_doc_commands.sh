#!/bin/sh
# Runs the commands README.md and docs/*.md show, so documentation that drifts fails the build.
#
# 1. Every fenced ```sh block is run with `sh -e`, blocks of one page in page order, in a scratch
#    directory of that page where the repository's top-level folders are linked (so
#    streams/samples/day_clear.vbim resolves; `build` is the build BIN_DIR belongs to) and BIN_DIR
#    (the built vbim) is first on PATH.
#    The line right before a fence may say, as an HTML comment readers do not see:
#      <!-- doc-test: skip: REASON -->       the block is not run here (REASON says where it is run)
#      <!-- doc-test: file NAME -->          the block is written to NAME for later blocks of the page
#      <!-- doc-test: setup: COMMAND -->     COMMAND runs first (any number of such lines)
# 2. Every inline code span that starts with `vbim CMD` must name a command vbim has, and each
#    --option in it must appear in `vbim CMD --help`.
# Usage: run_doc_commands.sh SOURCE_DIR BIN_DIR [PAGE...]   (default: README.md docs/*.md)
set -eu
root=$(cd "${1:?usage: run_doc_commands.sh SOURCE_DIR BIN_DIR [PAGE...]}" && pwd)
bin=$(cd "${2:?usage: run_doc_commands.sh SOURCE_DIR BIN_DIR [PAGE...]}" && pwd)
shift 2
cd "$root"
[ $# -gt 0 ] || set -- README.md docs/*.md
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vbim-doc-commands.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
PATH="$bin:$PATH"
export PATH
status=0

for page in "$@"; do
  name=$(echo "$page" | tr '/.' '__')
  work="$tmp/$name"
  blocks="$tmp/$name.blocks"
  mkdir -p "$work" "$blocks"
  for entry in "$root"/*; do
    case "$(basename "$entry")" in build* | out) continue ;; esac
    ln -s "$entry" "$work/$(basename "$entry")"
  done
  ln -s "$(dirname "$bin")" "$work/build"  # the build BIN_DIR belongs to, for `scripts/x.sh build`
  # Block n: $blocks/n (its text), $blocks/n.setup (setup lines); $blocks/list: "n kind lang line arg".
  awk -v dir="$blocks" '
    inside && /^```/ { inside = 0; close(dir "/" n); next }
    inside { print > (dir "/" n); next }
    /^```/ {
      inside = 1; n++
      lang = substr($0, 4); if (lang == "") lang = "-"
      print n, kind, lang, FNR, (arg == "" ? "-" : arg) > (dir "/list")
      printf "" > (dir "/" n)
      printf "%s", setup > (dir "/" n ".setup")
      close(dir "/" n ".setup")
      kind = "run"; arg = ""; setup = ""
      next
    }
    /^<!-- doc-test: skip: .* -->$/ { kind = "skip"; next }
    /^<!-- doc-test: file [^ ]+ -->$/ { kind = "file"; arg = $4; next }
    /^<!-- doc-test: setup: .* -->$/ {
      line = $0; sub(/^<!-- doc-test: setup: /, "", line); sub(/ -->$/, "", line)
      setup = setup line "\n"; next
    }
    { kind = "run"; arg = ""; setup = "" }
    BEGIN { kind = "run" }
  ' "$page"
  [ -f "$blocks/list" ] || continue
  while read -r n kind lang line arg; do
    case "$kind" in
      skip) continue ;;
      file)
        cp "$blocks/$n" "$work/$arg"
        continue
        ;;
    esac
    [ "$lang" = sh ] || continue
    cat "$blocks/$n.setup" "$blocks/$n" > "$blocks/$n.sh"
    if (cd "$work" && sh -e "$blocks/$n.sh") > "$blocks/$n.log" 2>&1; then
      echo "$page:$line: ran"
    else
      echo "$page:$line: this block fails as written:" >&2
      sed 's/^/  | /' "$blocks/$n.sh" >&2
      echo "  its output (last 20 lines):" >&2
      tail -n 20 "$blocks/$n.log" | sed 's/^/  > /' >&2
      status=1
    fi
  done < "$blocks/list"
done

# Inline `vbim CMD --option ...` spans: the command and its options exist.
helps="$tmp/helps"
mkdir -p "$helps"
grep -o '`vbim [a-z][a-z-]*[^`]*`' "$@" 2>/dev/null | while IFS= read -r hit; do
  page=${hit%%:*}
  span=${hit#*:}
  span=$(echo "$span" | tr -d '`')
  cmd=$(echo "$span" | awk '{ print $2 }')
  if [ ! -f "$helps/$cmd" ]; then
    if ! vbim "$cmd" --help > "$helps/$cmd" 2>&1; then
      echo "$page: \`$span\`: vbim has no command '$cmd'" >&2
      echo fail >> "$tmp/inline-failed"
      continue
    fi
  fi
  for opt in $(echo "$span" | grep -o -- ' --[a-z][a-z0-9-]*' || true); do
    if ! grep -q -- "$opt\b" "$helps/$cmd"; then
      echo "$page: \`$span\`: 'vbim $cmd' has no option $opt" >&2
      echo fail >> "$tmp/inline-failed"
    fi
  done
done
[ -f "$tmp/inline-failed" ] && status=1
[ "$status" -eq 0 ] && echo "every documented command runs as written"
exit "$status"
