// Busy spans and counters on the simulated clock, written as Chrome trace-event JSON (opens in
// the Perfetto UI) and as VCD (opens in GTKWave). Output is byte-identical across runs: no dates,
// no host times, integer time formatting, insertion order preserved.
#pragma once

#include <array>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/clock.hpp"
#include "runtime/trace_stream.hpp"

namespace vbim {

class Tracer {
 public:
  using TrackId = std::uint32_t;
  using CounterId = std::uint32_t;

  explicit Tracer(bool enabled = true) : enabled_(enabled) {}
  Tracer(Tracer&&) = default;
  Tracer& operator=(Tracer&&) = default;
  ~Tracer();
  bool enabled() const { return enabled_; }

  // A row of busy spans: one per component ("drive", "sif", "ipu", ...).
  TrackId track(std::string name);
  // A named integer signal ("ring.banks_full", "gs.pop").
  CounterId counter(std::string name);

  // Marks track busy from `begin` to `end` doing `what` (a short label). A span that starts exactly
  // where the track's previous span with the same label ended extends it, so a component that is
  // busy back to back shows as one span (the busy time is the same; the files stay small).
  void span(TrackId track, Tick begin, Tick end, std::string_view what);
  void begin(TrackId track, Tick t, std::string_view what);
  void end(TrackId track, Tick t);
  // Records a counter value from time t on. Repeated equal values are dropped.
  void value(CounterId counter, Tick t, std::int64_t v);
  // A zero-length marker on a track ("stall", "underrun").
  void instant(TrackId track, Tick t, std::string_view what);

  // In memory (the default): every record is kept until one of these writes the whole trace.
  void writeChromeJson(std::ostream& out) const;
  void writeVcd(std::ostream& out) const;

  // Streaming (runtime/trace_stream.hpp): records go to `json` and `vcd` as they become final and
  // are not kept, so memory does not grow with the run. Call before the first record, with every
  // track and counter created; then advance(now) as the clock moves (VCD changes more than
  // `window` before it are written) and finish() at the end. The streams must outlive the Tracer's
  // use of them.
  void streamTo(std::ostream& json, std::ostream& vcd, TraceDetail detail = TraceDetail::Coalesced,
                Tick window = fromMs(10'000));
  void advance(Tick now);
  void finish();
  bool streaming() const { return stream_ != nullptr; }
  // kFull in memory; streamTo's choice when streaming. Components may record coarser spans when
  // it is kCoalesced (the IPU: one span per busy stretch instead of two per macroblock).
  TraceDetail detail() const { return detail_; }
  const TraceStream* stream() const { return stream_.get(); }

  std::size_t spanCount() const { return spans_.size(); }  // in memory only
  // Sum of span lengths on a track within [from, to) (streaming: see TraceStream::busyTime).
  Tick busyTime(TrackId track, Tick from, Tick to) const;

 private:
  struct Span {
    TrackId track;
    Tick begin;
    Tick end;  // begin == end: instant
    std::uint32_t label;
    bool instant;
  };
  struct Sample {
    CounterId counter;
    Tick t;
    std::int64_t v;
  };
  struct Open {
    Tick begin = -1;
    std::uint32_t label = 0;
  };
  std::uint32_t intern(std::string_view s);
  TraceStream* live();  // the stream, its header written; null when in memory

  bool enabled_;
  std::vector<std::string> tracks_;
  std::vector<Open> open_;
  std::vector<std::size_t> lastSpan_;  // per track: index in spans_ of its latest span, or npos
  std::vector<std::string> counters_;
  std::vector<std::int64_t> last_;
  std::vector<bool> hasLast_;
  std::vector<std::string> labels_;
  struct RecentLabel {
    const char* data = nullptr;
    std::uint32_t id = 0;
  };
  std::array<RecentLabel, 16> recentLabels_{};  // by the label text's address
  std::vector<Span> spans_;
  std::vector<Sample> samples_;
  std::unique_ptr<TraceStream> stream_;
  bool headerWritten_ = false;
  TraceDetail detail_ = TraceDetail::Full;
};

}  // namespace vbim
