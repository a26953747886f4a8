// Drive model: sustained rates by radius (CAV) and flat CLV, each seek class with latency drawn from
// the seed, read-ahead, drive retries, end of media, stalls.
#include <gtest/gtest.h>

#include <sstream>

#include "iop/cd_errors.hpp"
#include "tests/iop/iop_fixture.hpp"

namespace vbim::iop::test {
namespace {

struct Step {
  Tick delay;  // idle before issuing
  std::int64_t lsn;
  std::int64_t sectors;
};

struct Done {
  Tick issued;
  Tick finished;
  std::uint32_t error;
  SeekClass seek;
};

Task<void> script(Scheduler& s, Drive& d, std::vector<Step> steps, std::vector<Done>& out) {
  Event ev(s);
  for (const Step& st : steps) {
    co_await s.delay(st.delay);
    auto c = std::make_shared<DriveCommand>();
    c->lsn = st.lsn;
    c->sectors = st.sectors;
    c->notify = &ev;
    d.enqueue(c);
    while (!c->done) co_await ev.wait();
    out.push_back(Done{c->issuedAt, c->finishedAt, c->error, c->seek});
  }
}

std::vector<Done> run(Rig& r, std::vector<Step> steps) {
  r.build(r.disc ? r.disc->sectorCount() : kLayer, false);
  std::vector<Done> out;
  r.s.spawn("script", script(r.s, *r.drive, std::move(steps), out));
  r.s.run();
  return out;
}

// Time for n contiguous sectors from lsn with no buffered data: reads back to back, the last
// sector's DMA after it (the DMA of earlier sectors hides under the next read).
Tick contiguousReadTicks(std::int64_t lsn, std::int64_t n, Tick (*sector)(std::int64_t)) {
  Tick t = 0;
  for (std::int64_t i = 0; i < n; ++i) t += sector(lsn + i);
  return t + kDmaTicks;
}

Tick clvSector(std::int64_t) {
  return kClvSectorTicks;
}

TEST(DriveRate, CavInnerAndOuterRadiusMatchTheModel) {
  for (std::int64_t lsn : {std::int64_t{0}, kLayer - 4000}) {
    Rig r;
    // Prime the head at lsn, then a long contiguous read: no seek, no latency.
    auto done = run(r, {{0, lsn, 16}, {0, lsn + 16, 2000}});
    ASSERT_EQ(done.size(), 2u);
    EXPECT_EQ(done[1].seek, SeekClass::Contiguous);
    const Tick took = done[1].finished - done[1].issued;
    EXPECT_EQ(took, contiguousReadTicks(lsn + 16, 2000, cavSectorTicks));
    // And that is the CAV rate of docs/hardware.md#dvd-drive: 1080 sectors/s at the hub, 2700 at the
    // rim (within the drift of the rate over 2000 sectors).
    const double rate = 2000.0 / toSeconds(took - kDmaTicks);
    if (lsn == 0) {
      EXPECT_NEAR(rate, 1080.0, 1080.0 * 0.001);
    } else {
      EXPECT_NEAR(rate, 2700.0, 2700.0 * 0.002);
    }
  }
}

TEST(DriveRate, ClvIsFlat1080) {
  for (std::int64_t lsn : {std::int64_t{0}, kLayer - 4000}) {
    Rig r;
    r.p.drive.spindle = "clv";
    auto done = run(r, {{0, lsn, 16}, {0, lsn + 16, 1080}});
    ASSERT_EQ(done.size(), 2u);
    EXPECT_EQ(done[1].finished - done[1].issued, contiguousReadTicks(lsn + 16, 1080, clvSector));
  }
}

TEST(DriveSeek, EachClassCostsItsTimePlusSeededLatency) {
  Rig r;
  const std::int64_t base = 100'000;
  // After each read the head sits at lsn + n. Issue without idling (no read-ahead).
  auto done = run(r, {{0, base, 8},
                      {0, base + 8 + 5, 8},                              // forward 5: contiguous, read through
                      {0, base + 21 + 1000, 8},                          // fast
                      {0, base + 1029 - 40, 8},                          // backward: fast
                      {0, base + 997 + 100'000, 8},                      // full
                      {0, base + 997 + 100'008 + 14'763, 8},             // just inside the fast window
                      {0, base + 997 + 100'008 + 14'771 + 14'764, 8}});  // just outside: full
  ASSERT_EQ(done.size(), 7u);
  EXPECT_EQ(done[1].seek, SeekClass::Contiguous);
  EXPECT_EQ(done[2].seek, SeekClass::Fast);
  EXPECT_EQ(done[3].seek, SeekClass::Fast);
  EXPECT_EQ(done[4].seek, SeekClass::Full);
  EXPECT_EQ(done[5].seek, SeekClass::Fast);
  EXPECT_EQ(done[6].seek, SeekClass::Full);

  // Latency draws: the drive's fork of the seed, one draw per seek, uniform in [0, 16 ms).
  Rng lat = Rng(r.seed).fork("drive.latency");
  const Tick rev = fromUs(16'000);
  std::vector<Tick> draws;
  auto draw = [&] { return static_cast<Tick>(lat.below(static_cast<std::uint64_t>(rev))); };
  const std::int64_t lsns[] = {base,           base + 13,      base + 1021,   base + 989,
                               base + 100'997, base + 115'768, base + 130'540};
  const Tick first = fromUs(100'000) + draw();  // the first read: head at 0, a full seek
  EXPECT_EQ(done[0].finished - done[0].issued, first + contiguousReadTicks(lsns[0], 8, cavSectorTicks));
  EXPECT_EQ(done[1].finished - done[1].issued,
            contiguousReadTicks(lsns[1] - 5, 13, cavSectorTicks));  // 5 skipped + 8 read
  const Tick seekCost[] = {0, 0, fromUs(30'000), fromUs(30'000), fromUs(100'000), fromUs(30'000), fromUs(100'000)};
  for (int i = 2; i < 7; ++i) {
    const Tick expected = seekCost[i] + draw() + contiguousReadTicks(lsns[i], 8, cavSectorTicks);
    EXPECT_EQ(done[static_cast<std::size_t>(i)].finished - done[static_cast<std::size_t>(i)].issued, expected)
        << "step " << i;
  }
  EXPECT_EQ(r.drive->stats().seeks[static_cast<int>(SeekClass::Fast)], 3);
  EXPECT_EQ(r.drive->stats().seeks[static_cast<int>(SeekClass::Full)], 3);
}

TEST(DriveSeek, ReadAheadServesTheNextSectorsAfterIdle) {
  Rig r;
  r.p.drive.spindle = "clv";
  // Idle 50 ms after the first read: 16 sectors (2.2 ms of reading) are buffered.
  auto done = run(r, {{0, 5000, 32}, {fromMs(50), 5032, 32}});
  ASSERT_EQ(done.size(), 2u);
  EXPECT_EQ(done[1].seek, SeekClass::Buffered);
  // 16 buffered sectors need only their DMA (16 x 24,576 ticks, chained); the other 16 are read
  // from t = 0 and the reads outpace the DMA from the 4th on, so the last DMA ends 16 reads + 1 DMA in.
  EXPECT_EQ(done[1].finished - done[1].issued, 16 * kClvSectorTicks + kDmaTicks);
  EXPECT_EQ(r.drive->stats().bufferedHits, 16);
}

TEST(DriveSeek, SpinUpFromStopped) {
  Rig r;
  r.p.drive.initially_spinning = false;
  r.p.drive.spindle = "clv";
  auto done = run(r, {{0, 0, 1}});
  // Spin-up (333 ms), then LSN 0 is where the head rests: read it.
  EXPECT_EQ(done[0].seek, SeekClass::Contiguous);
  EXPECT_EQ(done[0].finished - done[0].issued, fromMs(333) + kClvSectorTicks + kDmaTicks);
  EXPECT_EQ(r.drive->stats().spinUps, 1);
}

TEST(DriveErrors, RetriesCostARevolutionEachThenFail) {
  Rig r;
  r.p.drive.spindle = "clv";
  r.p.drive.retry_count = 2;
  r.build(kLayer, false);
  r.drive->addSectorFault(10, 2);  // fails twice, third attempt reads
  r.drive->addSectorFault(50, 3);  // fails all three attempts
  std::vector<Done> out;
  r.s.spawn("script", script(r.s, *r.drive, {{0, 0, 32}, {0, 32, 32}}, out));
  r.s.run();
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].error, 0u);
  EXPECT_EQ(out[0].finished - out[0].issued, 32 * kClvSectorTicks + 2 * fromUs(16'000) + kDmaTicks);
  EXPECT_EQ(out[1].error, kCdErRead);
  // Sectors 32..49 read, then sector 50 read and retried twice, then the error after its DMA wait.
  // Sectors 32..49 read; sector 50 is read and retried twice; the command ends there, with
  // sector 49's DMA long finished.
  EXPECT_EQ(out[1].finished - out[1].issued, 19 * kClvSectorTicks + 2 * fromUs(16'000));
  EXPECT_EQ(r.drive->stats().retries, 4);
}

TEST(DriveErrors, EndOfMediaIs0x32AfterTheLastSector) {
  Rig r;
  r.p.drive.spindle = "clv";
  r.disc = std::make_unique<MemoryDisc>(100);
  auto done = run(r, {{0, 0, 90}, {0, 90, 32}, {0, 100, 1}});
  ASSERT_EQ(done.size(), 3u);
  EXPECT_EQ(done[1].error, kCdErEndOfMedia);
  EXPECT_EQ(done[1].finished - done[1].issued, contiguousReadTicks(90, 10, clvSector));
  EXPECT_EQ(done[2].error, kCdErRead);  // an LSN past the end is refused at issue (P-CDVD)
}

TEST(DriveStall, WorkOverlappingAStallIsPushedBackByTheOverlap) {
  Rig r;
  r.p.drive.spindle = "clv";
  r.build(kLayer, false);
  // The second read (160 sectors, 21.8 ms) starts at T; a 300 ms stall begins 10 ms into it.
  std::vector<Done> out;
  r.s.spawn("script", script(r.s, *r.drive, {{0, 0, 16}, {0, 16, 160}}, out));
  r.s.runUntil(1);  // let the first command start
  const Tick firstEnd = contiguousReadTicks(0, 16, clvSector);
  r.drive->addStall(firstEnd + fromMs(10), firstEnd + fromMs(310));
  r.s.run();
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].finished, firstEnd);
  EXPECT_EQ(out[1].finished - out[1].issued, contiguousReadTicks(16, 160, clvSector) + fromMs(300));
  EXPECT_EQ(r.drive->stats().stalled, fromMs(300));
}

// Stalls given in any order, overlapping or touching, freeze the drive for their union.
TEST(DriveStall, OverlappingAndTouchingStallsMerge) {
  Rig r;
  r.p.drive.spindle = "clv";
  r.build(kLayer, false);
  std::vector<Done> out;
  r.s.spawn("script", script(r.s, *r.drive, {{0, 0, 4000}}, out));  // 3.7 s of reading
  const Tick ms = fromMs(1);
  r.drive->addStall(300 * ms, 400 * ms);
  r.drive->addStall(100 * ms, 150 * ms);
  r.drive->addStall(140 * ms, 200 * ms);  // overlaps the one before it
  r.drive->addStall(200 * ms, 250 * ms);  // touches it
  r.drive->addStall(90 * ms, 500 * ms);   // swallows all of them
  r.drive->addStall(600 * ms, 600 * ms);  // empty: ignored
  r.drive->addStall(700 * ms, 710 * ms);
  r.s.run();
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(r.drive->stats().stalled, 420 * ms);
  EXPECT_EQ(out[0].finished - out[0].issued, contiguousReadTicks(0, 4000, clvSector) + 420 * ms);
}

// A series of stalls pulled as the clock reaches them freezes the drive exactly as the same
// stalls given up front: the drive always knows the next one before it starts work across it.
TEST(DriveStall, StallSeriesEqualsTheSameStallsUpFront) {
  const auto stallsOf = [](int i) { return Drive::StallSpan{fromMs(37 * i + 5), fromMs(37 * i + 5) + 1000 + 77 * i}; };
  Tick finished[2] = {0, 0};
  Tick stalled[2] = {0, 0};
  for (int lazy = 0; lazy < 2; ++lazy) {
    Rig r;
    r.p.drive.spindle = "clv";
    r.build(kLayer, false);
    std::vector<Done> out;
    r.s.spawn("script", script(r.s, *r.drive, {{0, 0, 1000}, {fromMs(30), 5000, 1000}}, out));
    if (lazy) {
      r.drive->addStallSeries([i = 0, &stallsOf]() mutable -> std::optional<Drive::StallSpan> {
        if (i == 60) return std::nullopt;
        return stallsOf(i++);
      });
    } else {
      for (int i = 0; i < 60; ++i) r.drive->addStall(stallsOf(i).begin, stallsOf(i).end);
    }
    r.s.run();
    ASSERT_EQ(out.size(), 2u);
    finished[lazy] = out[1].finished;
    stalled[lazy] = r.drive->stats().stalled;
  }
  EXPECT_EQ(finished[0], finished[1]);
  EXPECT_EQ(stalled[0], stalled[1]);
  EXPECT_GT(stalled[0], 30 * 1000);
}

}  // namespace
}  // namespace vbim::iop::test

namespace vbim::iop::test {
namespace {

// The drive counts its busy time itself, so the busy share in stats.json is the same with or without
// a tracer: equal to the time on the trace's drive track, at any moment, including inside a stall
// that is still going on (the trace clips the stall's span there) and with retries.
TEST(DriveBusy, BusyTimeIsTheTracesDriveTrackWithOrWithoutATracer) {
  Rig traced, bare;
  for (Rig* r : {&traced, &bare}) {
    r->p.drive.spindle = "clv";
    r->traced = r == &traced;
    r->build(kLayer, false);
    r->drive->addSectorFault(40, 2);
    r->drive->addStall(fromMs(5), fromMs(30));
    r->drive->addStall(fromMs(60), fromMs(400));
  }
  std::vector<Done> outTraced, outBare;
  const std::vector<Step> steps{{0, 0, 64}, {fromMs(2), 5000, 32}, {0, 200'000, 16}, {fromMs(1), 100, 64}};
  traced.s.spawn("script", script(traced.s, *traced.drive, steps, outTraced));
  bare.s.spawn("script", script(bare.s, *bare.drive, steps, outBare));
  const Tracer::TrackId driveTrack = 0;  // the first track: the drive is the first thing the rig builds
  for (const Tick at : {fromMs(3), fromMs(20), fromMs(59), fromMs(200), fromMs(450), fromMs(900)}) {
    traced.s.runUntil(at);
    bare.s.runUntil(at);
    EXPECT_EQ(traced.drive->busyTime(at), traced.tracer.busyTime(driveTrack, 0, at)) << toSeconds(at) << " s";
    EXPECT_EQ(bare.drive->busyTime(at), traced.drive->busyTime(at)) << toSeconds(at) << " s";
  }
  EXPECT_EQ(outTraced.size(), steps.size());
  EXPECT_GT(traced.drive->stats().retries, 0);
  EXPECT_GT(traced.drive->busyTime(fromMs(900)), fromMs(340));  // the stalls alone
}

// A read with retries and a stall inside it: its span stops where each begins and goes on after, so
// the drive is busy exactly the sectors, the revolutions and the stall (before, those two counted
// twice: once in their own span and again in the read's), and the trace's drive_busy wire stays at 1
// from the first sector to the last (a nested span used to drop it to 0 at the retry's end).
TEST(DriveBusy, RetriesAndStallsInsideAReadCountOnce) {
  Rig r;
  r.p.drive.spindle = "clv";
  r.p.drive.retry_count = 2;
  r.traced = true;
  r.build(kLayer, false);
  r.drive->addSectorFault(10, 2);             // two retries, then the sector reads
  r.drive->addStall(fromMs(3), fromMs(10));   // during the sectors before it
  r.drive->addStall(fromMs(31), fromMs(33));  // during the retries (sector 10 ends near 31.5 ms)
  std::vector<Done> out;
  r.s.spawn("script", script(r.s, *r.drive, {{0, 0, 32}}, out));
  r.s.run();
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].error, 0u);
  const Tick stalls = fromMs(7) + fromMs(2);
  const Tick busy = 32 * kClvSectorTicks + 2 * fromUs(16'000) + stalls;
  EXPECT_EQ(out[0].finished - out[0].issued, busy + kDmaTicks);
  EXPECT_EQ(r.drive->busyTime(r.s.now()), busy);
  EXPECT_EQ(r.tracer.busyTime(0, 0, r.s.now()), busy);
  // The drive's wire, its value at the end of each instant: 1 from the first sector to the last.
  std::ostringstream vcd;
  r.tracer.writeVcd(vcd);
  const std::string v = vcd.str();
  const std::size_t var = v.find("$var wire 1 ") + 12;
  const std::string wire = v.substr(var, v.find(' ', var) - var);
  std::vector<char> values;  // per instant after $dumpvars
  std::istringstream in(v.substr(v.find("$end\n", v.find("$dumpvars")) + 5));
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] == '#') {
      values.push_back('?');
    } else if (!values.empty() && line.size() == wire.size() + 1 && line.substr(1) == wire) {
      values.back() = line[0];
    }
  }
  std::string shown;
  for (char c : values)
    if (c != '?' && (shown.empty() || shown.back() != c)) shown.push_back(c);
  EXPECT_EQ(shown, "10") << v;
}

}  // namespace
}  // namespace vbim::iop::test
