// Replay: only the GS side of a run (the presenters' blend and present, with their GS timing), fed
// by an arrival schedule instead of the drive, ring, demux and IPU: "frame k of stream s arrived
// before vsync n". Given the arrivals a port logged, it gives the per-vsync lightmap and sky (and
// their hashes.txt lines) a correct port must show; given the arrivals `vbim play` wrote
// (arrivals.csv), it reproduces that run's hashes.txt exactly (docs/porting.md, "Replay").
//
// The arrival log's format and what a malformed one gets: player/arrival_log.hpp.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "player/arrival_log.hpp"
#include "player/pipeline.hpp"
#include "player/player.hpp"
#include "player/port_frames.hpp"
#include "streams/descriptor.hpp"

namespace vbim::player {

struct ReplayOptions {
  PlatformConfig config;
  Tick duration = fromMs(10'000);
  std::optional<std::int64_t> vsyncs;  // when set, present vsyncs 0 to vsyncs - 1 (duration unused)
  Kernels kernels;
  // The port's decoded frames (player/port_frames.hpp) instead of vbim's decode of the stream.
  std::optional<PortFrames> frames;
};

class Replay {
 public:
  // `file` is a whole VBIM stream file (2,048-byte sectors); throws ConfigError when it holds no
  // playback descriptor, or an arrival names a variant or stream it does not have, or (with
  // options.frames) a picture whose file is missing or of the wrong size; GsError for settings the
  // presenters refuse.
  Replay(std::span<const std::uint8_t> file, const std::string& name, const std::vector<ReplayArrival>& arrivals,
         ReplayOptions options);
  ~Replay();
  Replay(const Replay&) = delete;
  Replay& operator=(const Replay&) = delete;

  void setSink(Player::Sink sink) { sink_ = std::move(sink); }
  void run();
  // Pictures the arrivals named that the stream could not give (missing or damaged): shown as black.
  std::int64_t missingPictures() const { return missing_; }
  // The first vsync at which timeline frame `seq` is due, on the schedule without play-late's slip:
  // the first n with time(n) >= t0 + seq / fps (docs/porting.md, "Vsyncs, due times and arrivals").
  // An arrival at vsync v is late by v - dueVsync(seq) vsyncs when that is positive.
  std::int64_t dueVsync(std::int64_t seq) const;
  // The arrival of frame `seq` of a stream and variant (the one the presenter took), or null.
  const ReplayArrival* arrivalOf(bool sky, int variant, std::int64_t seq) const;

 private:
  struct Impl;
  static Task<void> record(Replay& r);
  std::unique_ptr<Impl> impl_;
  Player::Sink sink_;
  std::int64_t missing_ = 0;
};

}  // namespace vbim::player
