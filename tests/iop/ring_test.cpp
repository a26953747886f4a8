// The sceCdSt ring: filling, the full-ring idle and re-poll, the underrun the arithmetic predicts
// under a stall, run-up retries, timeouts, stat/seek/pause/stop, data integrity, determinism.
#include <gtest/gtest.h>

#include <sstream>

#include "config/fault_plan_toml.hpp"
#include "iop/cd_errors.hpp"
#include "iop/fault_plan.hpp"
#include "tests/iop/iop_fixture.hpp"

namespace vbim::iop::test {
namespace {

struct Call {
  Tick at;
  std::uint32_t result;
  bool dataOk;
};

Task<void> starter(StreamRing& ring, std::int64_t lbn) {
  (void)co_await ring.start(lbn);
}

// Reads n sectors every `period` from `first` on, `calls` times, checking the LBA pattern against
// the sectors it expects next (from `lbn`).
Task<void> consumer(Scheduler& s, StreamRing& ring, Tick first, Tick period, int calls, std::uint32_t n,
                    std::int64_t lbn, std::vector<Call>& out) {
  std::vector<std::uint8_t> buf(n * kSectorBytes);
  std::int64_t expect = lbn;
  for (int i = 0; i < calls; ++i) {
    co_await s.until(first + period * i);
    const Tick at = s.now();
    const std::uint32_t r = co_await ring.read(n, buf);
    bool ok = true;
    for (std::uint32_t k = 0; k < stCount(r); ++k)
      ok = ok && sectorHasPattern(buf.data() + k * kSectorBytes, expect + k);
    expect += stCount(r);
    out.push_back(Call{at, r, ok});
  }
}

Tick bankTicks(const Rig& r) {
  return r.ring->bankSectors() * kClvSectorTicks + kDmaTicks;
}

TEST(StreamRing, FillsWholeBanksThenIdlesAndRePollsEvery8ms) {
  Rig r;
  r.p.drive.spindle = "clv";
  r.build();
  r.s.spawn("start", starter(*r.ring, 0));
  r.s.runUntil(fromMs(1000));
  // Five reads (4 visible banks + 1 held back), one after another, contiguous: no seeks.
  ASSERT_EQ(r.ring->readLog().size(), 5u);
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(r.ring->readLog()[k].first, static_cast<Tick>(k) * bankTicks(r));
    EXPECT_EQ(r.ring->readLog()[k].second, static_cast<std::int64_t>(k) * 32);
  }
  EXPECT_EQ(r.ring->visibleBanks(), 4);  // bankmax - 1
  EXPECT_EQ(r.ring->stat(), 128u);
  EXPECT_FALSE(r.drive->busy());
  const Tick fullAt = 5 * bankTicks(r);
  EXPECT_EQ(r.ring->stats().fullPolls, 1 + (fromMs(1000) - fullAt) / fromMs(8));

