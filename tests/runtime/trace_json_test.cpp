// trace.json is valid JSON with the events recorded: read back with the JSON library the tools
// around the model use (the model's own tests, trace_test.cpp, need no third-party header).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "runtime/trace.hpp"
#include "tests/runtime/trace_sample.hpp"

namespace vbim {
namespace {

using testing::sampleTrace;

TEST(Trace, ChromeJsonParsesAndHasTheEvents) {
  std::ostringstream s;
  sampleTrace().writeChromeJson(s);
  const auto j = nlohmann::json::parse(s.str());
  const auto& ev = j["traceEvents"];
  int spans = 0, counters = 0, instants = 0;
  for (const auto& e : ev) {
    if (e["ph"] == "X") ++spans;
    if (e["ph"] == "C") ++counters;
    if (e["ph"] == "i") ++instants;
  }
  EXPECT_EQ(spans, 2);
  EXPECT_EQ(counters, 2);
  EXPECT_EQ(instants, 1);
  EXPECT_NE(s.str().find(R"("ts":0.000,"dur":2000.000)"), std::string::npos);
}

}  // namespace
}  // namespace vbim
