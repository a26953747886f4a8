// What `vbim replay` says about a replay (docs/porting.md, "Replay"): its timeline.csv, the hashes it
// is compared with (--compare), what each presenter showed at a vsync, and the arrivals that came
// late or were never shown.
#pragma once

#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "player/arrival_log.hpp"
#include "player/player.hpp"
#include "player/replay.hpp"

namespace vbim::player {

// The hashes a replay is compared with: a run directory's hashes.txt or a port's, one line per
// vsync from 0, `<vsync> <time> <16 hex digits>` (the time is the port's own and not compared).
struct ExpectedHashes {
  std::string origin;                 // the file read
  std::vector<std::uint64_t> hashes;  // by vsync: line vsync + 1
};
// `path` a directory: path/hashes.txt. Throws ConfigError "FILE:LINE: what (expected ...)".
ExpectedHashes readExpectedHashes(const std::filesystem::path& path);

class ReplayNotes;
// Empty when the row's hash is the expected one; else the first difference, explained by `notes`
// (which has seen the row).
std::string hashDifference(const ExpectedHashes& expected, const VsyncRow& row, const ReplayNotes& notes);

// timeline.csv of a replay: play's columns that apply to it (not lag, sky_lag or ring_banks, which
// need the drive and a reference run), then where the target came from: the vsync it arrived at,
// the vsync it was due at and how many vsyncs late it arrived (0 on time; -1 without a target).
std::string replayTimelineHeader();
std::string replayTimelineLine(const VsyncRow& row, const Replay& replay);

// Follows a replay vsync by vsync (call add for each row) and explains it.
class ReplayNotes {
 public:
  ReplayNotes(const Replay& replay, const ArrivalLog& log, std::string origin)
      : replay_(replay), log_(log), origin_(std::move(origin)) {}
  void add(const VsyncRow& row);
  // Indented lines: what the lightmap and the sky showed at the row's vsync, the frame due, its
  // target and where and when the target arrived (ORIGIN:LINE), late or on time.
  std::string describe(const VsyncRow& row) const;
  // One line per arrival that came after its due vsync or was never shown, in the log's order.
  std::vector<std::string> lateOrUnshown() const;

 private:
  std::string presenter(const char* name, bool sky, const gs::VsyncRecord& r, std::int64_t vsync) const;
  const Replay& replay_;
  const ArrivalLog& log_;
  std::string origin_;
  std::set<std::tuple<bool, int, std::int64_t>> shown_;  // (sky, variant, frame) that became a target
  std::int64_t vsyncs_ = 0;
};

}  // namespace vbim::player
