// The vsync presenter on time: schedule, GS time per vsync (full and strip mode), loop wrap,
// convergence-aware steady stretches, SIMD vs scalar, PAL.
#include "gs/presenter.hpp"

#include <gtest/gtest.h>

#include "gs/simd/blend_simd.hpp"
#include "runtime/trace.hpp"

#include <functional>
#include <sstream>
#include "presenter_fixture.hpp"

namespace vbim::gs {
namespace {

using namespace test;

SourceScript onTime(Tick lead = fromMs(20)) {
  SourceScript s;
  s.lead = lead;
  s.decodeTime = fromMs(2);
  return s;
}

TEST(Presenter, StallFreeRunMatchesTheReferenceExactly) {
  GsParams p;
  Rig rig({stream("clear")}, wave, onTime(), p, p);
  rig.runFor(fromMs(2000));
  ASSERT_EQ(rig.lag().size(), 120u);  // NTSC vsyncs 0..119 before 2 s
  for (const LagSample& s : rig.lag()) ASSERT_EQ(s.maxDiff, 0) << "vsync " << s.vsync;
  const PresenterCounters& c = rig.run.counters();
  EXPECT_EQ(c.vsyncs, 120);
  EXPECT_EQ(c.framesShown, 60);  // one stream frame every second vsync
  EXPECT_EQ(c.framesLate, 0);
  EXPECT_EQ(c.framesDropped, 0);
  EXPECT_EQ(c.behindVsyncs, 0);
  EXPECT_EQ(c.catchUpVsyncs, 0);
  EXPECT_EQ(c.snaps, 1);  // the first frame is copied in
  // Frame k is the target from vsync 2k on.
  for (const VsyncRecord& r : rig.run.history()) ASSERT_EQ(r.targetSeq, r.vsync / 2) << r.vsync;
}

TEST(Presenter, FullModeUploadsNewFramesOnlyStripModeStreamsEveryVsync) {
  GsParams full;
  GsParams strips;
  strips.upload_mode = "strips";
  Rig a({stream("clear")}, wave, onTime(), full, full);
  Rig b({stream("clear")}, wave, onTime(), strips, strips);
  a.runFor(fromMs(500));
  b.runFor(fromMs(500));
  const GsTiming t{GsParams{}};
  // The default gs.upload_strategy: one IMAGE transfer per 16x16 macroblock.
  const Tick upload = t.imageTransfer(kW * kH * 4, (kW / 16) * (kH / 16));
  const Tick draw = t.spriteDraw(kW, kH);
  const Tick stripCost =
      2 * (t.imageTransfer(kW * 32 * 4, (kW / 16) * 2) + t.spriteDraw(kW, 32));  // 64 rows = 2 strips
  ASSERT_EQ(a.run.history().size(), b.run.history().size());
  for (std::size_t n = 0; n < a.run.history().size(); ++n) {
    const VsyncRecord& ra = a.run.history()[n];
    const VsyncRecord& rb = b.run.history()[n];
    EXPECT_EQ(ra.gsBusy, ra.vsync % 2 == 0 ? upload + draw : draw) << n;
    EXPECT_EQ(rb.gsBusy, stripCost) << n;
    EXPECT_EQ(ra.pop, rb.pop) << n;
  }
  // Same pixels, less VRAM, more bus traffic.
  EXPECT_EQ(a.run.lightmap().pixels, b.run.lightmap().pixels);
  EXPECT_LT(b.run.vram().pagesUsed(), a.run.vram().pagesUsed());
  EXPECT_GT(b.run.counters().uploadBytes, a.run.counters().uploadBytes);
}

TEST(Presenter, LoopWrapPopNeverExceedsOneBlendStep) {
  GsParams p;
  std::vector<StreamInfo> s = {stream("ramp", 12)};
  Rig rig(s, ramp, onTime(), p, p);
  rig.runFor(fromMs(1300));  // 12 frames at ~30 fps loop every ~0.4 s
  const auto& h = rig.run.history();
  int wraps = 0;
  for (std::size_t n = 1; n < h.size(); ++n) {
    const VsyncRecord& r = h[n];
    const Rgba8Image target = ramp(0, r.targetSeq % 12);
    const int distance = maxDiff(target, rig.before[n]);
    ASSERT_LE(r.pop, maxStep(distance, p.fix)) << "vsync " << n;
    if (r.targetSeq > 0 && r.targetSeq % 12 == 0 && h[n - 1].targetSeq % 12 == 11) {
      ++wraps;
      // The stream jumps by 220 levels (230 -> 10); the lightmap moves by one blend step.
      EXPECT_GE(distance, 200);
      EXPECT_LE(r.pop, maxStep(220, p.fix));
      EXPECT_LE(r.pop, maxStep(255, p.fix));
      EXPECT_GT(r.pop, 0);
    }
  }
  EXPECT_EQ(wraps, 3);
  EXPECT_EQ(rig.run.counters().loopWraps, 3);
  // The wraps are the largest pops of the run, and still one blend step.
  EXPECT_LE(rig.run.counters().maxPop, maxStep(220, p.fix));
  EXPECT_GT(rig.run.counters().maxPop, 90);
}

TEST(Presenter, WithoutLoopTheLastFrameHoldsAndSteadyVsyncsCostNoHostWork) {
  GsParams p;
  p.loop = false;
  SourceScript sc = onTime();
  sc.loop = false;
  Rig rig({stream("ramp", 12)}, ramp, sc, p, p);
  rig.runFor(fromMs(1500));
  const auto& h = rig.run.history();
  EXPECT_EQ(h.back().targetSeq, 11);
  EXPECT_EQ(rig.run.counters().loopWraps, 0);
  // Converged on the last frame: the tail of the run skips every tile, and the texels are 230.
  const int tiles = (kW / 64) * (kH / 32);
  EXPECT_GT(rig.run.counters().tilesSkipped, 40 * tiles);
  // Approached from below, floor stops FIX 64 one level short: 229 (the asymmetric fixed point).
  EXPECT_GE(rig.run.lightmap().pixels[0], 230 - stallBand(p.fix));
  EXPECT_LE(rig.run.lightmap().pixels[0], 230);
  // The GS still draws every vsync: simulated time does not depend on the shortcut.
  EXPECT_EQ(h.back().gsBusy, GsTiming(p).spriteDraw(kW, kH));
}

TEST(Presenter, SimdConvergenceAwareEqualsScalarBlendEverything) {
  GsParams fast;  // convergence-aware by default
  GsParams plain;
  plain.convergence_aware = false;
  SourceScript sc = onTime();
  sc.stalls = {{fromMs(700), fromMs(400)}};
  std::vector<std::uint64_t> hashesA, hashesB;
  auto hasher = [](std::vector<std::uint64_t>& out) {
    return [&out](const VsyncRecord&, const Rgba8Image& lm) {
      std::uint64_t h = 1469598103934665603ULL;
      for (std::uint8_t b : lm.pixels) h = (h ^ b) * 1099511628211ULL;
      out.push_back(h);
    };
  };
  Scheduler s;
  ScriptedFrameSource srcA({stream("clear", 30)}, wave, sc), srcB({stream("clear", 30)}, wave, sc);
  PresenterOptions oa, ob;
  oa.kernels = &simd::kernels();
  oa.onVsync = hasher(hashesA);
  ob.onVsync = hasher(hashesB);
  Presenter a(s, srcA, fast, oa), b(s, srcB, plain, ob);
  s.spawn("a", a.run(fromMs(3000)));
  s.spawn("b", b.run(fromMs(3000)));
  s.runUntil(fromMs(3000));
  ASSERT_EQ(hashesA.size(), 180u);
  EXPECT_EQ(hashesA, hashesB);
  EXPECT_GT(a.counters().tilesSkipped, 0);
  EXPECT_EQ(b.counters().tilesSkipped, 0);
}

// Presents the "clear" script for 500 ms recording into `tracer`; `beforeRun` runs once the
// presenter (and so its tracks) exists. Returns the presenter's counters.
PresenterCounters runTraced(const GsParams& p, Tracer& tracer, const std::function<void()>& beforeRun = {}) {
  Scheduler s;
  ScriptedFrameSource src({stream("clear")}, wave, onTime());
  PresenterOptions o;
  o.tracer = &tracer;
  Presenter pr(s, src, p, o);
  if (beforeRun) beforeRun();
  s.spawn("gs", pr.run(fromMs(500)));
  s.runUntil(fromMs(500));
  return pr.counters();
}

TEST(Presenter, TracesGsBusySpansAndCounters) {
  Tracer tracer;
  const PresenterCounters c = runTraced(GsParams{}, tracer);
  EXPECT_GT(tracer.spanCount(), 30u);
  EXPECT_EQ(tracer.busyTime(0, 0, fromMs(500)), c.gsBusy);
  std::ostringstream json;
  tracer.writeChromeJson(json);
  EXPECT_NE(json.str().find("gs.pop"), std::string::npos);
  EXPECT_NE(json.str().find("upload"), std::string::npos);
}

// Strip mode, streamed at the default detail: a vsync's strip uploads and blends are one `strips`
// span (the same busy time); full detail keeps a span per strip step.
TEST(Presenter, StripSpansAreOneSpanPerVsyncUnlessFullDetail) {
  std::string text[2];
  Tick busy[2] = {0, 0};
  const TraceDetail details[2] = {TraceDetail::Coalesced, TraceDetail::Full};
  for (int i = 0; i < 2; ++i) {
    GsParams p;
    p.upload_mode = "strips";
    Tracer tracer;
    std::ostringstream json, vcd;
    const PresenterCounters c = runTraced(p, tracer, [&] { tracer.streamTo(json, vcd, details[i]); });
    tracer.finish();
    busy[i] = tracer.busyTime(0, 0, fromMs(500));
    EXPECT_EQ(busy[i], c.gsBusy);
    text[i] = json.str();
  }
  EXPECT_EQ(busy[0], busy[1]);
  EXPECT_NE(text[0].find("\"strips\""), std::string::npos);
  EXPECT_EQ(text[0].find("\"upload\""), std::string::npos);
  EXPECT_NE(text[1].find("\"upload\""), std::string::npos);
  EXPECT_NE(text[1].find("\"blend\""), std::string::npos);
  EXPECT_LT(text[0].size() * 2, text[1].size());
}

TEST(Presenter, PalPresentsFiftyTimesASecond) {
  GsParams p;
  p.video = "pal";
  Rig rig({stream("clear")}, wave, onTime(), p, p);
  rig.runFor(fromMs(1000));
  EXPECT_EQ(rig.run.counters().vsyncs, 50);
  EXPECT_EQ(rig.run.history()[1].at, fromMs(20));
}

TEST(Presenter, GsWorkLongerThanAVsyncLosesVsyncs) {
  GsParams p;
  p.frame_buffers = 0;
  p.depth_format = "none";
  p.sky_width = 0;
  p.upload_mode = "strips";
  p.textured_pixels_per_clock = 1;
  p.page_break_overhead_pct = 400;
  const int w = 1024, h = 512;  // 524,288 px * 5 clocks > one NTSC field (2.46 M ticks)
  Scheduler s;
  ScriptedFrameSource src(
      {stream("big", 10, w, h)}, [](int, std::int64_t k) { return waveSized(0, k, 1024, 512); }, onTime());
  Presenter pr(s, src, p);
  s.spawn("gs", pr.run(fromMs(200)));
  s.runUntil(fromMs(200));
  EXPECT_GT(pr.counters().missedVsyncs, 0);
  EXPECT_LT(pr.counters().vsyncs, 12);
  EXPECT_EQ(pr.counters().vsyncs + pr.counters().missedVsyncs, 12);
}

// Two presenters on one GS (the lightmap and the sky of a console): at every vsync the second
// waits while the first draws, so their work never overlaps and the second's wait is the first's
// work; the pixels are those each would draw alone.
TEST(Presenter, PresentersSharingOneGsDrawOneAfterTheOther) {
  GsParams p;
  p.upload_mode = "strips";  // GS work at every vsync
  Scheduler s;
  SerialUnit gs(s);
  ScriptedFrameSource lmSource({stream("clear")}, wave, onTime());
  ScriptedFrameSource skySource(
      {stream("sky", 300, 64, 32)}, [](int v, std::int64_t k) { return waveSized(v, k, 64, 32); }, onTime());
  PresenterOptions shared;
  shared.gs = &gs;
  shared.name = "gs";
  Presenter lightmap(s, lmSource, p, shared);
  shared.name = "gs.sky";
  Presenter sky(s, skySource, p, shared);
  s.spawn("gs", lightmap.run(fromMs(300)));
  s.spawn("gs.sky", sky.run(fromMs(300)));
  s.runUntil(fromMs(300));

  Scheduler alone;
  ScriptedFrameSource skyAloneSource(
      {stream("sky", 300, 64, 32)}, [](int v, std::int64_t k) { return waveSized(v, k, 64, 32); }, onTime());
  Presenter skyAlone(alone, skyAloneSource, p);
  alone.spawn("gs.sky", skyAlone.run(fromMs(300)));
  alone.runUntil(fromMs(300));

  ASSERT_EQ(lightmap.history().size(), sky.history().size());
  ASSERT_FALSE(sky.history().empty());
  Tick waited = 0;
  for (std::size_t n = 0; n < sky.history().size(); ++n) {
    const VsyncRecord& a = lightmap.history()[n];
    const VsyncRecord& b = sky.history()[n];
    ASSERT_GT(a.gsBusy, 0) << n;
    EXPECT_EQ(a.gsWait, 0) << n;         // the lightmap asks first (spawned first)
    EXPECT_EQ(b.gsWait, a.gsBusy) << n;  // the sky draws when the lightmap is done
    EXPECT_EQ(b.gsBusy, skyAlone.history()[n].gsBusy) << n;
    waited += b.gsWait;
  }
  EXPECT_EQ(gs.waited(), waited);
  EXPECT_EQ(sky.lightmap().pixels, skyAlone.lightmap().pixels);
}

}  // namespace
}  // namespace vbim::gs
