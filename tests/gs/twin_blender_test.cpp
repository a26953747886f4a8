// Two blenders that follow each other (TiledBlender::Twin, issue #31) must give, at every step,
// the bytes, change counts, largest change and hash chain of two blenders that do all their own
// work: through the same and different sources, FIX changes, copies (FIX 128), either blending
// first, a source that is equal in bytes but another image, strips, and partial tiles.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "gs/error.hpp"
#include "gs/hash_chain.hpp"
#include "gs/simd/blend_simd.hpp"
#include "gs/tiled_blender.hpp"
#include "gs/twin_tiles.hpp"
#include "runtime/rng.hpp"

namespace vbim::gs {
namespace {

Rgba8Image randomImage(Rng& rng, int w, int h) {
  Rgba8Image img(w, h);
  for (auto& b : img.pixels) b = static_cast<std::uint8_t>(rng.below(256));
  return img;
}

// One side: a blender that follows its twin and one that does its own work, on equal lightmaps.
struct Side {
  Side(int w, int h, const BlendKernels& k, bool hash)
      : twinned(w, h, k, true, hash), alone(w, h, k, true, hash), lmTwinned(w, h), lmAlone(w, h) {
    twinned.recordBlends();
  }
  TiledBlender twinned;
  TiledBlender alone;
  Rgba8Image lmTwinned;
  Rgba8Image lmAlone;
  const Rgba8Image* lastSource = nullptr;  // the source of the last blend (to tell the twin)
};

struct Totals {
  int copied = 0;
  int steps = 0;
};

void runTwins(const BlendKernels& kernels, int w, int h, int stripRows, std::uint64_t seed, Totals& totals) {
  Rng rng(seed);
  // The run in hash mode (as the player's lightmap), the reference not.
  Side run(w, h, kernels, true);
  Side ref(w, h, kernels, false);
  TwinTiles equal(run.twinned.tileChanges().size());
  // Both lightmaps start all zero: equal at change count 0.
  for (std::size_t i = 0; i < equal.size(); ++i) equal.setEqual(i, 0, 0);
  // Sources: frames of a sequence; each side has its own copy of a frame's bytes.
  std::vector<Rgba8Image> frames;
  for (int i = 0; i < 4; ++i) frames.push_back(randomImage(rng, w, h));
  std::vector<Rgba8Image> refFrames = frames;
  int runFrame = 0;
  int refFrame = 0;
  for (int step = 0; step < 240; ++step) {
    // Mostly in step; now and then the reference moves on first or the run falls behind.
    if (rng.chance(1, 12)) runFrame = (runFrame + 1) % 4;
    if (rng.chance(1, 12)) refFrame = runFrame;
    if (rng.chance(1, 30)) refFrame = (refFrame + 1) % 4;
    BlendSpec spec = makeBlendSpec(rng.chance(1, 8) ? 100 : 64);
    if (rng.chance(1, 40)) {  // a copy, as a snap does
      spec.fix = 0x80;
      spec.dither = false;
    }
    BlendSpec refSpec = rng.chance(1, 20) ? makeBlendSpec(50) : spec;
    const int rowBegin =
        stripRows > 0 ? static_cast<int>(rng.below(static_cast<std::uint64_t>((h + 31) / 32))) * 32 : 0;
    const int rowEnd = stripRows > 0 ? std::min(h, rowBegin + stripRows) : h;
    const bool refFirst = rng.chance(1, 2);
    auto blendSide = [&](Side& me, Side& other, const Rgba8Image& src, int frame, const BlendSpec& s, bool runSide) {
      const auto id = static_cast<std::uint64_t>(frame) + 1;
      // The other's last blend was from a frame with these bytes (the presenter compares the images;
      // here a frame's index names its bytes on both sides).
      const bool same = other.lastSource != nullptr && other.twinned.lastSourceId() == id;
      const TiledBlender::Twin twin{&other.twinned, &other.lmTwinned, &equal, runSide, same};
      const TiledBlender::Result a = me.twinned.blend(me.lmTwinned, src, s, id, rowBegin, rowEnd, &twin);
      const TiledBlender::Result b = me.alone.blend(me.lmAlone, src, s, id, rowBegin, rowEnd);
      me.lastSource = &src;
      totals.copied += a.tilesCopied;
      ASSERT_EQ(a.pop, b.pop) << "step " << step;
      ASSERT_EQ(a.tilesBlended + a.tilesSkipped + a.tilesCopied, b.tilesBlended + b.tilesSkipped) << "step " << step;
      ASSERT_EQ(me.lmTwinned.pixels, me.lmAlone.pixels) << "step " << step;
      ASSERT_EQ(me.twinned.tileChanges(), me.alone.tileChanges()) << "step " << step;
    };
    const int runShown = runFrame;
    const int refShown = refFrame;
    if (refFirst) {
      blendSide(ref, run, refFrames[static_cast<std::size_t>(refShown)], refShown, refSpec, false);
      blendSide(run, ref, frames[static_cast<std::size_t>(runShown)], runShown, spec, true);
    } else {
      blendSide(run, ref, frames[static_cast<std::size_t>(runShown)], runShown, spec, true);
      blendSide(ref, run, refFrames[static_cast<std::size_t>(refShown)], refShown, refSpec, false);
    }
    if (::testing::Test::HasFatalFailure()) return;
    // The hash chain of the run (hash mode) is that of its own work.
    const HashChain& a = run.twinned.hashChain(run.lmTwinned);
    const HashChain& b = run.alone.hashChain(run.lmAlone);
    ASSERT_TRUE(std::equal(std::begin(a.lanes), std::end(a.lanes), std::begin(b.lanes)) && a.count == b.count)
        << "step " << step;
    // What the lag would learn: tiles found equal by comparison (TiledDifference adds such facts).
    if (rng.chance(1, 3)) {
      const std::size_t stride = static_cast<std::size_t>(w) * 4;
      const int tilesX = run.twinned.tilesX();
      for (int ty = 0; ty < run.twinned.tilesY(); ++ty) {
        for (int tx = 0; tx < tilesX; ++tx) {
          const int y0 = ty * kTileHeight;
          const auto rows = static_cast<std::size_t>(std::min(kTileHeight, h - y0));
          const std::size_t left = static_cast<std::size_t>(tx) * kTileWidth * 4;
          const std::size_t bytes = static_cast<std::size_t>(std::min(kTileWidth, w - tx * kTileWidth)) * 4;
          const ByteDifference d = compareRectScalar(run.lmTwinned.row(y0) + left, stride, ref.lmTwinned.row(y0) + left,
                                                     stride, bytes, rows);
          const std::size_t i = static_cast<std::size_t>(ty) * tilesX + tx;
          if (d.max == 0) equal.setEqual(i, run.twinned.tileChanges()[i], ref.twinned.tileChanges()[i]);
        }
      }
    }
    ++totals.steps;
  }
}

TEST(TwinBlender, SameBytesCountsAndChainAsOwnWorkScalar) {
  Totals t;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    runTwins(scalarKernels(), 256, 128, 0, seed, t);
    ASSERT_FALSE(HasFatalFailure()) << "seed " << seed;
  }
  EXPECT_GT(t.copied, 400) << "the twins should copy tiles while in step";
}

TEST(TwinBlender, SameBytesCountsAndChainAsOwnWorkSimd) {
  Totals t;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    runTwins(simd::kernels(), 256, 128, 0, seed, t);
    ASSERT_FALSE(HasFatalFailure()) << "seed " << seed;
  }
  EXPECT_GT(t.copied, 400);
}

