// The arrival log replay reads (docs/porting.md, "Replay"): `vbim play` writes it as arrivals.csv,
// a port logs the same rows from its decode loop.
//
//   vsync   the first vsync at which the frame could be shown (it was ready after vsync - 1)
//   stream  lightmap:V or sky:V, V the variant number (0 first; `vbim info` lists them)
//   frame   the timeline frame number, counting on across loop wraps
// after a header `vsync,stream,frame`, and last, once, the end row `N,end,` (frame left empty): the
// run presented vsyncs 0 to N - 1 (play writes it; a port's log may leave it out).
//
// What a malformed log gets (each names ORIGIN:LINE):
//   refused (ConfigError): a row that is not three fields, a number that is not a non-negative
//     integer, a stream other than lightmap:V / sky:V, a row after the end row, and the same frame
//     of the same stream and variant arriving twice (its schedule would be ambiguous);
//   warned (ArrivalLog::warnings), replayed as written: rows out of vsync order (each row carries
//     its own vsync, so the order does not change the schedule), a frame arriving after a later
//     frame of its stream (no in-order decoder does that: it is shown only if it arrives before a
//     newer frame is due), and gaps (frames of a stream that never arrive: never shown).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vbim::player {

struct ReplayArrival {
  std::int64_t vsync = 0;
  bool sky = false;
  int variant = 0;
  std::int64_t seq = 0;
  int line = 0;  // line in the log (1 first); 0 when the arrival did not come from a file
};

struct ArrivalLog {
  std::vector<ReplayArrival> arrivals;  // in the file's order
  std::optional<std::int64_t> vsyncs;   // the end row's N: vsyncs the run presented; none without one
  std::vector<std::string> warnings;    // "ORIGIN:LINE: ..." for rows replayed as written (above)
};

std::string arrivalsHeader();
std::string arrivalLine(const ReplayArrival& a);
std::string arrivalsEndLine(std::int64_t vsyncs);
// Throws ConfigError "ORIGIN:LINE: what is wrong (expected ...)".
ArrivalLog parseArrivals(const std::string& text, const std::string& origin);

// "lightmap:V" or "sky:V", as the log writes the stream.
std::string arrivalStream(const ReplayArrival& a);

}  // namespace vbim::player
