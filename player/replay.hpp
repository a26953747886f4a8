// Replay: only the GS side of a run (the presenters' blend and present, with their GS timing), fed
// by an arrival schedule instead of the drive, ring, demux and IPU: "frame k of stream s arrived
// before vsync n". Given the arrivals a port logged, it gives the per-vsync lightmap and sky (and
// their hashes.txt lines) a correct port must show; given the arrivals `vbim play` wrote
// (arrivals.csv), it reproduces that run's hashes.txt exactly (docs/porting.md, "Replay").
//
// arrivals.csv: a header `vsync,stream,frame`, then one line per frame a presenter received:
//   vsync   the first vsync at which the frame could be shown (it was ready after vsync - 1)
//   stream  lightmap:V or sky:V, V the variant number (0 first; `vbim info` lists them)
//   frame   the timeline frame number, counting on across loop wraps (stream frame = frame mod
//           frames per variant)
// and last, once, the end row `N,end,` (frame left empty): the run presented vsyncs 0 to N - 1, so
// a replay of the log presents as many (play writes it; a port's log may leave it out).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "player/pipeline.hpp"
#include "player/player.hpp"
#include "streams/descriptor.hpp"

namespace vbim::player {

struct ReplayArrival {
  std::int64_t vsync = 0;
  bool sky = false;
  int variant = 0;
  std::int64_t seq = 0;
};

struct ArrivalLog {
  std::vector<ReplayArrival> arrivals;
  std::optional<std::int64_t> vsyncs;  // the end row's N: vsyncs the run presented; none without one
};

std::string arrivalsHeader();
std::string arrivalLine(const ReplayArrival& a);
std::string arrivalsEndLine(std::int64_t vsyncs);
// Throws ConfigError "ORIGIN:LINE: what is wrong (expected ...)".
ArrivalLog parseArrivals(const std::string& text, const std::string& origin);

struct ReplayOptions {
  PlatformConfig config;
  Tick duration = fromMs(10'000);
  std::optional<std::int64_t> vsyncs;  // when set, present vsyncs 0 to vsyncs - 1 (duration unused)
  Kernels kernels;
};

class Replay {
 public:
  // `file` is a whole VBIM stream file (2,048-byte sectors); throws ConfigError when it holds no
  // playback descriptor, or an arrival names a variant or stream it does not have; GsError for
  // settings the presenters refuse.
  Replay(std::span<const std::uint8_t> file, const std::string& name, const std::vector<ReplayArrival>& arrivals,
         ReplayOptions options);
  ~Replay();
  Replay(const Replay&) = delete;
  Replay& operator=(const Replay&) = delete;

  void setSink(Player::Sink sink) { sink_ = std::move(sink); }
  void run();
  // Pictures the arrivals named that the stream could not give (missing or damaged): shown as black.
  std::int64_t missingPictures() const { return missing_; }

 private:
  struct Impl;
  static Task<void> record(Replay& r);
  std::unique_ptr<Impl> impl_;
  Player::Sink sink_;
  std::int64_t missing_ = 0;
};

}  // namespace vbim::player
