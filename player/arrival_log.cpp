#include "player/arrival_log.hpp"

#include <algorithm>
#include <charconv>
#include <map>
#include <sstream>
#include <string_view>
#include <tuple>

#include "runtime/error.hpp"

namespace vbim::player {

std::string arrivalsHeader() {
  return "vsync,stream,frame\n";
}

std::string arrivalStream(const ReplayArrival& a) {
  return (a.sky ? "sky:" : "lightmap:") + std::to_string(a.variant);
}

std::string arrivalLine(const ReplayArrival& a) {
  return std::to_string(a.vsync) + "," + arrivalStream(a) + "," + std::to_string(a.seq) + "\n";
}

std::string arrivalsEndLine(std::int64_t vsyncs) {
  return std::to_string(vsyncs) + ",end,\n";
}

namespace {

bool parseInt(std::string_view s, std::int64_t& v) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && end == s.data() + s.size() && v >= 0;
}

std::string frames(std::int64_t from, std::int64_t to) {
  return from == to ? "frame " + std::to_string(from) : "frames " + std::to_string(from) + "-" + std::to_string(to);
}

// The warnings of a well-formed log: rows out of vsync order, and per stream (in vsync order) a
// frame after a later one or a gap in the frame numbers.
void checkOrder(ArrivalLog& log, const std::string& origin) {
  const auto at = [&](const ReplayArrival& a) { return origin + ":" + std::to_string(a.line) + ": "; };
  const std::vector<ReplayArrival>& rows = log.arrivals;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    if (rows[i].vsync < rows[i - 1].vsync) {
      log.warnings.push_back(at(rows[i]) + "vsync " + std::to_string(rows[i].vsync) + " after vsync " +
                             std::to_string(rows[i - 1].vsync) + " (line " + std::to_string(rows[i - 1].line) +
                             "): rows out of vsync order; replayed by their vsync");
    }
  }
  std::vector<ReplayArrival> byVsync = rows;
  std::stable_sort(byVsync.begin(), byVsync.end(),
                   [](const ReplayArrival& x, const ReplayArrival& y) { return x.vsync < y.vsync; });
  for (const bool sky : {false, true}) {
    const std::string name = sky ? "sky" : "lightmap";
    const ReplayArrival* newest = nullptr;                 // the highest frame so far of this stream
    std::map<std::int64_t, const ReplayArrival*> firstOf;  // frame -> its first arrival in vsync order
    for (const ReplayArrival& a : byVsync) {
      if (a.sky != sky) continue;
      firstOf.emplace(a.seq, &a);
      if (newest != nullptr && a.seq < newest->seq) {
        log.warnings.push_back(at(a) + name + " frame " + std::to_string(a.seq) + " arrives at vsync " +
                               std::to_string(a.vsync) + ", after frame " + std::to_string(newest->seq) + " (line " +
                               std::to_string(newest->line) + ", vsync " + std::to_string(newest->vsync) +
                               "): a decoder delivers in order; it is shown only if no newer frame is due");
      }
      if (newest == nullptr || a.seq > newest->seq) newest = &a;
    }
    // Gaps: frame numbers the log never names, between 0 and its last frame.
    std::int64_t expected = 0;
    for (const auto& [seq, a] : firstOf) {
      if (seq > expected) {
        log.warnings.push_back(at(*a) + name + " " + frames(expected, seq - 1) +
                               (seq - 1 == expected ? " never arrives" : " never arrive") + " (the log goes on at " +
                               "frame " + std::to_string(seq) + "): never shown");
      }
      expected = seq + 1;
    }
  }
}

}  // namespace

ArrivalLog parseArrivals(const std::string& text, const std::string& origin) {
  ArrivalLog log;
  std::istringstream in(text);
  std::string line;
  int n = 0;
  const auto bad = [&](const std::string& what) {
    return ConfigError(origin + ":" + std::to_string(n) + ": " + what +
                       " (expected vsync,stream,frame: e.g. 12,lightmap:0,6; stream lightmap:V or sky:V; "
                       "each frame once; last, the end row N,end,)");
  };
  std::map<std::tuple<bool, int, std::int64_t>, const ReplayArrival*> seen;  // filled after the parse
  while (std::getline(in, line)) {
    ++n;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    if (n == 1 && line == "vsync,stream,frame") continue;
    const auto c1 = line.find(',');
    const auto c2 = c1 == std::string::npos ? c1 : line.find(',', c1 + 1);
    if (c2 == std::string::npos || line.find(',', c2 + 1) != std::string::npos) throw bad("'" + line + "'");
    const std::string stream = line.substr(c1 + 1, c2 - c1 - 1);
    if (log.vsyncs) throw bad("'" + line + "' after the end row");
    if (stream == "end") {
      std::int64_t vsyncs = 0;
      if (!parseInt(std::string_view(line).substr(0, c1), vsyncs)) throw bad("end vsync '" + line.substr(0, c1) + "'");
      if (c2 + 1 != line.size()) throw bad("end row '" + line + "' with a frame");
      log.vsyncs = vsyncs;
      continue;
    }
    ReplayArrival a;
    std::int64_t variant = 0;
    const auto colon = stream.find(':');
    const std::string kind = stream.substr(0, colon);
    if (colon == std::string::npos || (kind != "lightmap" && kind != "sky") ||
        !parseInt(std::string_view(stream).substr(colon + 1), variant) || variant > 255) {
      throw bad("stream '" + stream + "'");
    }
    if (!parseInt(std::string_view(line).substr(0, c1), a.vsync)) throw bad("vsync '" + line.substr(0, c1) + "'");
    if (!parseInt(std::string_view(line).substr(c2 + 1), a.seq)) throw bad("frame '" + line.substr(c2 + 1) + "'");
    a.sky = kind == "sky";
    a.variant = static_cast<int>(variant);
    a.line = n;
    log.arrivals.push_back(a);
  }
  for (const ReplayArrival& a : log.arrivals) {
    const auto [it, fresh] = seen.emplace(std::make_tuple(a.sky, a.variant, a.seq), &a);
    if (!fresh) {
      n = a.line;
      throw bad(arrivalStream(a) + " frame " + std::to_string(a.seq) + " arrives twice (first at line " +
                std::to_string(it->second->line) + ", vsync " + std::to_string(it->second->vsync) + ")");
    }
  }
  checkOrder(log, origin);
  return log;
}

}  // namespace vbim::player
