// Stalls, catch-up policies and branching, measured against a stall-free reference presenter in
// the same scheduler.
#include <gtest/gtest.h>

#include "presenter_fixture.hpp"

namespace vbim::gs {
namespace {

using namespace test;

constexpr Tick kStallAt = fromMs(1000);
constexpr Tick kStallFor = fromMs(500);
constexpr Tick kEnd = fromMs(4000);

SourceScript stalled() {
  SourceScript s;
  s.lead = fromMs(20);
  s.decodeTime = fromMs(2);
  s.stalls = {{kStallAt, kStallFor}};
  return s;
}

GsParams withPolicy(const std::string& policy) {
  GsParams p;
  p.catchup = policy;
  return p;
}

// The first vsync from which the run blends toward the same frames as the reference for good.
std::size_t caughtUpAt(const Rig& rig) {
  const auto& a = rig.run.history();
  const auto& b = rig.ref.history();
  std::size_t c = a.size();
  while (c > 0 && a[c - 1].targetSeq == b[c - 1].targetSeq && a[c - 1].variant == b[c - 1].variant) --c;
  return c;
}

// Every vsync that blends (not a copy) moves each texel by at most one blend step toward its target.
void expectSmooth(const Rig& rig, const ScriptedFrameSource::ImageFn& img, std::int64_t frames) {
  const auto& h = rig.run.history();
  for (std::size_t n = 1; n < h.size(); ++n) {
    if (h[n].snapped || h[n].targetSeq < 0) continue;
    const int distance = maxDiff(img(h[n].variant, h[n].targetSeq % frames), rig.before[n]);
    ASSERT_LE(h[n].pop, maxStep(distance, h[n].fix)) << "vsync " << n;
  }
}

TEST(CatchUp, BlendThroughReturnsToTheReferenceWithinThePredictedVsyncs) {
  const GsParams p;  // blend-through, FIX 64
  Rig rig({stream("clear")}, wave, stalled(), p, p);
  rig.runFor(kEnd);
  const auto& lag = rig.lag();
  const auto& h = rig.run.history();
  ASSERT_EQ(lag.size(), 240u);

  // Before the stall the run is the reference.
  const std::int64_t stallVsync = rig.run.clock().countAt(kStallAt);
  for (std::int64_t n = 0; n <= stallVsync; ++n) ASSERT_EQ(lag[n].maxDiff, 0) << n;

  // Where the arithmetic says catch-up happens: the first vsync whose due frame is ready by then.
  ScriptedFrameSource probe({stream("clear")}, wave, stalled());
  auto dueReady = [&](std::int64_t n) {
    const Tick t = rig.run.clock().time(n);
    return probe.readyTime(dueSeq(stream("clear"), 0, t)) <= t;
  };
  std::int64_t predicted = stallVsync;
  while (dueReady(predicted)) ++predicted;  // the first vsync whose due frame is missing
  EXPECT_TRUE(h[predicted].behind);
  while (!dueReady(predicted)) ++predicted;  // the first one whose due frame has arrived
  const std::size_t c = caughtUpAt(rig);
  EXPECT_EQ(static_cast<std::int64_t>(c), predicted);
  EXPECT_GT(h[c - 1].targetSeq, 0);
  EXPECT_TRUE(h[c - 1].behind || h[c - 1].catchUp);

  // The stall was visible: the run fell behind by more than the floor's band.
  const int band = stallBand(p.fix);
  EXPECT_GT(lag[c - 1].maxDiff, band);

  // From the catch-up vsync on, both blend toward the same frames with the same FIX, so the
  // distance d between them shrinks at least as g(d) = d - floor(d * FIX / 128) each vsync, down
  // to the band where floor stops it (1 level for FIX 64).
  int d = lag[c - 1].maxDiff;
  std::size_t predictedVsyncs = 0;
  while (d > band) {
    d = contract(d, p.fix);
    ++predictedVsyncs;
  }
  for (std::size_t n = c; n < lag.size(); ++n) {
    ASSERT_LE(lag[n].maxDiff, contract(lag[n - 1].maxDiff, p.fix)) << "vsync " << n;
  }
  ASSERT_LT(c - 1 + predictedVsyncs, lag.size());
  EXPECT_LE(lag[c - 1 + predictedVsyncs].maxDiff, band)
      << "after " << predictedVsyncs << " vsyncs from a lag of " << lag[c - 1].maxDiff;
  // Whatever the lag at catch-up (at most 255), 8 vsyncs suffice at FIX 64: 255 128 64 32 16 8 4 2 1.
  EXPECT_LE(predictedVsyncs, 8u);
  for (std::size_t n = c - 1 + predictedVsyncs; n < lag.size(); ++n) ASSERT_LE(lag[n].maxDiff, band) << n;

  const PresenterCounters& k = rig.run.counters();
  EXPECT_GT(k.framesLate, 0);
  EXPECT_EQ(k.framesCaughtUp, k.framesLate);  // blend-through blends toward every late frame it shows
  EXPECT_GT(k.catchUpVsyncs, 0);
  EXPECT_GT(k.behindVsyncs, 25);  // 500 ms of missing frames is ~30 vsyncs
  EXPECT_GT(k.framesDropped, 0);  // the catch-up burst skips frames nobody blended toward
  EXPECT_EQ(k.snaps, 1);
  expectSmooth(rig, wave, 300);
}

TEST(CatchUp, HardSkipShowsThePopBlendThroughAvoids) {
  Rig smooth({stream("clear")}, wave, stalled(), withPolicy("blend-through"), GsParams{});
  Rig skip({stream("clear")}, wave, stalled(), withPolicy("hard-skip"), GsParams{});
  smooth.runFor(kEnd);
  skip.runFor(kEnd);
  expectSmooth(smooth, wave, 300);

  // The hard skip copies the late frame in: its pop is the whole distance. At the same vsync,
  // blend-through moves one blend step toward the same frame.
  const auto& h = skip.run.history();
  const auto& b = smooth.run.history();
  std::size_t firstSnap = 0;
  int snaps = 0;
  for (std::size_t n = 1; n < h.size(); ++n) {
    if (!h[n].snapped) continue;
    ++snaps;
    const int distance = maxDiff(wave(0, h[n].targetSeq), skip.before[n]);
    EXPECT_EQ(h[n].pop, distance) << n;
    if (firstSnap == 0) firstSnap = n;
  }
  ASSERT_GE(snaps, 1);
  ASSERT_EQ(b[firstSnap].targetSeq, h[firstSnap].targetSeq);
  EXPECT_TRUE(b[firstSnap].catchUp);
  EXPECT_FALSE(b[firstSnap].snapped);
  EXPECT_LE(b[firstSnap].pop, maxStep(h[firstSnap].pop, 64));
  EXPECT_LT(b[firstSnap].pop, h[firstSnap].pop);
  EXPECT_GT(skip.run.counters().maxPop, smooth.run.counters().maxPop);
  EXPECT_EQ(skip.run.counters().snaps, snaps + 1);
  EXPECT_EQ(skip.run.counters().framesCaughtUp, 0);  // every late frame was copied in
  EXPECT_EQ(skip.run.counters().framesLate, snaps);
  // On time the pattern moves 9 levels per frame, so no vsync pops by more than that.
  EXPECT_LE(smooth.ref.counters().maxPop, 9);
  std::printf("max pop: on time %d, blend-through %d, hard skip %d\n", smooth.ref.counters().maxPop,
              smooth.run.counters().maxPop, skip.run.counters().maxPop);
}

TEST(CatchUp, PlayLateNeverDropsAndKeepsItsLag) {
  Rig rig({stream("clear")}, wave, stalled(), withPolicy("play-late"), GsParams{});
  rig.runFor(kEnd);
  const PresenterCounters& k = rig.run.counters();
  EXPECT_EQ(k.framesDropped, 0);
  EXPECT_GE(k.slip, kStallFor - fromMs(40));
  EXPECT_LE(k.slip, kStallFor + fromMs(40));
  // Each frame is shown in turn, one stream frame per two vsyncs after the slip.
  const auto& h = rig.run.history();
  for (std::size_t n = 1; n < h.size(); ++n) ASSERT_LE(h[n].targetSeq - h[n - 1].targetSeq, 1) << n;
  // Half a second late for good: the lag never returns to the band.
  EXPECT_GT(rig.lag().back().maxDiff, stallBand(64));
  expectSmooth(rig, wave, 300);
}

TEST(CatchUp, LargerFixWhileBehindCatchesUpSooner) {
  GsParams fast;
  fast.catchup_fix = 120;
  Rig a({stream("clear")}, wave, stalled(), GsParams{}, GsParams{});
  Rig b({stream("clear")}, wave, stalled(), fast, GsParams{});
  a.runFor(kEnd);
  b.runFor(kEnd);
  const std::int64_t stallEnd = a.run.clock().countAt(kStallAt + kStallFor);
  auto backInBand = [&](const Rig& r) {
    std::int64_t n = stallEnd;
    while (n < static_cast<std::int64_t>(r.lag().size()) && r.lag()[n].maxDiff > stallBand(64)) ++n;
    return n;
  };
  EXPECT_LT(backInBand(b), backInBand(a));
  bool used = false;
  for (const VsyncRecord& r : b.run.history()) used |= r.fix == 120;
  EXPECT_TRUE(used);
  expectSmooth(b, wave, 300);
}

TEST(Branching, SwitchesAtTheSameTimeOfDaySmoothly) {
  const std::vector<StreamInfo> streams = {stream("clear"), stream("overcast")};
  SourceScript sc;
  sc.lead = fromMs(20);
  sc.decodeTime = fromMs(2);
  sc.branchLatency = fromMs(60);  // the seek to the other stream
  const GsParams p;
  // The reference plays the overcast stream from the start.
  Rig rig(streams, wave, sc, p, p, [](int, std::int64_t k) { return wave(1, k); });
  const Tick branchAt = fromMs(1500);
  rig.run.scheduleBranch(branchAt, 1);
  rig.runFor(kEnd);
  const auto& h = rig.run.history();
  const std::int64_t branchVsync = rig.run.clock().countAt(branchAt - 1) + 1;
  const std::int64_t dueAtBranch = h[branchVsync].dueSeq;

  std::size_t first = 0;
  while (first < h.size() && h[first].variant != 1) ++first;
  ASSERT_LT(first, h.size());
  // The first overcast frame comes after the seek and is the one due then: the same time of day.
  EXPECT_GT(h[first].at, branchAt + sc.branchLatency - fromMs(17));
  EXPECT_GT(h[first].targetSeq, dueAtBranch);
  EXPECT_EQ(h[first].targetSeq, h[first].dueSeq);
  for (std::size_t n = first; n < h.size(); ++n) ASSERT_EQ(h[n].variant, 1) << n;
  EXPECT_EQ(rig.run.counters().branches, 1);
  EXPECT_EQ(rig.run.variant(), 1);

  // Smooth: no vsync moves a texel more than one blend step; the change of weather is spread over
  // vsyncs and converges onto the overcast reference as g(d) predicts.
  expectSmooth(rig, wave, 300);
  EXPECT_EQ(rig.run.counters().snaps, 1);
  const auto& lag = rig.lag();
  EXPECT_GT(lag[first - 1].maxDiff, 40);  // clear vs overcast differ a lot
  int d = lag[first - 1].maxDiff;
  std::size_t k = 0;
  while (d > stallBand(64)) d = contract(d, 64), ++k;
  EXPECT_LE(lag[first - 1 + k].maxDiff, stallBand(64));
  for (std::size_t n = first; n < first + k; ++n) ASSERT_GT(lag[n].maxDiff, 0) << "took more than one vsync";
}

}  // namespace
}  // namespace vbim::gs
