// Streaming a trace to its files as the run goes (runtime/trace_stream.hpp): the same events as
// the in-memory writer, nothing kept, VCD in time order with same-instant toggles coalesced by
// default, and spans that follow each other never overlapping after rounding.
#include "runtime/trace.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace vbim {
namespace {

// Records a few tracks' worth of spans, instants and counter values, out of time order as the
// model does (a span is recorded when it ends; a stall span when it begins).
void record(Tracer& t, Tick until) {
  const auto drive = t.track("drive");
  const auto ipu = t.track("ipu");
  const auto banks = t.counter("ring.banks");
  for (Tick base = 0; base < until; base += 10'000) {
    t.span(drive, base + 100, base + 2'000, "read");
    t.span(drive, base + 2'000, base + 2'500, "read");  // extends the one before
    t.span(ipu, base + 3'000, base + 3'400, "idec");
    t.span(ipu, base + 3'400, base + 3'900, "csc");  // ipu_busy 1 -> 0 -> 1 at 3400
    t.instant(drive, base + 4'000, "full");
    t.value(banks, base + 4'000, base / 10'000 % 3);
    t.span(drive, base + 5'000, base + 9'000, "stall");
    t.advance(base + 5'000);
  }
}

std::vector<std::string> lines(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  for (std::string l; std::getline(in, l);) {
    if (!l.empty() && l.back() == ',') l.pop_back();
    out.push_back(l);
  }
  std::sort(out.begin(), out.end());
  return out;
}

struct Streamed {
  std::string json;
  std::string vcd;
  Tick driveBusy = 0;
  std::size_t kept = 0;
};

Streamed stream(TraceDetail detail, Tick until, Tick window) {
  std::ostringstream json;
  std::ostringstream vcd;
  Tracer t;
  t.streamTo(json, vcd, detail, window);
  record(t, until);
  Streamed s;
  s.driveBusy = t.busyTime(0, 0, kNever);
  s.kept = t.spanCount();
  t.finish();
  s.json = json.str();
  s.vcd = vcd.str();
  return s;
}

TEST(TraceStream, WritesTheEventsTheInMemoryWriterWrites) {
  Tracer memory;
  record(memory, 200'000);
  std::ostringstream json;
  memory.writeChromeJson(json);
  const Streamed s = stream(TraceDetail::Full, 200'000, 20'000);
  EXPECT_EQ(lines(s.json), lines(json.str()));
  EXPECT_EQ(s.kept, 0u);  // nothing held in memory but the last span of each track
  EXPECT_EQ(s.driveBusy, memory.busyTime(0, 0, kNever));
  EXPECT_EQ(s.json.substr(s.json.size() - 4), "\n]}\n");
}

TEST(TraceStream, FullDetailVcdEqualsTheInMemoryOne) {
  Tracer memory;
  record(memory, 200'000);
  std::ostringstream vcd;
  memory.writeVcd(vcd);
  EXPECT_EQ(stream(TraceDetail::Full, 200'000, 20'000).vcd, vcd.str());
}

TEST(TraceStream, CoalescedVcdDropsSameInstantToggles) {
  const Streamed full = stream(TraceDetail::Full, 100'000, 20'000);
  const Streamed coalesced = stream(TraceDetail::Coalesced, 100'000, 20'000);
  // ipu_busy (identifier '"') goes 1 -> 0 -> 1 at base + 3400 in full detail only.
  const auto count = [](const std::string& v, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t p = v.find(what); p != std::string::npos; p = v.find(what, p + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count(full.vcd, "\n0\"\n"), 20u + 1);  // 2 falls per base, and the $dumpvars value
  EXPECT_EQ(count(coalesced.vcd, "\n0\"\n"), 10u + 1);
  // Times strictly increase in both.
  for (const std::string* v : {&full.vcd, &coalesced.vcd}) {
    long long last = -1;
    std::istringstream in(*v);
    for (std::string l; std::getline(in, l);) {
      if (l.empty() || l[0] != '#') continue;
      const long long t = std::stoll(l.substr(1));
      EXPECT_GT(t, last);
      last = t;
    }
  }
}

// Tick 1 is 6.78 ns, tick 3 is 20.34 ns: begin 0.007 us plus a rounded duration of 0.014 us
// (2 ticks, 13.56 ns) passed the next span's begin, 0.020 us. The duration is now the difference
// of the rounded ends.
TEST(TraceStream, SpansThatFollowEachOtherDoNotOverlapAfterRounding) {
  for (bool streamed : {false, true}) {
    std::ostringstream json;
    std::ostringstream vcd;
    Tracer t;
    if (streamed) t.streamTo(json, vcd);
    const auto a = t.track("a");
    t.span(a, 1, 3, "x");
    t.span(a, 3, 5, "y");
    if (streamed) {
      t.finish();
    } else {
      t.writeChromeJson(json);
    }
    EXPECT_NE(json.str().find(R"("ts":0.007,"dur":0.013})"), std::string::npos) << json.str();
    EXPECT_NE(json.str().find(R"("ts":0.020,"dur":0.014})"), std::string::npos) << json.str();
  }
}

// A counter that goes negative (target_seq = -1 before the first frame) is a signed value in the
// VCD, in both writers: declared `real`, written "r-1", not 64 ones (issue #33).
TEST(TraceStream, NegativeCounterValuesAreSignedInTheVcd) {
  for (bool streamed : {false, true}) {
    std::ostringstream json;
    std::ostringstream vcd;
    Tracer t;
    if (streamed) t.streamTo(json, vcd);
    const auto c = t.counter("target_seq");
    t.value(c, 2, -1);
    t.value(c, 4, 7);
    if (streamed) {
      t.finish();
    } else {
      t.writeVcd(vcd);
    }
    const std::string v = vcd.str();
    EXPECT_NE(v.find("$var real 64 "), std::string::npos) << v;
    EXPECT_NE(v.find("\nr-1 "), std::string::npos) << v;
    EXPECT_NE(v.find("\nr7 "), std::string::npos) << v;
    EXPECT_EQ(v.find("1111111111111111"), std::string::npos) << v;
  }
}

TEST(TraceStream, RepeatedRunsAreByteIdentical) {
  const Streamed a = stream(TraceDetail::Coalesced, 100'000, 20'000);
  const Streamed b = stream(TraceDetail::Coalesced, 100'000, 20'000);
  EXPECT_EQ(a.json, b.json);
  EXPECT_EQ(a.vcd, b.vcd);
}

TEST(TraceStream, TracksMustExistBeforeTheFirstRecord) {
  std::ostringstream json;
  std::ostringstream vcd;
  Tracer t;
  t.streamTo(json, vcd);
  const auto a = t.track("a");
  t.span(a, 0, 1, "x");
  EXPECT_THROW(t.track("late"), std::logic_error);
}

}  // namespace
}  // namespace vbim
