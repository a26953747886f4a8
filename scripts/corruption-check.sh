#!/usr/bin/env bash
# The corruption harness (issue #16): damaged copies of the sample streams (tests/streams/corruption/
# corrupt_stream.cpp: bit flips, zeroed runs, truncation, dropped/duplicated/reordered sectors,
# sectors lost at ring-bank boundaries, mangled pack/PES/sequence/descriptor headers, damage in the
# sky stream) through `vbim info`, `vbim info --json`, `vbim decode` (as text or with --json),
# `vbim play` and `vbim play --json`. Every run must end with exit 0 (play: stats.json written,
# concealment counted there; decode --json: its document counts the files the directory holds), or
# exit 1/2 with a message on stderr; info --json, decode --json and play --json print valid UTF-8
# JSON on stdout, also with exit 2; never a signal, a hang (timeout), std::terminate or a sanitizer
# report. Each stream is decoded once (a decode under ASan costs about what a play does), in a
# --format and a mode cycled by the stream's number: --json for three in four, the text summary for
# the fourth; yuv and rgba mostly, png and exr (libpng and OpenEXR: 20-30 ms a frame, 0.5-1 s a
# stream) for one in sixteen each, so every format and both modes meet damaged frames.
#
#   scripts/corruption-check.sh BUILD_DIR [SEEDS_PER_KIND] [VALGRIND_SEEDS]
#
# BUILD_DIR holds vbim and vbim_corrupt (CI: the ASan+UBSan build). With VALGRIND_SEEDS > 0, that many
# seeds per kind are also played under valgrind (memcheck) with the Release build in build/.
# Cost in CI (2 samples x 12 kinds x 10 seeds = 240 streams, 720 runs, 2 cores): about 90 s with
# the Release build, a few minutes under ASan; 12 plays under valgrind take a few minutes more. The
# GOP stream (issue #29) adds half as many streams again (one seed per kind, all three: 16 s in
# ctest on a loaded 2-core machine, 2026-12-03).
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:?usage: scripts/corruption-check.sh BUILD_DIR [SEEDS_PER_KIND] [VALGRIND_SEEDS]}"
seeds="${2:-10}"
vgSeeds="${3:-0}"
vbim="$build/cli/vbim"
corrupt="$build/tests/streams/vbim_corrupt"
for f in "$vbim" "$corrupt"; do
  [ -x "$f" ] || { echo "corruption-check: $f is missing (build the vbim and vbim_corrupt targets)" >&2; exit 2; }
done
kinds=(bitflips zeros truncate drop duplicate reorder bank_loss pack_header pes_header sequence descriptor descriptor_text
  sky)
work=$(mktemp -d "${TMPDIR:-/tmp}/vbim-corruption.XXXXXX")
trap 'rm -rf "$work"' EXIT
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"

# A stream with P and B pictures (issue #29) beside the intra-only samples: closed GOPs of 12 with two
# B pictures, two variants, played through the BDEC flow (damage counted in stats.json).
"$vbim" author --synthetic clear,overcast --synthetic-frames 30 --gop 12 --b-frames 2 --loop 6 \
  --out "$work/gop12.vbim" >/dev/null
# Generate the damaged streams.
# decode's --format and mode by the stream's number: --json three times in four, every format
# with --json over 16 streams (png and exr once each), the text summary as yuv or rgba.
decodes=("png json" "yuv json" "rgba json" "yuv text" "rgba json" "yuv json" "rgba json" "rgba text"
  "exr json" "yuv json" "rgba json" "yuv text" "rgba json" "yuv json" "yuv json" "rgba text")
