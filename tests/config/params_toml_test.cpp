#include "config/params_toml.hpp"
#include "runtime/param_table.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace vbim {
namespace {

struct Settings {
  std::int64_t seekMs = 100;
  double rate = 1.5;
  bool cav = true;
  std::string spin = "cav";
};

ParamTable table(Settings& s) {
  ParamTable t;
  t.addInt("drive.full_seek_ms", &s.seekMs, 0, 10'000, "ms", "PCSX2 CDVD_internal.h");
  t.addReal("sif.rate", &s.rate, 0.1, 100, "MB/s", "assumption");
  t.addBool("drive.cav", &s.cav, "libcdvd");
  t.addChoice("drive.spin", &s.spin, {"cav", "clv"}, "libcdvd");
  return t;
}

std::string errorOf(const std::string& toml) {
  Settings s;
  try {
    ParamTable ts = table(s);
    config::applyToml(ts, toml, "plat.toml");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(Params, LoadsValues) {
  Settings s;
  ParamTable ts = table(s);
  config::applyToml(ts, "[drive]\nfull_seek_ms = 120\nspin = \"clv\"\ncav = false\n[sif]\nrate = 12\n", "x");
  EXPECT_EQ(s.seekMs, 120);
  EXPECT_EQ(s.spin, "clv");
  EXPECT_FALSE(s.cav);
  EXPECT_DOUBLE_EQ(s.rate, 12.0);
}

TEST(Params, UnknownKeyNamesFileLineAndKey) {
  const std::string e = errorOf("[drive]\nfull_seek_ms = 1\nfull_seek = 2\n");
  EXPECT_NE(e.find("plat.toml:3"), std::string::npos) << e;
  EXPECT_NE(e.find("drive.full_seek"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown key"), std::string::npos) << e;
}

TEST(Params, OutOfRangeAndWrongType) {
  std::string e = errorOf("[drive]\n\nfull_seek_ms = -5\n");
  EXPECT_NE(e.find("plat.toml:3"), std::string::npos) << e;
  EXPECT_NE(e.find("outside the allowed range [0, 10000]"), std::string::npos) << e;
  e = errorOf("[drive]\nfull_seek_ms = 1.5\n");
  EXPECT_NE(e.find("expected an integer"), std::string::npos) << e;
  e = errorOf("[drive]\nspin = \"fast\"\n");
  EXPECT_NE(e.find("not one of cav, clv"), std::string::npos) << e;
  e = errorOf("[drive\n");
  EXPECT_NE(e.find("syntax error"), std::string::npos) << e;
}

TEST(Params, DefaultsRoundTripThroughToml) {
  Settings a;
  a.rate = 2.25;
  std::ostringstream out;
  table(a).writeToml(out);
  Settings b;
  b.seekMs = 1;
  b.rate = 0.5;
  ParamTable tb = table(b);
  config::applyToml(tb, out.str(), "defaults");
  EXPECT_EQ(b.seekMs, 100);
  EXPECT_DOUBLE_EQ(b.rate, 2.25);
}

}  // namespace
}  // namespace vbim
