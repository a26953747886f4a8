// The --json summary of `vbim replay` (docs/cli.md, "JSON summaries"): what its text report says (the
// vsyncs replayed, the pictures the stream lacked, every arrival that came late or was never shown,
// and with --compare the first vsync whose hash differs, explained presenter by presenter) as one
// JSON document. Text from the inputs that is not UTF-8 becomes U+FFFD (runs::jsonText, as play's).
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "player/arrival_log.hpp"
#include "player/replay.hpp"
#include "player/replay_report.hpp"
#include "runs/replay_run.hpp"

namespace vbim::runs {

// What replayRun gathers as the replay runs, for the document.
struct ReplayFacts {
  std::string fileOnDisc;  // the stream's file on an ISO 9660 image, or empty: a bare stream file
  std::string policy;      // the catch-up policy in force (--policy, else the config's gs.catchup)
  std::int64_t vsyncs = 0;
  std::int64_t imagesWritten = 0;
  // (sky, variant, frame) that became a presenter's target: as player::ReplayNotes counts them.
  std::set<std::tuple<bool, int, std::int64_t>> shown;
  std::optional<player::VsyncRow> firstDifference;  // with --compare: the first row whose hash differs
};

// The arrivals of `log` before the replay's end that came after their due vsync or were never shown,
// as player::ReplayNotes::lateOrUnshown lists them in words (the same order).
struct LateArrival {
  player::ReplayArrival arrival;
  std::int64_t dueVsync = 0;
  bool late = false;
  bool neverShown = false;
};
std::vector<LateArrival> lateOrUnshown(const player::Replay& replay, const player::ArrivalLog& log,
                                       const ReplayFacts& facts);

// `vbim replay --json`.
std::string replaySummaryJson(const ReplayRequest& r, const player::Replay& replay, const player::ArrivalLog& log,
                              const ReplayFacts& facts, const std::optional<player::ExpectedHashes>& expected,
                              bool& replaced);

}  // namespace vbim::runs
