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

// Whether the display kept up to the end of the run (docs/player.md, "Stuck and starved runs"):
//   stuck    at the end of the run the lightmap had been behind schedule (its newest due frame not
//            ready) at every vsync for kStuckAfter or longer, with no new frame shown in that time:
//            a deadlocked ring, a drive that never delivers, a stall still under way;
//   starved  stuck, and no frame was ever shown;
//   ok       otherwise (a run too short to tell is ok).
// The run itself completed: the commands report it loudly and record it (stats.json "health"), and
// still exit 0 (docs/cli.md).
inline constexpr Tick kStuckAfter = fromMs(5'000);
struct RunHealth {
  std::string verdict = "ok";  // "ok", "stuck" or "starved"
  Tick stuckFor = 0;           // behind, with no new frame, from this long before the last vsync to it
};
RunHealth runHealth(const gs::PresenterCounters& lightmap, const RunTotals& totals);
// A one-line warning naming the verdict and what it means; empty for "ok".
std::string healthWarning(const RunHealth& h);

// "<vsync> <seconds, 6 decimals> <16 hex digits>\n"
std::string hashesLine(const VsyncRow& row);
std::string timelineHeader();
std::string timelineLine(const VsyncRow& row);
// The paragraph `vbim play` prints after a run: its length, host and CPU time (measured by the
// caller: the model reads no clock), frames shown, late, dropped and caught up, pop and lag maxima,
// ring underruns, retries, damage and the `images` written. `disc` names the disc.
std::string playSummary(const Player& player, const std::string& disc, double wallSeconds, double cpuSeconds,
                        std::int64_t images);

// Everything stats.json holds, for a run that has been run to its end (or to now()).
// `run`, when given, is written first as "run": where the run came from (the command's inputs and
// their digests, the vbim version: runs/provenance.hpp), so the totals can be traced to their inputs.
void writeStatsJson(const Player& player, std::ostream& out, const json::Value* run = nullptr);

}  // namespace vbim::player
