// The arrival log replay reads: what is refused (with its line) and what is replayed with a warning
// naming its line (player/arrival_log.hpp, docs/porting.md "Malformed arrival logs").
#include "player/arrival_log.hpp"

#include <gtest/gtest.h>

#include <string>

#include "runtime/error.hpp"

namespace vbim::player {
namespace {

std::string refusal(const std::string& text) {
  try {
    parseArrivals(text, "log.csv");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(accepted)";
}

bool hasWarning(const ArrivalLog& log, const std::string& part) {
  for (const std::string& w : log.warnings) {
    if (w.find(part) != std::string::npos) return true;
  }
  return false;
}

TEST(ArrivalLog, AWellFormedLogHasNoWarningsAndKeepsItsLines) {
  const ArrivalLog log = parseArrivals(
      "vsync,stream,frame\n24,lightmap:0,0\n24,sky:0,0\n91,lightmap:0,1\n91,sky:0,1\n120,end,\n", "log.csv");
  EXPECT_TRUE(log.warnings.empty());
  ASSERT_EQ(log.arrivals.size(), 4u);
  EXPECT_EQ(log.arrivals[2].line, 4);
  EXPECT_EQ(log.arrivals[2].vsync, 91);
  EXPECT_EQ(log.arrivals[2].seq, 1);
  EXPECT_EQ(log.vsyncs, 120);
}

TEST(ArrivalLog, BadNumbersAreRefusedWithTheirLine) {
  EXPECT_NE(refusal("vsync,stream,frame\n3,lightmap:0,1\n-4,lightmap:0,2\n").find("log.csv:3: vsync '-4'"),
            std::string::npos);
  EXPECT_NE(refusal("vsync,stream,frame\n3,lightmap:0,x\n").find("log.csv:2: frame 'x'"), std::string::npos);
  EXPECT_NE(refusal("vsync,stream,frame\n3,lightmap:0\n").find("log.csv:2: '3,lightmap:0'"), std::string::npos);
  EXPECT_NE(refusal("vsync,stream,frame\n3,lightmap:300,1\n").find("log.csv:2: stream 'lightmap:300'"),
            std::string::npos);
}

TEST(ArrivalLog, AFrameArrivingTwiceIsRefusedNamingBothLines) {
  const std::string e = refusal("vsync,stream,frame\n3,lightmap:0,1\n3,sky:0,1\n9,lightmap:0,1\n");
  EXPECT_NE(e.find("log.csv:4: lightmap:0 frame 1 arrives twice (first at line 2, vsync 3)"), std::string::npos) << e;
  // The same frame number of another variant is a branch, not a duplicate.
  const ArrivalLog branch = parseArrivals("3,lightmap:0,1\n9,lightmap:1,1\n", "log.csv");
  EXPECT_EQ(branch.arrivals.size(), 2u);
}

TEST(ArrivalLog, RowsOutOfVsyncOrderAreWarnedAndKept) {
  const ArrivalLog log = parseArrivals("vsync,stream,frame\n10,lightmap:0,0\n70,lightmap:0,1\n40,sky:0,0\n", "log.csv");
  EXPECT_EQ(log.arrivals.size(), 3u);
  EXPECT_TRUE(hasWarning(log, "log.csv:4: vsync 40 after vsync 70 (line 3)")) << log.warnings.size();
}

TEST(ArrivalLog, GapsAreWarnedAtTheLineWhereTheLogGoesOn) {
  const ArrivalLog log =
      parseArrivals("vsync,stream,frame\n10,lightmap:0,0\n70,lightmap:0,1\n130,lightmap:0,4\n", "log.csv");
  EXPECT_TRUE(hasWarning(log, "log.csv:4: lightmap frames 2-3 never arrive (the log goes on at frame 4)"));
  const ArrivalLog first = parseArrivals("10,sky:0,1\n", "log.csv");
  EXPECT_TRUE(hasWarning(first, "log.csv:1: sky frame 0 never arrives"));
}

TEST(ArrivalLog, AFrameAfterALaterOneIsWarned) {
  // Frame 1 delayed past frame 2: no in-order decoder does that; it is replayed as written.
  const ArrivalLog log =
      parseArrivals("vsync,stream,frame\n10,lightmap:0,0\n300,lightmap:0,1\n130,lightmap:0,2\n", "log.csv");
  EXPECT_TRUE(hasWarning(log, "log.csv:3: lightmap frame 1 arrives at vsync 300, after frame 2 (line 4, vsync 130)"));
  EXPECT_FALSE(hasWarning(log, "never arrive"));  // it does arrive: no gap
}

}  // namespace
}  // namespace vbim::player
