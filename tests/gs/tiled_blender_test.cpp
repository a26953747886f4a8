// The convergence-aware mode skips tiles at their fixed point; it must give the same bytes as
// blending everything, through target changes, FIX changes, partial tiles and strips.
#include "gs/tiled_blender.hpp"

#include <gtest/gtest.h>

#include "gs/error.hpp"
#include "gs/simd/blend_simd.hpp"
#include "runtime/rng.hpp"

namespace vbim::gs {
namespace {

Rgba8Image randomImage(Rng& rng, int w, int h, int base, int spread) {
  Rgba8Image img(w, h);
  for (auto& b : img.pixels)
    b = static_cast<std::uint8_t>(std::clamp<int>(base + static_cast<int>(rng.below(spread)), 0, 255));
  return img;
}

void runSequence(const BlendKernels& kernels, int w, int h, int stripRows) {
  Rng rng(42);
  TiledBlender aware(w, h, kernels, true);
  TiledBlender plain(w, h, scalarKernels(), false);
  Rgba8Image a = randomImage(rng, w, h, 0, 256);
  Rgba8Image b = a;
  Rgba8Image target = randomImage(rng, w, h, 0, 256);
  std::uint64_t id = 1;
  int skipped = 0;
  for (int step = 0; step < 300; ++step) {
    if (rng.chance(1, 25)) {  // a new frame: part of it changes, part stays
      Rgba8Image next = target;
      const int y0 = static_cast<int>(rng.below(static_cast<std::uint64_t>(h)));
      for (int y = y0; y < std::min(h, y0 + 20); ++y) {
        for (int x = 0; x < w * 4; ++x) next.row(y)[x] = static_cast<std::uint8_t>(rng.below(256));
      }
      target = next;
      ++id;
    }
    const BlendSpec spec = makeBlendSpec(rng.chance(1, 10) ? 100 : 64);
    int popA = 0, popB = 0;
    for (int y0 = 0; y0 < h; y0 += stripRows) {
      const int y1 = std::min(h, y0 + stripRows);
      const auto ra = aware.blend(a, target, spec, id, y0, y1);
      const auto rb = plain.blend(b, target, spec, id, y0, y1);
      popA = std::max(popA, ra.pop);
      popB = std::max(popB, rb.pop);
      skipped += ra.tilesSkipped;
      EXPECT_EQ(rb.tilesSkipped, 0);
    }
    ASSERT_EQ(a.pixels, b.pixels) << "step " << step;
    ASSERT_EQ(popA, popB) << "step " << step;
  }
  EXPECT_GT(skipped, 0) << "a steady target should leave converged tiles to skip";
}

// Hash mode: through new frames, FIX changes, strips and partial tiles, the blender's chain is the
// chain of the image's header and bytes as they are, whenever it is asked (not at every blend: the
// tile rows it did not fold are folded when asked), and bytes and tile counts are those of a
// blender without it.
void runHashed(const BlendKernels& kernels, int w, int h, int stripRows, bool aware) {
  Rng rng(1234);
  TiledBlender hashed(w, h, kernels, aware, true);
  TiledBlender plain(w, h, scalarKernels(), aware);
  Rgba8Image a = randomImage(rng, w, h, 0, 256);
  Rgba8Image b = a;
  Rgba8Image target = randomImage(rng, w, h, 0, 256);
  std::uint64_t id = 1;
  int checks = 0;
  for (int step = 0; step < 200; ++step) {
    if (rng.chance(1, 20)) {  // a new frame that differs in a band of rows only
      const int y0 = static_cast<int>(rng.below(static_cast<std::uint64_t>(h)));
      for (int y = y0; y < std::min(h, y0 + 9); ++y) {
        for (int x = 0; x < w * 4; ++x) target.row(y)[x] = static_cast<std::uint8_t>(rng.below(256));
      }
      ++id;
    }
    const BlendSpec spec = makeBlendSpec(rng.chance(1, 10) ? 100 : 64);
    for (int y0 = 0; y0 < h; y0 += stripRows) {
      const int y1 = std::min(h, y0 + stripRows);
      const auto ra = hashed.blend(a, target, spec, id, y0, y1);
      const auto rb = plain.blend(b, target, spec, id, y0, y1);
      ASSERT_EQ(ra.pop, rb.pop) << "step " << step;
      ASSERT_EQ(ra.tilesBlended, rb.tilesBlended) << "step " << step;
      ASSERT_EQ(ra.tilesSkipped, rb.tilesSkipped) << "step " << step;
    }
    ASSERT_EQ(a.pixels, b.pixels) << "step " << step;
    ASSERT_EQ(hashed.tileChanges(), plain.tileChanges()) << "step " << step;
    if (rng.chance(1, 3)) {
      HashChain want;
      want.addHeader(w, h);
      want.addBytes(a.pixels.data(), a.pixels.size());
      const HashChain& got = hashed.hashChain(a);
      ASSERT_EQ(got.count, want.count) << "step " << step;
      for (int l = 0; l < 4; ++l) ASSERT_EQ(got.lanes[l], want.lanes[l]) << "step " << step << " lane " << l;
      ++checks;
    }
  }
  EXPECT_GT(checks, 40);
}

TEST(TiledBlender, HashModeChainIsTheImagesChain) {
  for (const BlendKernels* k : {&scalarKernels(), &simd::kernels()}) {
    runHashed(*k, 256, 128, 32, true);  // whole tiles, strips of one tile row
    runHashed(*k, 200, 100, 64, true);  // partial tiles, rows of an even width
    runHashed(*k, 77, 70, 100, true);   // an odd width: rows are not whole words
    runHashed(*k, 130, 96, 96, false);  // without convergence marks
  }
}

TEST(TiledBlender, HashModeNeedsItsMode) {
  TiledBlender b(64, 32, scalarKernels(), true);
  Rgba8Image img(64, 32);
  EXPECT_THROW((void)b.hashChain(img), GsError);
}

TEST(TiledBlender, ConvergenceAwareIsBitIdenticalScalar) {
  runSequence(scalarKernels(), 256, 128, 128);
}
TEST(TiledBlender, ConvergenceAwareIsBitIdenticalSimd) {
  runSequence(simd::kernels(), 256, 128, 128);
}
TEST(TiledBlender, PartialTilesAndStrips) {
  runSequence(simd::kernels(), 100, 70, 32);
  runSequence(scalarKernels(), 130, 33, 64);
}

// tileChanges() is what the player's lag relies on to compare only the tiles that moved: a tile
// whose count did not move must hold the same bytes. The convergence-aware blender counts exactly
// the tiles that changed; the plain one may count a whole tile row.
void checkTileChanges(const BlendKernels& kernels, bool aware, int w, int h, int stripRows) {
  Rng rng(9);
  TiledBlender blender(w, h, kernels, aware);
  Rgba8Image lm = randomImage(rng, w, h, 0, 256);
  Rgba8Image target = randomImage(rng, w, h, 0, 256);
  std::uint64_t id = 1;
  int moved = 0, still = 0;
  for (int step = 0; step < 200; ++step) {
    if (rng.chance(1, 20)) {  // a new frame differing in a band of rows
      const int y0 = static_cast<int>(rng.below(static_cast<std::uint64_t>(h)));
      for (int y = y0; y < std::min(h, y0 + 9); ++y) {
        for (int x = 0; x < w * 4; ++x) target.row(y)[x] = static_cast<std::uint8_t>(rng.below(256));
      }
      ++id;
    }
    const BlendSpec spec = makeBlendSpec(rng.chance(1, 8) ? 128 : 64);
    for (int y0 = 0; y0 < h; y0 += stripRows) {
      const Rgba8Image before = lm;
      const std::vector<std::uint64_t> countsBefore = blender.tileChanges();
      blender.blend(lm, target, spec, id, y0, std::min(h, y0 + stripRows));
      for (int ty = 0; ty < blender.tilesY(); ++ty) {
        for (int tx = 0; tx < blender.tilesX(); ++tx) {
          bool same = true;
          for (int y = ty * kTileHeight; y < std::min(h, (ty + 1) * kTileHeight); ++y) {
            for (int x = tx * kTileWidth * 4; x < std::min(w, (tx + 1) * kTileWidth) * 4; ++x)
              same = same && before.row(y)[x] == lm.row(y)[x];
          }
          const std::size_t i = static_cast<std::size_t>(ty) * blender.tilesX() + tx;
          const bool counted = blender.tileChanges()[i] != countsBefore[i];
          ASSERT_LE(blender.tileChanges()[i], countsBefore[i] + 1) << "one count per blend";
          if (!counted) {
            ASSERT_TRUE(same) << "tile " << tx << "," << ty << " changed uncounted at step " << step;
          }
          if (aware) {
            ASSERT_EQ(counted, !same) << "tile " << tx << "," << ty << " at step " << step;
          }
          (counted ? moved : still) += 1;
        }
      }
    }
  }
  EXPECT_GT(moved, 0);
  EXPECT_GT(still, 0);
}

TEST(TiledBlender, TileChangesCountEveryTileThatMoved) {
  checkTileChanges(scalarKernels(), true, 256, 128, 128);
  checkTileChanges(simd::kernels(), true, 100, 70, 32);
  checkTileChanges(simd::kernels(), false, 130, 65, 64);
  checkTileChanges(scalarKernels(), false, 64, 32, 32);
}

TEST(TiledBlender, SteadyTargetCostsNothingOnceConverged) {
  Rng rng(7);
  const int w = 256, h = 256;
  TiledBlender blender(w, h, scalarKernels(), true);
  Rgba8Image lm = randomImage(rng, w, h, 0, 256);
  const Rgba8Image target = randomImage(rng, w, h, 0, 256);
  const BlendSpec spec = makeBlendSpec(64);
  int vsyncs = 0;
  TiledBlender::Result r;
  do {
    r = blender.blend(lm, target, spec, 1);
    ++vsyncs;
  } while (r.pop > 0 && vsyncs < 100);
  // Distances halve (roughly) each vsync: 255 -> within the floor's band in about 8 steps.
  EXPECT_LE(vsyncs, 10);
  r = blender.blend(lm, target, spec, 1);
  EXPECT_EQ(r.tilesBlended, 0);
  EXPECT_EQ(r.tilesSkipped, (w / 64) * (h / 32));
  // A different FIX is a different fixed point: everything is blended again.
  r = blender.blend(lm, target, makeBlendSpec(96), 1);
  EXPECT_EQ(r.tilesSkipped, 0);
}

}  // namespace
}  // namespace vbim::gs
