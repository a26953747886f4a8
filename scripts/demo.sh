#!/usr/bin/env bash
# README command 1: install what is missing, build, run the main job.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh build
./build/cli/vbim demo --force "$@"  # the main job owns out/demo/ and replaces it on each run
