// The text outputs of a run, shared by `vbim play`, `vbim demo` and the test API: one hashes.txt
// line and one timeline.csv row per vsync, and stats.json at the end (docs/player.md lists every
// field). Integer time in ticks next to seconds printed with fixed precision, so the files are
// byte-identical across runs and machines.
#pragma once

#include <iosfwd>
#include <string>

#include "player/player.hpp"
#include "runtime/json.hpp"

namespace vbim::player {

// "<vsync> <seconds, 6 decimals> <16 hex digits>\n"
std::string hashesLine(const VsyncRow& row);
std::string timelineHeader();
std::string timelineLine(const VsyncRow& row);
// Everything stats.json holds, for a run that has been run to its end (or to now()).
// `run`, when given, is written first as "run": where the run came from (the command's inputs and
// their digests, the vbim version: cli/provenance.hpp), so the totals can be traced to their inputs.
void writeStatsJson(const Player& player, std::ostream& out, const json::Value* run = nullptr);

}  // namespace vbim::player
