#include "runtime/trace.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "tests/runtime/trace_sample.hpp"

namespace vbim {
namespace {

using testing::sampleTrace;

TEST(Trace, VcdHasHeaderAndTimeOrderedChanges) {
  std::ostringstream s;
  sampleTrace().writeVcd(s);
  const std::string v = s.str();
  EXPECT_NE(v.find("$timescale 1ps $end"), std::string::npos);
  EXPECT_NE(v.find("drive_busy"), std::string::npos);
  EXPECT_NE(v.find("ring.banks"), std::string::npos);
  // Times appear in increasing order.
  long long last = -1;
  std::istringstream in(v);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] == '#') {
      const long long t = std::stoll(line.substr(1));
      EXPECT_GT(t, last);
      last = t;
    }
  }
  EXPECT_EQ(last, 2'000'000'000LL);  // 2 ms in ps: the last change (drive idle, ring = 1)
}

TEST(Trace, ByteIdenticalAcrossBuilds) {
  std::ostringstream a, b;
  sampleTrace().writeChromeJson(a);
  sampleTrace().writeChromeJson(b);
  EXPECT_EQ(a.str(), b.str());
}

TEST(Trace, BusyTimeSumsSpansInWindow) {
  Tracer t = sampleTrace();
  EXPECT_EQ(t.busyTime(0, 0, fromMs(10)), fromMs(2));
  EXPECT_EQ(t.busyTime(0, fromMs(1), fromMs(10)), fromMs(1));
  EXPECT_EQ(t.busyTime(1, 0, fromMs(10)), fromMs(1));
}

TEST(Trace, DisabledRecordsNothing) {
  Tracer t(false);
  const auto a = t.track("a");
  t.span(a, 0, 10, "x");
  EXPECT_EQ(t.spanCount(), 0u);
}

}  // namespace
}  // namespace vbim

namespace vbim {
namespace {

TEST(Trace, BackToBackSpansWithTheSameLabelCoalesce) {
  Tracer t;
  const auto a = t.track("a");
  t.span(a, 0, 10, "x");
  t.span(a, 10, 20, "x");  // contiguous, same label: extends
  t.span(a, 20, 30, "y");  // other label: new span
  t.span(a, 35, 40, "y");  // gap: new span
  EXPECT_EQ(t.spanCount(), 3u);
  EXPECT_EQ(t.busyTime(a, 0, 100), 35);
}

}  // namespace
}  // namespace vbim

namespace vbim {
namespace {

// Labels are looked up by the address of their text first; a buffer that holds another label at
// the same address must still get that label.
TEST(Trace, ALabelBufferReusedForAnotherLabelKeepsBothNames) {
  Tracer t;
  const auto a = t.track("a");
  std::string label = "first";
  label.reserve(32);
  const char* at = label.data();
  t.span(a, 0, 10, label);
  label = "other";
  ASSERT_EQ(label.data(), at);
  t.span(a, 10, 20, label);
  t.span(a, 20, 30, "first");
  t.span(a, 30, 40, std::string_view());  // an empty label, no text at all
  EXPECT_EQ(t.spanCount(), 4u);           // no two neighbours share a label
  std::ostringstream json;
  t.writeChromeJson(json);
  const std::string j = json.str();
  EXPECT_NE(j.find(R"("name":"first")"), std::string::npos);
  EXPECT_NE(j.find(R"("name":"other")"), std::string::npos);
  EXPECT_NE(j.find(R"("name":"")"), std::string::npos);
}

}  // namespace
}  // namespace vbim