n=0
for sample in streams/samples/*.vbim "$work/gop12.vbim"; do
  for kind in "${kinds[@]}"; do
    for ((seed = 1; seed <= seeds; ++seed)); do
      out="$work/$(basename "$sample" .vbim).$kind.$seed.vbim"
      rc=0
      "$corrupt" "$sample" "$out" "$kind" "$seed" || rc=$?
      if [ "$rc" = 0 ]; then
        echo "${decodes[n % 16]}" >"${out%.vbim}.decode"  # decode's --format and mode for this stream
        n=$((n + 1))
      elif [ "$rc" != 3 ]; then exit 1; fi
    done
  done
done
rm "$work/gop12.vbim"
echo "corruption-check: $n damaged streams in $work"

# The JSON documents one stream's commands printed, checked by one python start (0.1-0.3 s each on the
# 2-core machine: a start per document would cost more than the commands): each valid UTF-8 JSON, and
# decode --json's, after exit 0, counting the frame files its directory holds and naming only those.
#   python3 check_json.py DECODED_DIR EXTENSION [CMD FILE RC]...   prints "CMD: what is wrong" per failure
checkJson="$work/check_json.py"
cat >"$checkJson" <<'PY'
import json, os, sys
directory, extension, rest = sys.argv[1], sys.argv[2], sys.argv[3:]
for cmd, document, rc in zip(rest[0::3], rest[1::3], rest[2::3]):
    try:
        j = json.load(open(document, encoding="utf-8"))
    except ValueError as e:
        print(f"{cmd}: invalid JSON (or not UTF-8) on stdout: {e}")
        continue
    if cmd == "decodejson" and rc == "0":
        files = [f for f in os.listdir(directory) if f.endswith("." + extension)]
        named = [p["file"] for p in j["damaged_pictures"] if p["file"] is not None]
        if not j["output"]["files"] == j["frames"] == len(files) > 0 or not set(named) <= set(files):
            print(f"{cmd}: the document does not count the files written: {j['output']}, frames {j['frames']}, "
                  f"{len(files)} files, damaged pictures' files {named[:5]}")
PY
export checkJson

# One stream through the commands; prints a line per failure.
check_one() {
  local s="$1" vbim="$2" wrap="${3:-}" cmds="${4:-info json decode play playjson}" base rc log format mode
  local docs=() line
  base="${s%.vbim}"
  read -r format mode <"$base.decode"
  # decode --json is checked as its own command (decodejson): its document below.
  [ "$mode" = json ] && cmds="${cmds/decode/decodejson}"
  for cmd in $cmds; do
    log="$base.$cmd.log"
    rc=0
    case "$cmd" in
      info) timeout 120 $wrap "$vbim" info "$s" >"$log" 2>&1 || rc=$? ;;
      json) timeout 120 $wrap "$vbim" info --json "$s" >"$base.$cmd.json" 2>"$log" || rc=$? ;;
      decode) timeout 120 $wrap "$vbim" decode "$s" --format "$format" --force --out "$base.decoded" >"$log" 2>&1 ||
        rc=$? ;;
      decodejson) timeout 120 $wrap "$vbim" decode "$s" --format "$format" --json --force --out "$base.decoded" \
        >"$base.$cmd.json" 2>"$log" || rc=$? ;;
      play) timeout 300 $wrap "$vbim" play "$s" --duration 4s --force --out "$base.played" >"$log" 2>&1 || rc=$? ;;
      # The --json summary alone (no --out): the document is all of stdout.
      playjson) timeout 300 $wrap "$vbim" play "$s" --duration 4s --json >"$base.$cmd.json" 2>"$log" || rc=$? ;;
    esac
    local why=""
    if [ "$rc" = 124 ]; then why="timed out"
    elif [ "$rc" -gt 2 ]; then why="exit $rc"
    elif grep -qE "terminate called|AddressSanitizer|LeakSanitizer|runtime error:|ERROR SUMMARY: [1-9]" "$log"; then why="report in output"
    elif grep -q "internal error" "$log"; then why="internal error"
    elif [ "$rc" != 0 ] && [ ! -s "$log" ]; then why="exit $rc without a message"
    elif [ "$cmd" = play ] && [ "$rc" = 0 ] && [ ! -s "$base.played/stats.json" ]; then why="no stats.json"
    elif { [ "$cmd" = playjson ] || [ "$cmd" = decodejson ]; } && [ "$rc" = 0 ] && [ ! -s "$base.$cmd.json" ]; then
      why="exit 0 without the JSON summary"
    elif [ -s "$base.$cmd.json" ]; then
      docs+=("$cmd" "$base.$cmd.json" "$rc")  # checked below, also with exit 2
    fi
    if [ -n "$why" ]; then
      echo "FAIL $cmd $(basename "$s"): $why"
      sed -n 1,30p "$log" | sed 's/^/    /'
    fi
  done
  if [ "${#docs[@]}" -gt 0 ]; then
    python3 "$checkJson" "$base.decoded" "$format" "${docs[@]}" 2>&1 | while IFS= read -r line; do
      echo "FAIL ${line%%:*} $(basename "$s"): ${line#*: }"
      sed -n 1,30p "$base.${line%%:*}.log" 2>/dev/null | sed 's/^/    /'
    done
  fi
  rm -rf "$base.decoded" "$base.played" "$base".*.json
}
export -f check_one

start=$(date +%s)
failures=$(find "$work" -name '*.vbim' -print0 | sort -z |
  xargs -0 -P "$(nproc)" -I{} bash -c 'check_one "$1" "$2"' _ {} "$vbim")
echo "corruption-check: $n streams x (info, info --json, decode or decode --json, play, play --json) in $(( $(date +%s) - start )) s"
if [ "$vgSeeds" -gt 0 ]; then
  [ -x build/cli/vbim ] || { echo "corruption-check: build/cli/vbim (Release) is missing for valgrind" >&2; exit 2; }
  start=$(date +%s)
  vg="valgrind --quiet --error-exitcode=99 --exit-on-first-error=yes"
  # memcheck is ~30x slower: day_weather only, vbim play only (it runs the
  # parsers, the demux and the IPU timing model that info and decode share).
  picked=$(find "$work" -name 'day_weather.*.vbim' | sort | awk -F. -v k="$vgSeeds" '$(NF-1) <= k')
  failures+=$(printf '%s\n' $picked | xargs -P "$(nproc)" -I{} bash -c 'check_one "$1" "$2" "$3" play' _ {} \
    "$PWD/build/cli/vbim" "$vg")
  echo "corruption-check: $(printf '%s\n' $picked | wc -l) plays under valgrind in $(( $(date +%s) - start )) s"
fi
if [ -n "$failures" ]; then
  echo "$failures"
  exit 1
fi
echo "corruption-check: every run ended with a clear message or a counted concealment"
