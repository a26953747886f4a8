// Writes a Tracer's records to trace.json and signals.vcd while the run goes, so memory does not
// grow with the run's length (issue #16: a 1 h run held 2 GB of spans). Used by Tracer::streamTo.
//
// JSON (Chrome trace events, Perfetto): an event is written when it is final: a span when the next
// span of its track cannot extend it (or the clock has moved past it), an instant or counter value
// at once. Viewers need no order in this file.
// VCD (GTKWave) needs time order, but spans arrive when they end and begin in the past: changes wait
// in a heap and are written once the clock is `window` past them (Tracer::advance). A change older
// than what was already written is written at that time and counted (lateChanges()).
// Detail kCoalesced (the default) writes, per signal and instant, only the value it ends the instant
// with, and nothing if that is the value it had: a same-instant 0->1->0 toggle (ipu_busy between two
// macroblocks) cannot be seen in a viewer. kFull writes every change.
#pragma once

#include <charconv>
#include <concepts>
#include <cstdint>
#include <deque>
#include <ostream>
#include <queue>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/clock.hpp"

namespace vbim {

enum class TraceDetail { Coalesced, Full };

// Text for one of the trace files, gathered in a buffer and handed to the stream in pieces of
// kChunk bytes: the stream's formatted output (std::ostream's number formatting goes through
// vsnprintf) was most of the trace's cost. Numbers are written with std::to_chars.
class TraceText {
 public:
  explicit TraceText(std::ostream& os) : os_(os) { buf_.reserve(kChunk + kChunk / 4); }
  TraceText(const TraceText&) = delete;
  TraceText& operator=(const TraceText&) = delete;

  TraceText& operator<<(std::string_view s) {
    buf_.append(s);
    return spill();
  }
  TraceText& operator<<(const char* s) { return *this << std::string_view(s); }
  TraceText& operator<<(const std::string& s) { return *this << std::string_view(s); }
  TraceText& operator<<(char c) {
    buf_.push_back(c);
    return spill();
  }
  template <std::integral T>
  TraceText& operator<<(T v) {
    char digits[24];
    const auto r = std::to_chars(digits, digits + sizeof digits, v);
    buf_.append(digits, r.ptr);
    return spill();
  }
  void flush() {
    os_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
    buf_.clear();
  }

 private:
  static constexpr std::size_t kChunk = 256 * 1024;
  TraceText& spill() {
    if (buf_.size() >= kChunk) flush();
    return *this;
  }
  std::ostream& os_;
  std::string buf_;
};

// Nanoseconds as microseconds with three decimals ("12.345"), for `text << Micros{ns}`.
struct Micros {
  long long ns;
};
TraceText& operator<<(TraceText& text, Micros m);

class TraceStream {
 public:
  TraceStream(std::ostream& json, std::ostream& vcd, TraceDetail detail, Tick window);

  // Written once, before the first record: every track and counter must exist by then.
  void header(const std::vector<std::string>& tracks, const std::vector<std::string>& counters,
              const std::vector<std::string>& labels);
  void labelAdded(std::string_view label);

  void span(std::uint32_t track, Tick begin, Tick end, std::uint32_t label);
  void instant(std::uint32_t track, Tick t, std::uint32_t label);
  void value(std::uint32_t counter, Tick t, std::int64_t v);
  void advance(Tick now);
  void finish();

  // Busy time of a track within [from, to): spans already written count whole, the one still
  // held is clipped (the player asks at the end of a run, for the drive, whose spans follow each
  // other: every written span ends before the clock).
  Tick busyTime(std::uint32_t track, Tick from, Tick to) const;
  std::int64_t lateChanges() const { return late_; }

 private:
  struct Held {
    Tick begin = -1;
    Tick end = -1;
    std::uint32_t label = 0;
  };
  struct Change {
    Tick t;
    std::uint64_t seq;
    std::uint32_t var;
    std::int64_t v;
    bool operator>(const Change& o) const { return t != o.t ? t > o.t : seq > o.seq; }
  };
  void release(std::uint32_t track);  // writes the held span of a track
  void change(Tick t, std::uint32_t var, std::int64_t v);
  void flushBefore(Tick limit);      // writes every VCD change before `limit`
  const Change* nextChange() const;  // the earliest pending change by (t, seq), or null
  void popChange(const Change* c);
  void writeGroup(Tick t);
  void sep();

  TraceText json_;
  TraceText vcd_;
  TraceDetail detail_;
  Tick window_;
  std::size_t tracks_ = 0;
  std::vector<std::string> quoted_;  // labels as JSON strings
  std::vector<std::string> counterNames_;
  std::vector<std::string> quotedCounters_;  // counter names as JSON strings
  std::vector<std::string> ids_;             // VCD identifier per variable: tracks, then counters
  std::vector<Held> held_;
  std::vector<Tick> busy_;
  std::vector<std::int64_t> shown_;  // VCD value last written, per variable
  // Pending VCD changes, written in (t, seq) order. Most come in time order (counters at the
  // current instant) and are appended to ordered_; a change earlier than the last appended one (a
  // span's end, released late) goes to the heap. The two are merged when written.
  std::deque<Change> ordered_;
  std::priority_queue<Change, std::vector<Change>, std::greater<>> pending_;
  std::vector<Change> group_;  // the changes of one instant (flushBefore, writeGroup)
  std::vector<Change> last_;   // coalescing scratch (writeGroup)
  std::uint64_t seq_ = 0;
  Tick written_ = 0;  // every VCD change before this time is written
  long long lastPs_ = 0;
  std::int64_t late_ = 0;
  bool first_ = true;
};

// Helpers shared with the in-memory writers of runtime/trace.cpp.
namespace trace_format {
long long nanos(Tick t);             // nearest nanosecond
std::string micros(long long ns);    // "12.345"
long long vcdPicoseconds(Tick t);    // nearest picosecond
std::string vcdId(std::size_t n);    // printable identifier code
std::string vcdName(std::string s);  // blanks to underscores
// A counter's value change in VCD: counters are declared `real` so a viewer shows a negative value
// (target_seq = -1 before the first frame) as -1, not as 2^64 - 1 (issue #33).
std::string counterValue(std::int64_t v);  // "r-1"
inline constexpr const char* kCounterVar = "$var real 64 ";
}  // namespace trace_format

}  // namespace vbim