TEST(TwinBlender, PartialTilesAndStrips) {
  Totals t;
  runTwins(simd::kernels(), 200, 100, 0, 7, t);
  ASSERT_FALSE(HasFatalFailure());
  runTwins(simd::kernels(), 200, 100, 32, 8, t);
  ASSERT_FALSE(HasFatalFailure());
  runTwins(scalarKernels(), 130, 70, 64, 9, t);
  ASSERT_FALSE(HasFatalFailure());
  EXPECT_GT(t.copied, 100);
}

TEST(TwinBlender, NothingCopiedWithoutAKnownEqualTile) {
  Rng rng(3);
  TiledBlender a(128, 64, scalarKernels(), true);
  TiledBlender b(128, 64, scalarKernels(), true);
  a.recordBlends();
  b.recordBlends();
  Rgba8Image la(128, 64);
  Rgba8Image lb(128, 64);
  const Rgba8Image src = randomImage(rng, 128, 64);
  TwinTiles equal(a.tileChanges().size());  // no facts: the two might differ
  const BlendSpec spec = makeBlendSpec(64);
  a.blend(la, src, spec, 1);
  const TiledBlender::Twin twin{&a, &la, &equal, false, true};
  const TiledBlender::Result r = b.blend(lb, src, spec, 1, 0, 64, &twin);
  EXPECT_EQ(r.tilesCopied, 0);
  EXPECT_EQ(la.pixels, lb.pixels);  // blended by itself, to the same bytes
  // Once the tiles are known equal (both were all zero before), the next blend is copied.
  for (std::size_t i = 0; i < equal.size(); ++i) equal.setEqual(i, a.tileChanges()[i], b.tileChanges()[i]);
  a.blend(la, src, spec, 1);
  const TiledBlender::Result r2 = b.blend(lb, src, spec, 1, 0, 64, &twin);
  EXPECT_EQ(r2.tilesCopied, static_cast<int>(equal.size()));
  EXPECT_EQ(la.pixels, lb.pixels);
}

