// The reference pipeline shares the run's host work (issue #31, PlayerOptions::shareReference): a
// tile one of the two blended from the same bytes toward the same source with the same spec is
// copied by the other, and tiles known equal are not compared for the lag. Fault plays with and
// without the sharing must give the same rows (hash, lag, sky lag, presenter records) at every vsync
// and the same lightmaps and skies of both pipelines, over several fault plans, seeds, catch-up
// policies, upload modes, kernels and a branch; and the sharing must actually take place. The same
// with the reference mirroring the run (PlayerOptions::mirrorReference: it takes the run's blends
// as its own while every tile agrees) and without; the reference's own records (its pops) too.
// And with the two IPUs sharing their decodes (PlayerOptions::shareDecodes: one decodes each
// picture both are given after the same history, the other takes its picture) and without, also
// on a stream of GOPs with P and B pictures (the BDEC flow: a log per stream, and a stale decoder
// takes the other's frame stores).
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "config/fault_plan_toml.hpp"
#include "gs/simd/blend_simd.hpp"
#include "player/scenario.hpp"
#include "streams/authoring/stream_writer.hpp"
#include "streams/authoring/synthetic_day.hpp"
#include "streams/authoring/tone_map.hpp"
#include "tests/player/sample_path.hpp"
#include "tests/support/scratch.hpp"

