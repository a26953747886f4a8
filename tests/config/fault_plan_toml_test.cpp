// Fault plans: parsing, clear rejection of bad plans, and their effect on the simulated clock.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "config/fault_plan_toml.hpp"
#include "config/params_toml.hpp"
#include "iop/fault_plan.hpp"
#include "tests/iop/iop_fixture.hpp"

namespace vbim::iop::test {
namespace {

std::string errorOf(const std::string& text, const SectorSource* disc = nullptr) {
  try {
    config::parseFaultPlan(text, "plan.toml", disc);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(FaultPlan, ParsesEveryKind) {
  MemoryDisc disc(1'000'000);
  disc.addPatternFile("/AUDIO/MUSIC.PSS", 500'000, 1000);
  const FaultPlan p = config::parseFaultPlan(R"(
[[fault]]
kind = "stall"
at = "12.5s"
duration = "800ms"

[[fault]]
kind = "read_error"
lba = 123456
attempts = 5

[[fault]]
kind = "seek_away"
at = "3s"
file = '\AUDIO\MUSIC.PSS;1'
sectors = 64

[[fault]]
kind = "contention"
from = "10s"
duration = "5s"
share = 30
period = "50ms"

[[fault]]
kind = "random_stall"
from = "0s"
duration = "60s"
mean_interval = "20s"
stall = "250us"

[[fault]]
kind = "random_error"
from = "1s"
duration = "2s"
per_million = 100
)",
                                             "plan.toml", &disc);
  ASSERT_EQ(p.faults.size(), 6u);
  EXPECT_EQ(p.faults[0].at, fromMs(12'500));
  EXPECT_EQ(p.faults[0].duration, fromMs(800));
  EXPECT_EQ(p.faults[0].line, 2);
  EXPECT_EQ(p.faults[1].lba, 123456);
  EXPECT_EQ(p.faults[1].attempts, 5);
  EXPECT_EQ(p.faults[2].lba, 500'000);
  EXPECT_EQ(p.faults[3].share, 30);
  EXPECT_EQ(p.faults[3].period, fromMs(50));
  EXPECT_EQ(p.faults[4].stallLength, fromUs(250));
  EXPECT_EQ(p.faults[5].attempts, 1);
}

TEST(FaultPlan, ParsesTimesExactly) {
  EXPECT_EQ(parseDuration("1s"), 147'456'000);
  EXPECT_EQ(parseDuration("12.5s"), 12 * 147'456'000 + 73'728'000);
  EXPECT_EQ(parseDuration("8ms"), fromMs(8));
  EXPECT_EQ(parseDuration("0.001s"), fromMs(1));
  EXPECT_EQ(parseDuration("250us"), fromUs(250));
  EXPECT_THROW(parseDuration("800"), std::invalid_argument);
  EXPECT_THROW(parseDuration("-5ms"), std::invalid_argument);
  EXPECT_THROW(parseDuration("5 parsecs"), std::invalid_argument);
  EXPECT_THROW(parseDuration("ms"), std::invalid_argument);
}

TEST(FaultPlan, RejectsBadPlansNamingLineAndField) {
  struct Bad {
    std::string text;
    std::string expect;  // substrings of the message
  };
  const std::vector<Bad> bad = {
      {"[[fault]]\nkind = \"stall\"\nat = \"1s\"\nduration = \"-5ms\"\n",
       "plan.toml:4: fault 'stall', field 'duration'"},
      {"[[fault]]\nkind = \"stall\"\nat = \"soon\"\nduration = \"5ms\"\n",
       "plan.toml:3: fault 'stall', field 'at': 'soon' is not a valid time"},
      {"[[fault]]\nkind = \"stall\"\nat = 12\nduration = \"5ms\"\n", "field 'at': expected a time as a string"},
      {"[[fault]]\nkind = \"stal\"\nat = \"1s\"\n", "plan.toml:2: unknown fault kind 'stal'"},
      {"[[fault]]\nat = \"1s\"\n", "plan.toml:1: fault without a kind"},
      {"[[fault]]\nkind = \"stall\"\nat = \"1s\"\n", "field 'duration': missing"},
      {"[[fault]]\nkind = \"stall\"\nat = \"1s\"\nduration = \"0ms\"\n", "must be longer than zero"},
      {"[[fault]]\nkind = \"stall\"\nat = \"1s\"\nduration = \"5ms\"\nlength = 3\n",
       "plan.toml:5: fault 'stall', field 'length': unknown field"},
      {"[[fault]]\nkind = \"stall\"\nat = \"1s\"\nduration = \"500ms\"\n\n[[fault]]\nkind = \"stall\"\nat = "
       "\"1.2s\"\nduration = \"1s\"\n",
       "plan.toml:6: fault 'stall' starting at 1200000.000 us overlaps the one at line 1"},
      {"[[fault]]\nkind = \"read_error\"\nlba = 5\nattempts = 0\n",
       "field 'attempts': 0 is outside the allowed range [1"},
      {"[[fault]]\nkind = \"read_error\"\nlba = 5\nattempts = 2\n[[fault]]\nkind = \"read_error\"\nlba = 5\nattempts = "
       "1\n",
       "plan.toml:7: fault 'read_error', field 'lba': LBA 5 already has a read_error at line 1"},
      {"[[fault]]\nkind = \"read_error\"\nlba = -3\nattempts = 2\n", "field 'lba': -3 is outside the allowed range"},
      {"[[fault]]\nkind = \"contention\"\nfrom = \"1s\"\nduration = \"2s\"\nshare = 120\n",
       "field 'share': 120 is outside"},
      {"[[fault]]\nkind = \"contention\"\nfrom = \"1s\"\nduration = \"20ms\"\nshare = 20\n",
       "field 'period': is longer than"},
      {"[[fault]]\nkind = \"random_stall\"\nfrom = \"0s\"\nduration = \"2s\"\nmean_interval = \"10ms\"\nstall = "
       "\"20ms\"\n",
       "must be shorter than mean_interval"},
      // Finer than one sector's read (docs/fault-plans.md, "Cost"): the fuzzer's 52 ns period.
      {"[[fault]]\nkind = \"contention\"\nfrom = \"0s\"\nduration = \"60s\"\nshare = 17\nperiod = \".052us\"\n",
       "plan.toml:6: fault 'contention', field 'period': is shorter than 1ms"},
      {"[[fault]]\nkind = \"random_stall\"\nfrom = \"0s\"\nduration = \"2s\"\nmean_interval = \"999us\"\nstall = "
       "\"1us\"\n",
       "plan.toml:5: fault 'random_stall', field 'mean_interval': is shorter than 1ms"},
      {"[[fault]]\nkind = \"seek_away\"\nat = \"1s\"\nfile = \"x.pss\"\nsectors = 5\n", "needs a disc"},
      {"[fault]\nkind = \"stall\"\n", "'fault' must be an array of tables"},
      {"stall = 3\n", "plan.toml:1: unknown key 'stall'"},
      {"[[fault]\nkind = \"stall\"\n", "plan.toml:1: TOML syntax error"},
  };
  for (const Bad& b : bad) {
    const std::string msg = errorOf(b.text);
    EXPECT_NE(msg.find(b.expect), std::string::npos) << "plan:\n" << b.text << "\nmessage: " << msg;
  }
  MemoryDisc disc(1000);
  EXPECT_NE(errorOf("[[fault]]\nkind = \"seek_away\"\nat = \"1s\"\nlba = 990\nsectors = 64\n", &disc)
                .find("field 'sectors': 64 sectors from LBA 990 run past the end of the disc"),
            std::string::npos);
  EXPECT_NE(errorOf("[[fault]]\nkind = \"seek_away\"\nat = \"1s\"\nfile = \"/NOPE.PSS\"\nsectors = 4\n", &disc)
                .find("no file '/NOPE.PSS'"),
            std::string::npos);
  EXPECT_NE(errorOf("[[fault]]\nkind = \"read_error\"\nlba = 1000\nattempts = 1\n", &disc).find("[0, 999]"),
            std::string::npos);
  try {
    config::loadFaultPlan("/nonexistent/plan.toml");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/plan.toml: cannot open"), std::string::npos);
  }
}

// A directory given where a TOML file is expected was read as an empty file: no faults, no
// platform settings, exit 0. Both readers now refuse it, naming the path.
TEST(FaultPlan, ADirectoryIsNotAPlanOrAConfig) {
  const std::string dir = ::testing::TempDir();
  try {
    config::loadFaultPlan(dir);
    FAIL() << "a directory was read as a fault plan";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(dir + ": is a directory; expected a fault plan"), std::string::npos)
        << e.what();
  }
  ParamTable table;
  try {
    config::applyTomlFile(table, dir);
    FAIL() << "a directory was read as a config file";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(dir + ": is a directory; expected a config file"), std::string::npos)
        << e.what();
  }
}

TEST(FaultPlan, EmptyPlanIsNoFaults) {
  EXPECT_TRUE(config::parseFaultPlan("", "empty.toml").faults.empty());
}

Task<void> startRing(StreamRing& ring) {
  (void)co_await ring.start(0);
}

TEST(FaultPlan, SeekAwayMakesTheStreamSeekBack) {
  Rig r;
  r.p.drive.spindle = "clv";
  r.build();
  applyFaults(
      r.s, *r.drive,
      config::parseFaultPlan("[[fault]]\nkind = \"seek_away\"\nat = \"40ms\"\nlba = 1000000\nsectors = 64\n", "p"),
      Rng(1));
  r.s.spawn("start", startRing(*r.ring));
  r.s.runUntil(fromMs(1000));
  const auto& st = r.drive->stats();
  // Away: a full seek there; back: a full seek home. The ring's read was refused once (busy).
  EXPECT_EQ(st.seeks[static_cast<int>(SeekClass::Full)], 2);
  EXPECT_GE(r.ring->stats().issueFailures, 1);
  EXPECT_EQ(r.ring->visibleBanks(), 4);
}

TEST(FaultPlan, ContentionTakesItsShareOfDriveTime) {
  Rig r;
  r.p.drive.spindle = "clv";
  r.build(kLayer, false);
  applyFaults(
      r.s, *r.drive,
      config::parseFaultPlan("[[fault]]\nkind = \"contention\"\nfrom = \"0s\"\nduration = \"1s\"\nshare = 25\n", "p"),
      Rng(1));
  r.s.run();
  // Ten 25 ms slices, each at a seeded moment of its 100 ms period and wholly inside it.
  EXPECT_GE(r.s.now(), fromMs(900) + fromMs(25));
  EXPECT_LE(r.s.now(), fromMs(1000));
  EXPECT_EQ(r.drive->stats().commands, 10);
  for (int k = 0; k < 10; ++k)
    EXPECT_EQ(r.tracer.busyTime(0, fromMs(100 * k), fromMs(100 * (k + 1))), fromMs(25)) << "period " << k;
}

// A slice at the same moment of every period locked onto the stream's 200 ms re-try after a
// refused sceCdRE: with a 200 ms period from 0 s, every re-try met the drive busy and no bank was
// ever read. Drawn per period, the slices leave the stream gaps to start in.
TEST(FaultPlan, ContentionAtTheRetryPeriodDoesNotLockTheStreamOut) {
  for (const std::uint64_t seed : {1, 2, 3, 4, 5}) {
    Rig r;
    r.p.drive.spindle = "clv";
    r.build();
    applyFaults(r.s, *r.drive,
                config::parseFaultPlan("[[fault]]\nkind = \"contention\"\nfrom = \"0s\"\nduration = \"60s\"\n"
                                       "share = 15\nperiod = \"200ms\"\nlba = 900000\n",
                                       "p"),
                Rng(seed).fork("faults"));
    r.s.spawn("start", startRing(*r.ring));
    r.s.runUntil(fromMs(10'000));
    EXPECT_EQ(r.ring->visibleBanks(), 4) << "seed " << seed;  // the ring filled
  }
}

TEST(FaultPlan, RandomStallsAreSeededAndPushTheReadBack) {
  auto finish = [](std::uint64_t seed, Tick& stalled) {
    Rig r;
    r.p.drive.spindle = "clv";
    r.build(kLayer, false);
    applyFaults(r.s, *r.drive,
                config::parseFaultPlan("[[fault]]\nkind = \"random_stall\"\nfrom = \"0s\"\nduration = \"2s\"\n"
                                       "mean_interval = \"100ms\"\nstall = \"10ms\"\n",
                                       "p"),
                Rng(seed));
    auto c = std::make_shared<DriveCommand>();
    c->lsn = 0;
    c->sectors = 4000;  // 3.7 s of reading, across the whole stall window
    r.drive->enqueue(c);
    r.s.run();
    stalled = r.drive->stats().stalled;
    return c->finishedAt;
  };
  Tick s1 = 0, s2 = 0, s3 = 0;
  const Tick a = finish(3, s1);
  const Tick b = finish(3, s2);
  const Tick c = finish(4, s3);
  EXPECT_EQ(a, b);
  EXPECT_EQ(s1, s2);
  EXPECT_GT(s1, fromMs(50));  // about 2 s / 110 ms ~ 18 stalls of 10 ms
  EXPECT_EQ(a, 4000 * kClvSectorTicks + kDmaTicks + s1);
  EXPECT_NE(s1, s3);
  (void)c;
}

}  // namespace
}  // namespace vbim::iop::test

namespace vbim::iop::test {
namespace {

// The examples in docs/fault-plans.md parse (against a disc holding the files they name).
TEST(FaultPlan, DocumentedExamplesParse) {
  const char* root = std::getenv("VBIM_SOURCE_DIR");
  ASSERT_NE(root, nullptr);
  std::ifstream in(std::string(root) + "/docs/fault-plans.md");
  ASSERT_TRUE(in);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string doc = ss.str();
  MemoryDisc disc(kLayer);
  disc.addPatternFile("/DATA/LEVEL2.BIN", 300'000, 4096);
  disc.addPatternFile("/AUDIO/MUSIC.PSS", 900'000, 40'000);
  int blocks = 0;
  for (std::size_t at = doc.find("```toml\n"); at != std::string::npos; at = doc.find("```toml\n", at + 1)) {
    const std::size_t begin = at + 8;
    const std::size_t end = doc.find("```", begin);
    ASSERT_NE(end, std::string::npos);
    EXPECT_NO_THROW(config::parseFaultPlan(doc.substr(begin, end - begin), "fault-plans.md example", &disc))
        << doc.substr(begin, end - begin);
    ++blocks;
  }
  EXPECT_EQ(blocks, 4);
}

// Times the 64-bit tick counter cannot hold were wrapped (a 10^11 s `at` was accepted) or, with
// 21 digits, overflowed the parser's numerator; now they are refused with the limit.
TEST(FaultPlan, TimesBeyondTheTickCounterAreRefused) {
  const std::string e = errorOf("[[fault]]\nkind = \"stall\"\nat = \"99999999999s\"\nduration = \"1s\"\n");
  EXPECT_NE(e.find("plan.toml:3: fault 'stall', field 'at': '99999999999s' is not a valid time: longer than the "
                   "simulated clock can count (at most 10000000000s)"),
            std::string::npos)
      << e;
  EXPECT_THROW(parseDuration("999999999999.999999999s"), std::invalid_argument);
  EXPECT_THROW(parseDuration("125099989669s"), std::invalid_argument);
  EXPECT_EQ(parseDuration("10000000000s"), kMaxTime);
  EXPECT_THROW(parseDuration("10000000000.00000001s"), std::invalid_argument);  // one tick more
  EXPECT_EQ(parseDuration("0.000000001s"), 0);                                  // rounds to the nearest tick
  // The longest contention period's slice is computed without overflow.
  const FaultPlan p = config::parseFaultPlan(
      "[[fault]]\nkind = \"contention\"\nfrom = \"0s\"\nduration = \"10000000000s\"\nshare = 99\n"
      "period = \"10000000000s\"\n",
      "p");
  EXPECT_EQ(contentionSlice(p.faults.at(0)), kMaxTime / 100 * 99);
}

// Dense faults over a window far longer than the run: generated as the clock reaches them, so
// arming costs nothing and a short run only pays for its own faults. Expanded up front this plan
// was ~10^9 contention commands and ~5 x 10^8 stalls (bad_alloc, or hours of re-sorting).
TEST(FaultPlan, DenseFaultsOverAHugeWindowCostOnlyWhatIsPlayed) {
  Rig r;
  r.p.drive.spindle = "clv";
  r.build(kLayer, false);
  applyFaults(r.s, *r.drive,
              config::parseFaultPlan("[[fault]]\nkind = \"random_stall\"\nfrom = \"0s\"\nduration = \"1000000s\"\n"
                                     "mean_interval = \"1ms\"\nstall = \"100us\"\n\n"
                                     "[[fault]]\nkind = \"contention\"\nfrom = \"0s\"\nduration = \"1000000s\"\n"
                                     "share = 50\nperiod = \"1ms\"\n",
                                     "p"),
              Rng(1));
  auto c = std::make_shared<DriveCommand>();
  c->lsn = 0;
  c->sectors = 400;
  r.drive->enqueue(c);
  r.s.runUntil(fromMs(2000));
  EXPECT_TRUE(c->done);
  // About one stall per 1.1 ms while the drive works, and one contention command per period.
  EXPECT_GT(r.drive->stats().stalled, fromMs(20));
  EXPECT_GE(r.drive->stats().commands, 1900);
}

}  // namespace
}  // namespace vbim::iop::test
