#!/usr/bin/env bash
# Soak benchmark (not a timed test): plays a sample for 24 simulated hours with a fault plan of every
# kind (bench/soak/every_kind.toml) and default options (trace on), and reports wall time and peak
# RSS (GNU time). Figures: docs/reliability.md.
#   bench/soak/soak.sh [BUILD_DIR] [DURATION]      defaults: build, 86400s
set -euo pipefail
cd "$(dirname "$0")/../.."
build="${1:-build}"
duration="${2:-86400s}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
/usr/bin/time -v "$build/cli/vbim" play streams/samples/day_weather.vbim --duration "$duration" \
  --faults bench/soak/every_kind.toml --force --out "$out/run" 2> "$out/time.txt"
grep -E "Elapsed \(wall clock\)|Maximum resident set size" "$out/time.txt"
du -b "$out/run/trace.json" "$out/run/signals.vcd"
