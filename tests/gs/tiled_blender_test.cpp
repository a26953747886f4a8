// The convergence-aware mode skips tiles at their fixed point; it must give the same bytes as
// blending everything, through target changes, FIX changes, partial tiles and strips.
#include "gs/tiled_blender.hpp"

#include <gtest/gtest.h>

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
