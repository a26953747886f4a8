// The reader of a run directory (the writer is player/run_dir.hpp): what a `vbim play ... --every N
// --out RUN_DIR` run left behind, as the renderer (render/render_run.hpp) needs it:
// frames/lightmap_NNNNNN.png (+ sky_NNNNNN.png), timeline.csv (one row per vsync, docs/player.md),
// faults.csv (when the drive was disturbed, player/fault_spans.hpp) and authoring.json (how the
// stream was made, when it carried a record).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "player/fault_spans.hpp"

namespace vbim::player {

struct RunFrame {
  std::int64_t vsync = 0;
  std::filesystem::path lightmap;
  std::optional<std::filesystem::path> sky;
};

struct TimelineRow {
  double timeSeconds = 0;
  std::int64_t targetSeq = 0;
  int variant = 0;
  bool behind = false;   // the lightmap is behind the frame due (a stall)
  bool catchUp = false;  // the presenter is catching up
  bool snapped = false;
};

struct RunDir {
  std::filesystem::path path;
  std::vector<RunFrame> frames;                  // by vsync
  std::map<std::int64_t, TimelineRow> timeline;  // by vsync; empty if timeline.csv is missing
  std::int64_t vsyncs = 0;                       // rows in timeline.csv
  std::vector<FaultSpan> faults;                 // faults.csv; empty without faults or the file
  std::optional<std::string> authoring;          // authoring.json as written, if the run has one
};

// Throws vbim::Error: not a directory, no frames/lightmap_*.png|exr, a timeline row that does not
// parse (file:line and what was expected).
RunDir readRunDir(const std::filesystem::path& dir);

}  // namespace vbim::player