// A blender that takes its twin's blends (TiledBlender::takeTwinBlend, the mirroring reference)
// moves its change counts and reports the pop as one that blends the same bytes itself, through
// source and FIX changes, converged tiles and strips; and each taken tile is noted equal.
TEST(TwinBlender, TakenBlendsMoveCountsAndPopAsOwnBlends) {
  for (const bool simdKernels : {false, true}) {
    const BlendKernels& k = simdKernels ? simd::kernels() : scalarKernels();
    Rng rng(11);
    const int w = 200;
    const int h = 100;
    TiledBlender run(w, h, k, true, /*hashChain=*/true);
    TiledBlender taker(w, h, k, true);
    TiledBlender alone(w, h, k, true);
    run.recordBlends();
    Rgba8Image lmRun(w, h);
    Rgba8Image lmAlone(w, h);
    TwinTiles equal(run.tileChanges().size());
    std::vector<Rgba8Image> frames;
    for (int i = 0; i < 3; ++i) frames.push_back(randomImage(rng, w, h));
    int frame = 0;
    for (int step = 0; step < 200; ++step) {
      if (rng.chance(1, 15)) frame = (frame + 1) % 3;
      BlendSpec spec = makeBlendSpec(rng.chance(1, 6) ? 100 : 48);
      if (rng.chance(1, 40)) {
        spec.fix = 0x80;
        spec.dither = false;
      }
      const int rowBegin = rng.chance(1, 3) ? static_cast<int>(rng.below(4)) * 32 : 0;
      const int rowEnd = rowBegin == 0 ? h : std::min(h, rowBegin + 32);
      const auto id = static_cast<std::uint64_t>(frame) + 1;
      run.blend(lmRun, frames[static_cast<std::size_t>(frame)], spec, id, rowBegin, rowEnd);
      const int pop = taker.takeTwinBlend(run, equal, /*runSide=*/false, id, spec, rowBegin, rowEnd);
      const TiledBlender::Result own =
          alone.blend(lmAlone, frames[static_cast<std::size_t>(frame)], spec, id, rowBegin, rowEnd);
      ASSERT_EQ(pop, own.pop) << "step " << step;
      ASSERT_EQ(taker.tileChanges(), alone.tileChanges()) << "step " << step;
      ASSERT_EQ(lmRun.pixels, lmAlone.pixels) << "step " << step;
      for (std::size_t i = 0; i < equal.size(); ++i) {
        if (run.tileChanges()[i] == 0 && taker.tileChanges()[i] == 0) continue;  // never blended yet
        ASSERT_TRUE(equal.equalAt(i, run.tileChanges()[i], taker.tileChanges()[i])) << "tile " << i;
      }
    }
  }
}

TEST(TwinBlender, TakingABlendNotRecordedThrows) {
  TiledBlender run(64, 32, scalarKernels(), true);
  TiledBlender taker(64, 32, scalarKernels(), true);
  TwinTiles equal(run.tileChanges().size());
  const BlendSpec spec = makeBlendSpec(64);
  EXPECT_THROW(taker.takeTwinBlend(run, equal, false, 1, spec, 0, 32), GsError);  // no recordBlends()
  run.recordBlends();
  EXPECT_THROW(taker.takeTwinBlend(run, equal, false, 1, spec, 0, 32), GsError);  // nothing blended yet
}

}  // namespace
}  // namespace vbim::gs
