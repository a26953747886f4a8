// A run directory: the files of a play, written as the run goes (docs/player.md, "Outputs"):
//   hashes.txt     one line per vsync (player/report.hpp)
//   timeline.csv   one row per vsync
//   arrivals.csv   each frame the presenters received, for `vbim replay` (player/replay.hpp)
//   faults.csv     when the drive was disturbed: the plan's timed faults, the read errors met
//                  (player/fault_spans.hpp)
//   trace.json, signals.vcd   the trace, streamed as the run goes (optional)
//   ipu_commands.csv   every IPU command, word and time (optional: player/ipu_command_log.hpp)
//   frames/lightmap_NNNNNN.EXT, frames/sky_NNNNNN.EXT   pictures every N vsyncs and at given times
//   stats.json     at the end (player/report.hpp)
// `vbim play` and `vbim demo` write through it, and a test can too (docs/test-api.md): attach a
// RunDirWriter to the run's Player before it runs, finish() it after. Picture files are written by
// a function the caller gives (the model writes no image format: `vbim play` gives PNG or EXR), on a
// host thread of their own by default (player/picture_queue.hpp: same files, off the simulation's
// path); the rest is the model's own text. `vbim render` reads what it wrote
// (player/run_dir_reader.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <set>
#include <string>

#include "player/fault_spans.hpp"
#include "player/picture_queue.hpp"
#include "player/player.hpp"
#include "runtime/json.hpp"
#include "runtime/trace.hpp"

namespace vbim::player {

struct RunDirOptions {
  std::int64_t every = 0;  // pictures every N vsyncs (0: never)
  std::set<Tick> at;       // and at the first vsync at or after each of these times
  // Writes one picture (the lightmap or the sky, as the GS holds it: a copy the function may change)
  // to a path ending in "." + imageExtension. Null: no pictures.
  std::function<void(const std::filesystem::path&, Rgba8Image&)> writeImage;
  std::string imageExtension = "png";
  // How many pictures may wait for the thread that writes them (PictureQueue); 0: no thread, each
  // is written on the simulation's thread as it comes.
  std::size_t pictureQueue = 8;
  bool trace = true;  // trace.json and signals.vcd (the Player must trace: PlayerOptions::trace)
  TraceDetail traceDetail = TraceDetail::Coalesced;
  bool ipuCommands = false;                    // ipu_commands.csv (`vbim play --trace-detail ipu`)
  std::function<void(const VsyncRow&)> onRow;  // every vsync, after its lines are written
};

class RunDirWriter {
 public:
  // Opens the files in `dir` (an existing directory) and attaches to `player` before it runs: its
  // sink (chained after any sink it has), its arrival hook and its trace. Throws vbim::Error when a
  // file cannot be opened.
  RunDirWriter(Player& player, const std::filesystem::path& dir, RunDirOptions options);
  RunDirWriter(const RunDirWriter&) = delete;
  RunDirWriter& operator=(const RunDirWriter&) = delete;

  // Returns once every picture of the vsyncs so far is written; throws the first picture that
  // failed (what writeImage threw). finish() calls it first.
  void flushPictures();
  // CPU time of the thread that writes the pictures so far (0 without one), for summaries.
  double pictureCpuSeconds() const { return pictures_ ? pictures_->cpuSeconds() : 0.0; }

  // After the run: closes hashes.txt, timeline.csv and arrivals.csv (its end line), writes
  // faults.csv and stats.json (with `run` first, when given: where the run came from) and finishes the trace.
  // Throws vbim::Error when a file cannot be written.
  void finish(const json::Value* run = nullptr);

  std::int64_t images() const { return images_; }  // picture files written so far
  const std::filesystem::path& directory() const { return dir_; }

 private:
  void onVsync(const VsyncRow& row, const Rgba8Image& lightmap, const Rgba8Image* sky);
  void writePicture(std::filesystem::path path, const Rgba8Image& picture);  // a copy, queued or written

  Player& player_;
  std::filesystem::path dir_;
  RunDirOptions options_;
  std::ofstream hashes_;
  std::ofstream timeline_;
  std::ofstream arrivals_;
  std::ofstream traceJson_;
  std::ofstream traceVcd_;
  std::ofstream ipuCommands_;
  std::set<Tick>::const_iterator nextAt_;
  std::int64_t presented_ = 0;  // the vsyncs of hashes.txt: arrivals.csv's end row, for replay
  std::int64_t images_ = 0;
  ReadErrorSpans readErrors_;
  Rgba8Image copy_;                       // without a PictureQueue: the copy handed to writeImage
  std::optional<PictureQueue> pictures_;  // last: its thread stops before options_ goes
};

}  // namespace vbim::player