namespace vbim::player {
namespace {

struct Case {
  std::string sample = "day_clear.vbim";  // under streams/samples/, or a path
  const char* faults = "";
  std::uint64_t seed = 1;
  bool simd = true;
  bool strips = false;
  bool aware = true;
  std::string policy = "blend-through";
  int catchupFix = 0;
  Tick branchAt = -1;
  Tick duration = fromMs(40'000);
  // Play-late slips the run's schedule for good after the stall, so the two never blend the same
  // bytes toward the same frame again: nothing to share, the bytes must still agree.
  bool expectShared = true;
  // The reference mirrors the run once they are in step, in strip mode too: its processes are in
  // the scheduler's first lane, so it asks for each strip's blend before the run makes it (before
  // the lanes, a run with no frame during the spin-up stall came first at every later tick, and a
  // strip-mode reference never mirrored).
  bool expectMirrored = true;
  // A stall after the two were in step makes the mirroring reference take its own bytes back.
  bool expectStops = false;
};

struct Outcome {
  std::vector<VsyncRow> rows;
  Rgba8Image lightmap, sky, refLightmap, refSky;
  std::int64_t copied = 0;      // tiles copied by either pipeline's presenters
  std::int64_t mirrored = 0;    // tiles whose blend the reference took from the run's (mirroring)
  std::int64_t stops = 0;       // times the mirroring reference took its own bytes back
  std::int64_t rowsCopied = 0;  // lightmap rows it copied back from the run when it stopped
  int height = 0;               // the lightmap's
  std::vector<gs::VsyncRecord> refRecords, refSkyRecords;
  std::int64_t decodesTaken = 0;  // decodes one IPU took from the other
};

Outcome play(const Case& c, bool share, bool mirror, bool shareDecodes) {
  const std::string path = c.sample.find('/') == std::string::npos ? testing::samplePath(c.sample) : c.sample;
  Scenario sc = Scenario::bareFile(path).seed(c.seed).trace(false).policy(c.policy);
  if (c.simd) sc.kernels(Kernels{&gs::simd::kernels(), nullptr, nullptr});
  sc.options().config.gs.convergence_aware = c.aware;
  sc.options().config.gs.catchup_fix = c.catchupFix;
  if (c.strips) sc.options().config.gs.upload_mode = "strips";
  sc.options().shareReference = share;
  sc.options().mirrorReference = mirror;
  sc.options().shareDecodes = shareDecodes;
  sc.faults(config::parseFaultPlan(c.faults, "<faults>", &sc.disc()));
  if (c.branchAt >= 0) sc.branch(c.branchAt, 1);
  auto run = sc.start(c.duration);
  Player& p = run->player();
  Outcome o;
  // The reference's records as they are once every presenter presented the vsync.
  Player::Sink inner = p.sink();
  p.setSink([&](const VsyncRow& row, const Rgba8Image& lm, const Rgba8Image* sky) {
    o.refRecords.push_back(p.reference()->lightmap().last());
    o.refSkyRecords.push_back(p.reference()->sky()->last());
    if (inner) inner(row, lm, sky);
  });
  run->runToEnd();
  EXPECT_TRUE(p.hasReference());
  o.rows = run->rows();
  o.lightmap = p.lightmap();
  o.sky = *p.sky();
  o.refLightmap = p.reference()->lightmap().lightmap();
  o.refSky = p.reference()->sky()->lightmap();
  for (Pipeline* pl : {&p.pipeline(), p.reference()}) {
    o.copied += pl->lightmap().counters().tilesCopied + pl->sky()->counters().tilesCopied;
    o.mirrored += pl->lightmap().counters().tilesMirrored + pl->sky()->counters().tilesMirrored;
    o.stops += pl->lightmap().counters().mirrorStops + pl->sky()->counters().mirrorStops;
    o.rowsCopied += pl->lightmap().counters().mirrorRowsCopied + pl->sky()->counters().mirrorRowsCopied;
  }
  o.height = o.lightmap.height;
  EXPECT_EQ(p.sharedDecodes() != nullptr, shareDecodes);
  if (p.sharedDecodes() != nullptr) o.decodesTaken = p.sharedDecodes()->counters().taken;
  for (const ipu::SharedDecodes* flow : p.sharedFlowDecodes()) o.decodesTaken += flow->counters().taken;
  return o;
}

void expectSameRecord(const gs::VsyncRecord& a, const gs::VsyncRecord& b, std::int64_t n) {
  EXPECT_EQ(a.at, b.at) << "vsync " << n;
  EXPECT_EQ(a.targetSeq, b.targetSeq) << "vsync " << n;
  EXPECT_EQ(a.variant, b.variant) << "vsync " << n;
  EXPECT_EQ(a.fix, b.fix) << "vsync " << n;
  EXPECT_EQ(a.pop, b.pop) << "vsync " << n;
  EXPECT_EQ(a.snapped, b.snapped) << "vsync " << n;
  EXPECT_EQ(a.gsBusy, b.gsBusy) << "vsync " << n;
}

void expectSameOutcome(const Outcome& shared, const Outcome& own) {
  ASSERT_EQ(shared.rows.size(), own.rows.size());
  int lagged = 0;
  for (std::size_t i = 0; i < own.rows.size(); ++i) {
    const VsyncRow& a = shared.rows[i];
    const VsyncRow& b = own.rows[i];
    ASSERT_EQ(a.hash, b.hash) << "vsync " << b.vsync;
    ASSERT_EQ(a.lag, b.lag) << "vsync " << b.vsync;
    ASSERT_EQ(a.skyLag, b.skyLag) << "vsync " << b.vsync;
    ASSERT_EQ(a.ringBanks, b.ringBanks) << "vsync " << b.vsync;
    expectSameRecord(a.lightmap, b.lightmap, b.vsync);
    ASSERT_TRUE(a.sky && b.sky);
    expectSameRecord(*a.sky, *b.sky, b.vsync);
    if (b.lag != 0) ++lagged;
  }
  ASSERT_EQ(shared.refRecords.size(), own.refRecords.size());
  for (std::size_t i = 0; i < own.refRecords.size(); ++i) {
    expectSameRecord(shared.refRecords[i], own.refRecords[i], own.refRecords[i].vsync);
    expectSameRecord(shared.refSkyRecords[i], own.refSkyRecords[i], own.refSkyRecords[i].vsync);
  }
  EXPECT_EQ(shared.lightmap.pixels, own.lightmap.pixels);
  EXPECT_EQ(shared.sky.pixels, own.sky.pixels);
  EXPECT_EQ(shared.refLightmap.pixels, own.refLightmap.pixels);
  EXPECT_EQ(shared.refSky.pixels, own.refSky.pixels);
  EXPECT_GT(lagged, 10) << "the faults should make the run differ from the reference";
  EXPECT_EQ(own.copied, 0);
  EXPECT_EQ(own.mirrored, 0);
}

void expectSameBytes(const Case& c) {
  const Outcome own = play(c, false, false, /*shareDecodes=*/false);
  const Outcome copying = play(c, true, /*mirror=*/false, /*shareDecodes=*/false);
  const Outcome mirroring = play(c, true, /*mirror=*/true, /*shareDecodes=*/true);
  const Outcome decodesOnly = play(c, false, false, /*shareDecodes=*/true);
  {
    SCOPED_TRACE("shared by copies");
    expectSameOutcome(copying, own);
  }
  {
    SCOPED_TRACE("shared by mirroring and decodes");
    expectSameOutcome(mirroring, own);
  }
  {
    SCOPED_TRACE("decodes shared");
    expectSameOutcome(decodesOnly, own);
  }
  // Two decodes a second in either play for most of its 40 s: most of them taken.
  EXPECT_GT(decodesOnly.decodesTaken, 40) << "the IPUs should share the decodes of the same pictures";
  EXPECT_GT(mirroring.decodesTaken, 40);
  EXPECT_EQ(copying.mirrored, 0);
  EXPECT_EQ(copying.stops, 0);
  if (!c.aware) {
    EXPECT_EQ(copying.copied, 0) << "without the convergence shortcut there is nothing recorded to share";
    EXPECT_EQ(mirroring.copied + mirroring.mirrored, 0) << "nor anything to mirror";
  } else if (c.expectShared) {
    EXPECT_GT(copying.copied, 1000) << "the pipelines should share most blends while in step";
    if (c.expectMirrored) {
      EXPECT_GT(mirroring.mirrored, 1000) << "the reference should mirror the run while in step";
    }
  }
  // A few stops per divergence, never one per blend; each copies back only the rows the run blended
  // for the reference while it mirrored, so never more than a few lightmaps' worth in all.
  EXPECT_LT(mirroring.stops, 40);
  EXPECT_LT(mirroring.rowsCopied, 40 * mirroring.height);
  if (c.expectStops) {
    EXPECT_GT(mirroring.stops, 0) << "the late stall should make the reference take its bytes back";
    EXPECT_GT(mirroring.rowsCopied, 0) << "it mirrored the run's blends, so it takes their rows back";
  }
}

constexpr const char* kStalls =
    "[[fault]]\nkind='stall'\nat='200ms'\nduration='4s'\n"
    "[[fault]]\nkind='random_stall'\nfrom='0s'\nduration='40s'\nmean_interval='6s'\nstall='3s'\n";
constexpr const char* kStallsAndReadError =
    "[[fault]]\nkind='stall'\nat='200ms'\nduration='6s'\n"
    "[[fault]]\nkind='read_error'\nlba=2090\nattempts=300\n"
    "[[fault]]\nkind='random_stall'\nfrom='0s'\nduration='40s'\nmean_interval='5s'\nstall='2s'\n";
constexpr const char* kLongStall = "[[fault]]\nkind='stall'\nat='200ms'\nduration='8s'\n";
// In step from the start (no fault before 20 s), then a stall over the loop's re-read at 24 s: the
// run shows six frames late.
constexpr const char* kLateStall = "[[fault]]\nkind='stall'\nat='20s'\nduration='10s'\n";

TEST(SharedReference, SameBytesAsUnsharedAcrossSeeds) {
  for (const std::uint64_t seed : {1, 2, 5}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    Case c;
    c.faults = kStallsAndReadError;
    c.seed = seed;
    expectSameBytes(c);
  }
}

TEST(SharedReference, SameBytesScalarKernelsOtherSample) {
  Case c;
  c.sample = "day_weather.vbim";
  c.faults = kStalls;
  c.simd = false;
  expectSameBytes(c);
}

TEST(SharedReference, SameBytesInStripsWithCatchUpFix) {
  Case c;
  c.faults = kStalls;
  c.strips = true;
  c.catchupFix = 96;
  expectSameBytes(c);
}

TEST(SharedReference, SameBytesForEachCatchUpPolicy) {
  for (const char* policy : {"hard-skip", "play-late"}) {
    SCOPED_TRACE(policy);
    Case c;
    c.faults = kLongStall;
    c.policy = policy;
    c.expectShared = std::string(policy) != "play-late";
    expectSameBytes(c);
  }
}

TEST(SharedReference, SameBytesWithABranch) {
  Case c;
  c.sample = "day_weather.vbim";
  c.faults = kStallsAndReadError;
  c.branchAt = fromMs(14'000);
  c.seed = 3;
  expectSameBytes(c);
}

TEST(SharedReference, SameBytesWhenTheRunFallsBehindAfterBeingInStep) {
  for (const char* policy : {"blend-through", "hard-skip"}) {
    SCOPED_TRACE(policy);
    Case c;
    c.faults = kLateStall;
    c.policy = policy;
    c.seed = 4;
    c.expectStops = true;
    expectSameBytes(c);
  }
}

// A day cycle of GOPs of 12 with 2 B pictures (as `vbim author --gop 12 --b-frames 2`), 128x128
// with a 64x32 sky, 24 frames at 1 frame/s, written under the test's scratch directory.
std::string gopStream() {
  streams::AuthorSettings s;
  s.gameFps = {1, 1};
  s.encoder.gop = 12;
  s.encoder.bFrames = 2;
  streams::StreamWriter w(s);
  streams::SyntheticDay day;
  day.width = 128;
  day.height = 128;
  day.skyWidth = 64;
  day.skyHeight = 32;
  day.frames = 24;
  w.beginVariant("clear");
  for (std::uint32_t f = 0; f < day.frames; ++f) {
    const Rgba8Image lm = streams::toneMap(streams::syntheticLightmap(day, f), streams::ToneMapping{});
    const Rgba8Image sky = streams::toneMap(streams::syntheticSky(day, f), streams::ToneMapping{});
    w.addFrame(lm, &sky);
  }
  const std::vector<std::uint8_t> bytes = w.finish();
  const std::string path = (vbim::testing::scratchDir("shared_reference_gop") / "gop12.vbim").string();
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  return path;
}

TEST(SharedReference, SameBytesOnAStreamOfGops) {
  const std::string path = gopStream();
  for (const std::uint64_t seed : {1, 3}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    Case c;
    c.sample = path;
    c.faults = kStallsAndReadError;
    c.seed = seed;
    expectSameBytes(c);
  }
}

TEST(SharedReference, SameBytesWithoutTheConvergenceShortcut) {
  Case c;
  c.faults = kStalls;
  c.aware = false;
  expectSameBytes(c);
}

}  // namespace
}  // namespace vbim::player
