#!/bin/sh
# Regenerates the player's golden hash and lag lists (tests/player/golden/*.txt and golden/lag/*.txt)
# from the current model and sample streams, e.g. after the samples were re-authored. Review
# `git diff tests/player/golden` before committing: every changed line is a vsync whose output changed.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-"$root/build"}
cmake --build "$build" --target player_tests
VBIM_UPDATE_GOLDEN=1 VBIM_SOURCE_DIR="$root" "$build/tests/player/player_tests" --gtest_filter='Samples/Golden.*:Samples/LagGolden.*'
echo "updated $root/tests/player/golden; review with: git -C $root diff --stat tests/player/golden"