  // The reader takes a bank at 1 s: at the next 8 ms re-poll the held bank shows and the drive
  // resumes at LSN 160 from its read-ahead buffer.
  std::vector<Call> calls;
  r.s.spawn("ee", consumer(r.s, *r.ring, fromMs(1000), fromMs(1), 1, 32, 0, calls));
  r.s.runUntil(fromMs(1100));
  ASSERT_EQ(calls.size(), 1u);
  EXPECT_EQ(stCount(calls[0].result), 32u);
  EXPECT_TRUE(calls[0].dataOk);
  ASSERT_GE(r.ring->readLog().size(), 6u);
  const Tick resumedAt = r.ring->readLog()[5].first;
  EXPECT_EQ(r.ring->readLog()[5].second, 160);
  EXPECT_GT(resumedAt, fromMs(1000));
  EXPECT_LE(resumedAt, fromMs(1008) + r.sif->transferTicks(32 * kSectorBytes));
  EXPECT_EQ((resumedAt - fullAt) % fromMs(8), 0);
  EXPECT_EQ(r.drive->stats().seeks[static_cast<int>(SeekClass::Buffered)], 1);
  EXPECT_EQ(r.ring->visibleBanks(), 4);
}

// With a ring of K banks, full and idle when a stall of D begins, a reader taking one bank every
// P sees its first underrun at the first call after the ring drains. Arithmetic:
//   calls at t_j = Ts + 10 ms + j P. The ring holds K banks (K - 1 visible + 1 held).
//   The refill is issued during the stall and lands at R = Ts + D + 16 x sector + DMA
//   (16 sectors come from the read-ahead buffer, 16 are read).
//   The reader finishes bank K-1 at t_{K-1} + SIF(bank); if R is later, it stays on the empty
//   bank and call K returns 0 (sceCdSt's reader only steps on when the next bank is ready).
// So the first underrun is at t_K exactly when D > D* = t_{K-1} + SIF - Ts - 16 x sector - DMA.
TEST(StreamRing, StallOfDWithKBanksUnderrunsExactlyWhenTheRingDrains) {
  for (std::int64_t K : {3, 5, 8}) {
    for (int side : {-1, +1}) {
      Rig r;
      r.p.drive.spindle = "clv";
      r.p.ring.bankmax = K;
      r.p.ring.bufmax_sectors = K * 32;
      r.build();
      const Tick Ts = fromMs(1000);
      const Tick P = fromMs(50);
      const Tick t0 = Ts + fromMs(10);
      const Tick sif = r.sif->transferTicks(32 * kSectorBytes);
      const Tick refill = 16 * kClvSectorTicks + kDmaTicks;
      const Tick dStar = t0 + (K - 1) * P + sif - Ts - refill;
      const Tick D = dStar + side;
      r.drive->addStall(Ts, Ts + D);
      r.s.spawn("start", starter(*r.ring, 0));
      std::vector<Call> calls;
      const int n = static_cast<int>(2 * K + 4);
      r.s.spawn("ee", consumer(r.s, *r.ring, t0, P, n, 32, 0, calls));
      r.s.runUntil(t0 + P * n + fromMs(1));
      ASSERT_EQ(calls.size(), static_cast<std::size_t>(n));
      for (const Call& c : calls) EXPECT_TRUE(c.dataOk);
      if (side > 0) {
        EXPECT_EQ(r.ring->stats().firstUnderrunAt, t0 + K * P) << "K=" << K;
        EXPECT_EQ(stCount(calls[static_cast<std::size_t>(K)].result), 0u);
        for (std::int64_t j = 0; j < K; ++j) EXPECT_EQ(stCount(calls[static_cast<std::size_t>(j)].result), 32u);
      } else {
        EXPECT_EQ(r.ring->stats().underruns, 0) << "K=" << K << " D*-1 must just make it";
      }
    }
  }
}

TEST(StreamRing, ReadErrorRetriesRunUpFrom32Then16Then0AndSurfaceTheError) {
  struct Case {
    std::int64_t lba;
    std::int64_t attempts;
    std::vector<std::int64_t> log;
  };
  const std::vector<Case> cases = {
      {40, 3, {0, 32, 0, 16, 32, 64, 96}},     // one failure: -32, -16, 0
      {40, 6, {0, 32, 0, 16, 0, 16, 32, 64}},  // fails again at -16: the run-up restarts
      {8, 3, {0, 32, 16, 0, 32, 64}},          // target below 32: the run-up goes after it
  };
  for (const Case& c : cases) {
    Rig r;
    r.p.drive.spindle = "clv";
    r.p.drive.retry_count = 2;  // a command gives up after 3 failing attempts of a sector
    r.build();
    r.drive->addSectorFault(c.lba, c.attempts);
    r.s.spawn("start", starter(*r.ring, 0));
    std::vector<Call> calls;
    r.s.spawn("ee", consumer(r.s, *r.ring, fromMs(2000), fromMs(1), 3, 32, 0, calls));
    r.s.runUntil(fromMs(2100));
    ASSERT_GE(r.ring->readLog().size(), c.log.size());
    for (std::size_t i = 0; i < c.log.size(); ++i) EXPECT_EQ(r.ring->readLog()[i].second, c.log[i]) << "entry " << i;
    ASSERT_EQ(calls.size(), 3u);
    EXPECT_EQ(stError(calls[0].result), kCdErRead);  // reported once, on the next read
    EXPECT_EQ(stError(calls[1].result), 0u);
    for (const Call& k : calls) {
      EXPECT_EQ(stCount(k.result), 32u);
      EXPECT_TRUE(k.dataOk);
    }
  }
}

TEST(StreamRing, FirstReadTimesOutAfter15sThenRetriesWhenTheDriveFrees) {
  Rig r;
  r.p.drive.spindle = "clv";
  r.build();
  r.drive->addStall(fromMs(1), fromMs(20'000));
  r.s.spawn("start", starter(*r.ring, 0));
  std::vector<Call> calls;
  r.s.spawn("ee", consumer(r.s, *r.ring, fromMs(21'000), fromMs(1), 1, 32, 0, calls));
  r.s.runUntil(fromMs(22'000));
  EXPECT_EQ(r.ring->stats().timeouts, 1);
  // The break lands at 15 s; the retry finds the drive busy (frozen) until 20 s: one failure at
  // 15 s and every 200 ms after, the last at 20.0 s.
  EXPECT_EQ(r.ring->stats().issueFailures, 26);
  ASSERT_GE(r.ring->readLog().size(), 4u);
  EXPECT_EQ(r.ring->readLog()[1].first, fromMs(15'000) + 26 * fromMs(200));
  EXPECT_EQ(r.ring->readLog()[1].second, 32);  // run-up after LBN 0
  EXPECT_EQ(r.ring->readLog()[2].second, 16);
  EXPECT_EQ(r.ring->readLog()[3].second, 0);
  ASSERT_EQ(calls.size(), 1u);
  EXPECT_EQ(stError(calls[0].result), kCdErAbort);
  EXPECT_TRUE(calls[0].dataOk);
}

Task<void> statSeekScript(Scheduler& s, StreamRing& ring, std::vector<std::uint32_t>& out) {
  std::vector<std::uint8_t> buf(64 * kSectorBytes);
  co_await s.until(fromMs(500));
  out.push_back(ring.stat());                  // 0: full ring = 4 banks
  out.push_back(co_await ring.read(10, buf));  // 1
  out.push_back(ring.stat());                  // 2: still 4 banks (bank granularity)
  out.push_back(co_await ring.read(22, buf));  // 3: bank 0 done
  out.push_back(ring.stat());                  // 4: 3 banks
  co_await s.delay(fromMs(9));
  out.push_back(ring.stat());                         // 5: the held bank is visible again
  out.push_back(ring.seekDeferred(100'000) ? 1 : 0);  // 6
  out.push_back(co_await ring.read(32, buf));         // 7: repositioning -> 0
  out.push_back(ring.stat());                         // 8: 0
  co_await s.delay(fromMs(400));
  out.push_back(co_await ring.read(32, buf));                    // 9: data from 100000
  out.push_back(sectorHasPattern(buf.data(), 100'000) ? 1 : 0);  // 10
  out.push_back((co_await ring.pause()) ? 1 : 0);                // 11
  co_await s.delay(fromMs(400));
  std::uint32_t got = 0;
  for (int i = 0; i < 10; ++i) got += stCount(co_await ring.read(32, buf));
  out.push_back(got);                          // 12: what was buffered before the pause
  out.push_back(co_await ring.read(32, buf));  // 13: paused and empty -> 273 << 16
  out.push_back(ring.resume() ? 1 : 0);        // 14
  co_await s.delay(fromMs(200));
  // 15: flowing again. The reader sat on the bank it drained; the first call only steps it on to
  // the refilled bank and returns 0 (SDK-ST), the second reads.
  const std::uint32_t step = stCount(co_await ring.read(32, buf));
  out.push_back(step + stCount(co_await ring.read(32, buf)));
  out.push_back((co_await ring.stop()) ? 1 : 0);         // 16
  out.push_back(co_await ring.read(32, buf));            // 17: stopped -> 273 << 16
  out.push_back((co_await ring.seek(200'000)) ? 1 : 0);  // 18: immediate seek restarts
  co_await s.delay(fromMs(400));
  out.push_back(co_await ring.read(32, buf));                    // 19
  out.push_back(sectorHasPattern(buf.data(), 200'000) ? 1 : 0);  // 20
}

TEST(StreamRing, StatSeekPauseResumeStop) {
  Rig r;
  r.p.drive.spindle = "clv";
  r.build();
  r.s.spawn("start", starter(*r.ring, 0));
  std::vector<std::uint32_t> out;
  r.s.spawn("ee", statSeekScript(r.s, *r.ring, out));
  r.s.runUntil(fromMs(5000));
  ASSERT_EQ(out.size(), 21u);
  EXPECT_EQ(out[0], 128u);
  EXPECT_EQ(out[1], 10u);
  EXPECT_EQ(out[2], 128u);
  EXPECT_EQ(out[3], 22u);
  EXPECT_EQ(out[4], 96u);
  EXPECT_EQ(out[5], 128u);
  EXPECT_EQ(out[6], 1u);
  EXPECT_EQ(out[7], 0u);
  EXPECT_EQ(out[8], 0u);
  EXPECT_EQ(out[9], 32u);
  EXPECT_EQ(out[10], 1u);
  EXPECT_EQ(out[11], 1u);
  EXPECT_GT(out[12], 0u);
  EXPECT_EQ(out[13], static_cast<std::uint32_t>(kCdErStreamIdle) << 16);
  EXPECT_EQ(out[14], 1u);
  EXPECT_EQ(out[15], 32u);
  EXPECT_EQ(out[16], 1u);
  EXPECT_EQ(out[17], static_cast<std::uint32_t>(kCdErStreamIdle) << 16);
  EXPECT_EQ(out[18], 1u);
  EXPECT_EQ(out[19], 32u);
  EXPECT_EQ(out[20], 1u);
}

Task<void> blockingReader(StreamRing& ring, std::uint32_t total, std::uint32_t& got, std::uint32_t& err, bool& ok) {
  std::vector<std::uint8_t> buf(total * kSectorBytes);
  got = co_await ring.readBlocking(total, buf, err);
  ok = true;
  for (std::uint32_t k = 0; k < got; ++k) ok = ok && sectorHasPattern(buf.data() + k * kSectorBytes, 1000 + k);
}

TEST(StreamRing, BlockingReadWaitsForBanksAndGetsEverySectorInOrder) {
  Rig r;
  r.build();
  r.s.spawn("start", starter(*r.ring, 1000));
  std::uint32_t got = 0, err = 0;
  bool ok = false;
  r.s.spawn("ee", blockingReader(*r.ring, 1000, got, err, ok));
  r.s.runUntil(fromMs(5000));
  EXPECT_EQ(got, 1000u);
  EXPECT_EQ(err, 0u);
  EXPECT_TRUE(ok);
}

TEST(StreamRing, ReadingPastTheDiscEndSurfacesEndOfMedia) {
  Rig r;
  r.p.drive.spindle = "clv";
  r.disc = std::make_unique<MemoryDisc>(200);
  r.disc->addPatternFile("/S.PSS", 0, 200);
  r.build(200);
  r.s.spawn("start", starter(*r.ring, 100));
  std::vector<Call> calls;
  r.s.spawn("ee", consumer(r.s, *r.ring, fromMs(1000), fromMs(100), 6, 32, 100, calls));
  r.s.runUntil(fromMs(2000));
  std::uint32_t sectors = 0, eom = 0;
  for (const Call& c : calls) {
    sectors += stCount(c.result);
    if (stError(c.result) == kCdErEndOfMedia) ++eom;
  }
  EXPECT_EQ(sectors, 96u);  // three whole banks fit before LSN 200
  EXPECT_GE(eom, 1u);
}

std::string scenarioTrace(std::uint64_t seed) {
  Rig r;
  r.seed = seed;
  r.build();
  const FaultPlan plan = config::parseFaultPlan(R"(
[[fault]]
kind = "random_stall"
from = "0.5s"
duration = "3s"
mean_interval = "400ms"
stall = "60ms"
[[fault]]
kind = "random_error"
from = "0s"
duration = "4s"
per_million = 2000
attempts = 300
[[fault]]
kind = "seek_away"
at = "1.2s"
lba = 900000
sectors = 64
[[fault]]
kind = "contention"
from = "2s"
duration = "1s"
share = 30
lba = 1500000
)",
                                                "<scenario>", r.disc.get());
  applyFaults(r.s, *r.drive, plan, Rng(seed).fork("faults"));
  r.s.spawn("start", starter(*r.ring, 50'000));
  std::vector<Call> calls;
  r.s.spawn("ee", consumer(r.s, *r.ring, fromMs(300), fromMs(20), 200, 16, 50'000, calls));
  r.s.runUntil(fromMs(4300));
  std::ostringstream json;
  r.tracer.writeChromeJson(json);
  for (const Call& c : calls) json << c.at << ':' << c.result << (c.dataOk ? " ok" : " BAD") << '\n';
  return json.str();
}

TEST(StreamRing, IdenticalTracesAcrossRepeatedRuns) {
  const std::string a = scenarioTrace(7);
  const std::string b = scenarioTrace(7);
  const std::string c = scenarioTrace(8);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);  // the seed matters (latency draws, random faults)
  EXPECT_EQ(a.find(" BAD"), std::string::npos) << "every sector delivered must be the right one";
  EXPECT_GT(a.size(), 1000u);
}

}  // namespace
}  // namespace vbim::iop::test

namespace vbim::iop::test {
namespace {

TEST(StreamRing, RejectsASizeThatMakesNoBank) {
  Rig r;
  r.p.ring.bufmax_sectors = 3;
  r.p.ring.bankmax = 5;
  EXPECT_THROW(r.build(), ConfigError);
}

}  // namespace
}  // namespace vbim::iop::test

namespace vbim::iop::test {
namespace {

// The EE's polls while the drive spins up are counted apart from real underruns: startupPolls is
// exactly the short reads before the first one that returned data, and the rest are playback.
TEST(StreamRing, PollsDuringSpinUpAreStartupPollsNotPlaybackUnderruns) {
  Rig r;
  r.p.drive.spindle = "clv";
  r.p.drive.initially_spinning = false;  // the first read pays the 333 ms spin-up
  r.build();
  r.s.spawn("start", starter(*r.ring, 0));
  std::vector<Call> calls;
  r.s.spawn("ee", consumer(r.s, *r.ring, fromMs(1), fromMs(1), 900, 16, 0, calls));
  r.s.runUntil(fromMs(1000));
  std::int64_t before = 0;
  for (const Call& c : calls) {
    if (stCount(c.result) > 0) break;
    ++before;
  }
  EXPECT_GT(before, 300);  // 333 ms of spin-up, polled every 1 ms
  EXPECT_EQ(r.ring->stats().startupPolls, before);
  EXPECT_GT(r.ring->stats().playbackUnderruns(), 0);  // 16 sectors a ms outruns the 1.6x drive
  EXPECT_EQ(r.ring->stats().underruns, r.ring->stats().startupPolls + r.ring->stats().playbackUnderruns());
}

Task<void> seeker(Scheduler& s, StreamRing& ring, Tick at, std::int64_t lbn, Tick& seekedAt) {
  co_await s.until(at);
  (void)co_await ring.seek(lbn);
  seekedAt = s.now();  // the old banks are gone from here on
}

// A loop wrap or branch seeks the ring; the EE's polls until the first bank from the new position
// is visible are seekPolls, not playback underruns: with a reader slower than the drive, a run
// with one seek has no playback underrun at all.
TEST(StreamRing, PollsAfterASeekAreSeekPollsNotPlaybackUnderruns) {
  Rig r;
  r.build();
  r.s.spawn("start", starter(*r.ring, 0));
  std::vector<Call> calls;
  // 400 sectors/s: once a bank is in, the drive (over 1,000 sectors/s) stays ahead of the reader.
  r.s.spawn("ee", consumer(r.s, *r.ring, fromMs(1), fromMs(40), 100, 16, 0, calls));
  Tick seekedAt = -1;
  r.s.spawn("seek", seeker(r.s, *r.ring, fromMs(1'000), 200'000, seekedAt));
  r.s.runUntil(fromMs(4'100));
  std::int64_t polls = 0;
  bool dataAfterSeek = false;
  for (const Call& c : calls) {
    if (c.at < seekedAt) continue;
    if (stCount(c.result) > 0) {
      dataAfterSeek = true;
      break;
    }
    ++polls;
  }
  ASSERT_TRUE(dataAfterSeek);
  EXPECT_GT(polls, 1);  // a seek of 200,000 sectors takes longer than one 40 ms poll period
  EXPECT_EQ(r.ring->stats().seekPolls, polls);
  EXPECT_EQ(r.ring->stats().playbackUnderruns(), 0);
  EXPECT_EQ(r.ring->stats().underruns, r.ring->stats().startupPolls + polls);
}

}  // namespace
}  // namespace vbim::iop::test
