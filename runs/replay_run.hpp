// One replay, as `vbim replay` makes it: the GS side of a run (blend and present at every vsync,
// with the GS's timing, player/replay.hpp) fed by an arrival log, written as play writes its run
// directory (hashes.txt, timeline.csv, pictures) through an OutputDir, with the arrivals that came
// late or were never shown and, given hashes to compare with, the first vsync that differs
// (docs/porting.md, "Replay"). Not model code (pictures through imageio/, TOML through config/); the
// simulated clock's cost is the replay's.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace vbim::runs {

struct ReplayRequest {
  std::string stream;
  std::string file;  // the stream file on an ISO 9660 image (--file), or empty: the default
  std::string arrivals;
  std::string compare;  // a run directory or a hashes.txt to compare with, or empty
  std::string frames;   // the port's decoded frames (player/port_frames.hpp), or empty: vbim decodes
  std::string config;
  std::string duration = "60s";
  bool durationGiven = false;  // --duration given: it wins over the log's end row
  std::string policy;
  std::int64_t every = 0;
  std::string format = "png";
  std::string alpha = "opaque";
  bool force = false;
  bool json = false;  // ReplayResult::report as JSON (runs/replay_json.hpp)
  std::string out;
  // Called every 60 vsyncs with the vsyncs presented and the total (0 when only --duration says
  // it): the command's progress line, and where Ctrl-C stops it (cli/interrupt.hpp).
  std::function<void(std::int64_t, std::int64_t)> progress;
};

struct ReplayResult {
  std::string report;                  // what was replayed, the late arrivals, the comparison (`json`: the document)
  std::optional<std::string> differs;  // with `compare`: the origin whose hashes differ, if any
  bool jsonReplaced = false;           // `json`: bytes of the inputs not UTF-8 written as U+FFFD (kNotUtf8Warning)
};

// `warn` gets each warning about the arrival log (an unknown row, ...) before the replay runs.
// Throws vbim::Error on bad input and RunFailure (runs/error.hpp) when an output cannot be written.
ReplayResult replayRun(const ReplayRequest& r, const std::function<void(const std::string&)>& warn);

}  // namespace vbim::runs
