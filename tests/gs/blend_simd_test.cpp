// Every compiled SIMD target against the scalar reference: every (Cs, Cd, FIX) triple in both
// COLCLAMP and alpha modes, then random frames with odd lengths and offsets (the tails).
#include "gs/simd/blend_simd.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "runtime/rng.hpp"

namespace vbim::gs {
namespace {

bool isSampleFix(int fix) {
  return fix % 17 == 0 || fix == 1 || fix == 64 || fix == 127 || fix == 128 || fix == 129;
}

void allPairs(std::vector<std::uint8_t>& src, std::vector<std::uint8_t>& dst) {
  src.resize(65536 * 4);
  dst.resize(65536 * 4);
  for (int i = 0; i < 65536; ++i) {
    const int a = i & 0xFF, b = i >> 8;
    const std::uint8_t bytes[8] = {static_cast<std::uint8_t>(a),     static_cast<std::uint8_t>(b),
                                   static_cast<std::uint8_t>(a ^ b), static_cast<std::uint8_t>(i * 7),
                                   static_cast<std::uint8_t>(b),     static_cast<std::uint8_t>(a),
                                   static_cast<std::uint8_t>(b),     static_cast<std::uint8_t>(i * 13)};
    for (int c = 0; c < 4; ++c) src[4 * i + c] = bytes[c], dst[4 * i + c] = bytes[4 + c];
  }
}

TEST(BlendSimd, EveryTargetMatchesScalarOnEveryTriple) {
  std::vector<std::uint8_t> src, dst0;
  allPairs(src, dst0);
  std::set<std::string> targets;
  for (ColClamp cc : {ColClamp::Clamp, ColClamp::Wrap}) {
    for (AlphaWrite aw : {AlphaWrite::Source, AlphaWrite::Keep}) {
      for (int fix = 0; fix < 256; ++fix) {
        if (aw == AlphaWrite::Keep && !isSampleFix(fix)) continue;  // as in blend_test.cpp
        const BlendSpec spec = makeBlendSpec(fix, cc, aw);
        std::vector<std::uint8_t> want = dst0;
        const int wantDelta = blendSpanDeltaScalar(want.data(), src.data(), 65536, spec);
        simd::forEachTarget([&](const std::string& target) {
          if (target == "SCALAR") return;  // Highway's one-lane fallback runs the reference itself
          targets.insert(target);
          std::vector<std::uint8_t> got = dst0, gotDelta = dst0;
          simd::kernels().blend(got.data(), src.data(), 65536, spec);
          const int delta = simd::kernels().blendDelta(gotDelta.data(), src.data(), 65536, spec);
          if (got != want || gotDelta != want || delta != wantDelta) {
            ADD_FAILURE() << target << " differs from the scalar blend at fix " << fix;
          }
        });
        if (HasFailure()) return;
      }
    }
  }
  EXPECT_GE(targets.size(), 1u);
  std::string names;
  for (const auto& t : targets) names += t + " ";
  RecordProperty("targets", names);
  std::printf("SIMD targets tested: %s(dispatch picks %s)\n", names.c_str(), simd::kernels().name);
}

// spanAtFixedPoint is what lets a blender skip a row: wherever it says a pixel is at its fixed
// point, blending it again changes nothing, for every (Cs, Cd, FIX) and mode. And where it says
// not, the next blend does change it, except a Wrap-mode step of a whole 256 (FIX > 128).
TEST(BlendSimd, FixedPointTestIsSafeAndExactForEveryTriple) {
  std::vector<std::uint8_t> src, dst0;
  allPairs(src, dst0);
  for (ColClamp cc : {ColClamp::Clamp, ColClamp::Wrap}) {
    for (AlphaWrite aw : {AlphaWrite::Source, AlphaWrite::Keep}) {
      for (int fix = 0; fix < 256; ++fix) {
        const BlendSpec spec = makeBlendSpec(fix, cc, aw);
        for (int i = 0; i < 65536; ++i) {
          const std::uint8_t* s = src.data() + 4 * i;
          std::uint8_t d[4] = {dst0[4 * i], dst0[4 * i + 1], dst0[4 * i + 2], dst0[4 * i + 3]};
          const bool fixed = spanAtFixedPoint(d, s, 1, spec);
          const bool moved = blendSpanDeltaScalar(d, s, 1, spec) != 0;
          if (fixed && moved) FAIL() << "fixed point moved: fix " << fix << " pixel " << i;
          if (!fixed && !moved && !(cc == ColClamp::Wrap && fix > 128))
            FAIL() << "not a fixed point, yet nothing moved: fix " << fix << " pixel " << i;
        }
      }
    }
  }
}

TEST(BlendSimd, EveryTargetMatchesScalarOnRandomFrames) {
  Rng rng(6);
  simd::forEachTarget([&](const std::string& target) {
    for (int round = 0; round < 40; ++round) {
      const std::size_t pixels = 1 + rng.below(3000);
      const std::size_t offset = rng.below(17);  // unaligned starts
      std::vector<std::uint8_t> src((pixels + offset) * 4), dst((pixels + offset) * 4);
      for (auto& b : src) b = static_cast<std::uint8_t>(rng.below(256));
      for (auto& b : dst) b = static_cast<std::uint8_t>(rng.below(256));
      const BlendSpec spec =
          makeBlendSpec(static_cast<std::int64_t>(rng.below(256)), rng.chance(1, 2) ? ColClamp::Clamp : ColClamp::Wrap,
                        rng.chance(1, 2) ? AlphaWrite::Source : AlphaWrite::Keep);
      std::vector<std::uint8_t> want = dst, got = dst;
      const int wd = blendSpanDeltaScalar(want.data() + 4 * offset, src.data() + 4 * offset, pixels, spec);
      const int gd = simd::kernels().blendDelta(got.data() + 4 * offset, src.data() + 4 * offset, pixels, spec);
      ASSERT_EQ(got, want) << target << " pixels " << pixels << " offset " << offset;
      ASSERT_EQ(gd, wd) << target;
    }
  });
}

// Tiles: rows of a wider image (strides in bytes, not a multiple of the vector), odd widths, one
// row, and a change that sits only in the last row (the reduction must see every row).
TEST(BlendSimd, EveryTargetMatchesScalarOnRectangles) {
  Rng rng(7);
  simd::forEachTarget([&](const std::string& target) {
    for (int round = 0; round < 60; ++round) {
      const std::size_t pixels = 1 + rng.below(90);
      const std::size_t rows = 1 + rng.below(33);
      const std::size_t dstStride = 4 * (pixels + rng.below(9));
      const std::size_t srcStride = 4 * (pixels + rng.below(9));
      std::vector<std::uint8_t> src(srcStride * rows), dst(dstStride * rows);
      for (auto& b : src) b = static_cast<std::uint8_t>(rng.below(256));
      if (round % 3 == 0) {
        // Converged everywhere but one pixel of the last row.
        for (std::size_t y = 0; y < rows; ++y)
          std::copy_n(src.begin() + static_cast<std::ptrdiff_t>(y * srcStride), 4 * pixels,
                      dst.begin() + static_cast<std::ptrdiff_t>(y * dstStride));
        dst[(rows - 1) * dstStride + 4 * rng.below(pixels)] ^= 0x5A;
      } else {
        for (auto& b : dst) b = static_cast<std::uint8_t>(rng.below(256));
      }
      // FIX 64 (the default step, its own kernel) in a quarter of the rounds.
      const std::int64_t fix = round % 4 == 1 ? 64 : static_cast<std::int64_t>(rng.below(256));
      const BlendSpec spec = makeBlendSpec(fix, rng.chance(1, 2) ? ColClamp::Clamp : ColClamp::Wrap,
                                           rng.chance(1, 2) ? AlphaWrite::Source : AlphaWrite::Keep);
      std::vector<std::uint8_t> want = dst, got = dst;
      const int wd = blendRectDeltaScalar(want.data(), dstStride, src.data(), srcStride, pixels, rows, spec, nullptr);
      const int gd =
          simd::kernels().blendRectDelta(got.data(), dstStride, src.data(), srcStride, pixels, rows, spec, nullptr);
      ASSERT_EQ(got, want) << target << " " << pixels << "x" << rows << " strides " << dstStride << "/" << srcStride;
      ASSERT_EQ(gd, wd) << target;
      if (rows <= 32) {
        // With a settled-row mask (random rows marked settled): the same rows skipped and the same
        // rows marked, three blends in a row.
        const std::uint32_t start =
            static_cast<std::uint32_t>(rng.below(1u << 16)) & ((rows == 32 ? 0u : 1u << rows) - 1u);
        std::uint32_t wantMask = start, gotMask = start;
        std::vector<std::uint8_t> wantM = dst, gotM = dst;
        for (int pass = 0; pass < 3; ++pass) {
          const int wdm =
              blendRectDeltaScalar(wantM.data(), dstStride, src.data(), srcStride, pixels, rows, spec, &wantMask);
          const int gdm = simd::kernels().blendRectDelta(gotM.data(), dstStride, src.data(), srcStride, pixels, rows,
                                                         spec, &gotMask);
          ASSERT_EQ(gotM, wantM) << target << " pass " << pass;
          ASSERT_EQ(gdm, wdm) << target << " pass " << pass;
          ASSERT_EQ(gotMask, wantMask) << target << " pass " << pass << " fix " << int(spec.fix);
        }
      }
      // The scalar rectangle is its rows.
      std::vector<std::uint8_t> rowwise = dst;
      int rd = 0;
      for (std::size_t y = 0; y < rows; ++y) {
        rd = std::max(rd,
                      blendSpanDeltaScalar(rowwise.data() + y * dstStride, src.data() + y * srcStride, pixels, spec));
      }
      ASSERT_EQ(rowwise, want);
      ASSERT_EQ(rd, wd);
    }
  });
}

// The blend and the frame hash's chain in one pass (BlendHashRowsFn): every target against the
// scalar reference (each tile's blendRectDelta, then the rows into the chain), on image widths that
// are odd, even, a multiple of the tile or not, tile widths of 64 and others, random settled masks,
// chains starting at every phase (words before the rows mod 4), and without a chain.
TEST(BlendSimd, BlendHashRowsMatchesScalarOnEveryTarget) {
  Rng rng(31);
  simd::forEachTarget([&](const std::string& target) {
    for (int round = 0; round < 120; ++round) {
      const std::size_t pixels = 1 + rng.below(round % 2 == 0 ? 300 : 70);
      const std::size_t rows = 1 + rng.below(32);
      const std::size_t tilePixels = round % 3 == 0 ? 1 + rng.below(40) : 64;
      const std::size_t tiles = (pixels + tilePixels - 1) / tilePixels;
      std::vector<std::uint8_t> src(4 * pixels * rows), dst(4 * pixels * rows);
      for (auto& b : src) b = static_cast<std::uint8_t>(rng.below(256));
      for (std::size_t i = 0; i < dst.size(); ++i) {
        // Half the rounds close to the target, so that rows settle.
        dst[i] = round % 2 == 0 ? static_cast<std::uint8_t>(rng.below(256))
                                : static_cast<std::uint8_t>(src[i] - (rng.chance(1, 8) ? 1 : 0));
      }
      const std::int64_t fix = round % 4 == 1 ? 64 : static_cast<std::int64_t>(rng.below(256));
      const BlendSpec spec = makeBlendSpec(fix, rng.chance(1, 2) ? ColClamp::Clamp : ColClamp::Wrap,
                                           rng.chance(1, 2) ? AlphaWrite::Source : AlphaWrite::Keep);
      HashChain start;
      for (std::uint64_t k = rng.below(7); k > 0; --k) start.word(rng.below(1u << 30));
      std::vector<std::uint32_t> wantMask(tiles), gotMask(tiles);
      for (std::size_t t = 0; t < tiles; ++t) {
        wantMask[t] = gotMask[t] =
            static_cast<std::uint32_t>(rng.below(1u << 16)) & static_cast<std::uint32_t>(rng.below(1u << 16));
      }
      std::vector<int> wantDelta(tiles, 0), gotDelta(tiles, 0);
      std::vector<std::uint8_t> want = dst, got = dst;
      const bool withChain = round % 5 != 4;
      HashChain wantChain = start, gotChain = start;
      for (int pass = 0; pass < 2; ++pass) {
        blendHashRowsScalar(want.data(), src.data(), pixels, rows, tilePixels, spec, wantMask.data(), wantDelta.data(),
                            withChain ? &wantChain : nullptr);
        simd::kernels().blendHashRows(got.data(), src.data(), pixels, rows, tilePixels, spec, gotMask.data(),
                                      gotDelta.data(), withChain ? &gotChain : nullptr);
        const auto where = [&] {
          return target + " " + std::to_string(pixels) + "x" + std::to_string(rows) + " tile " +
                 std::to_string(tilePixels) + " fix " + std::to_string(spec.fix) + " pass " + std::to_string(pass);
        };
        ASSERT_EQ(got, want) << where();
        ASSERT_EQ(gotMask, wantMask) << where();
        ASSERT_EQ(gotDelta, wantDelta) << where();
        ASSERT_EQ(gotChain.count, wantChain.count) << where();
        for (int l = 0; l < 4; ++l) ASSERT_EQ(gotChain.lanes[l], wantChain.lanes[l]) << where() << " lane " << l;
      }
      // The reference is what it says: each tile's rectangle, then the rows' bytes into the chain.
      std::vector<std::uint8_t> byTile = dst;
      std::vector<std::uint32_t> tileMask(tiles);
      for (std::size_t t = 0; t < tiles; ++t) tileMask[t] = 0;
      HashChain byTileChain = start;
      std::vector<std::uint8_t> viaKernel = dst;
      std::vector<std::uint32_t> kernelMask(tiles, 0);
      std::vector<int> kernelDelta(tiles, 0);
      HashChain kernelChain = start;
      blendHashRowsScalar(viaKernel.data(), src.data(), pixels, rows, tilePixels, spec, kernelMask.data(),
                          kernelDelta.data(), &kernelChain);
      for (std::size_t t = 0; t < tiles; ++t) {
        const std::size_t x0 = t * tilePixels;
        const int d = blendRectDeltaScalar(byTile.data() + 4 * x0, 4 * pixels, src.data() + 4 * x0, 4 * pixels,
                                           std::min(tilePixels, pixels - x0), rows, spec, &tileMask[t]);
        ASSERT_EQ(kernelDelta[t], d);
      }
      byTileChain.addBytes(byTile.data(), byTile.size());
      ASSERT_EQ(viaKernel, byTile);
      ASSERT_EQ(kernelMask, tileMask);
      ASSERT_EQ(kernelChain.count, byTileChain.count);
      for (int l = 0; l < 4; ++l) ASSERT_EQ(kernelChain.lanes[l], byTileChain.lanes[l]);
    }
  });
}

// The fused kernel at the shapes a play gives it, which the random rounds above do not reach:
// 512-pixel rows of eight 64-pixel tiles (a 512x512 lightmap's tile row) and rows of exactly 64
// tiles (the most the kernel takes before it hands a row to the scalar reference), blended several
// times toward the same frame so that rows settle unevenly from tile to tile and pass to pass, then
// toward a new frame; every target against the scalar reference, the chain's lanes included.
TEST(BlendSimd, BlendHashRowsMatchesScalarOnPlayShapes) {
  Rng rng(512);
  simd::forEachTarget([&](const std::string& target) {
    for (int round = 0; round < 12; ++round) {
      const std::size_t tilePixels = round % 3 == 2 ? 8 : 64;
      const std::size_t pixels = round % 3 == 2 ? 64 * tilePixels : 512;
      const std::size_t tiles = pixels / tilePixels;
      const std::size_t rows = round % 4 == 3 ? 1 + rng.below(32) : 32;
      std::vector<std::uint8_t> src(4 * pixels * rows), dst(4 * pixels * rows);
      for (auto& b : src) b = static_cast<std::uint8_t>(rng.below(256));
      // Each tile its own distance from the target (0 to 255 in steps of powers of two), so that
      // tiles settle after different numbers of blends.
      for (std::size_t i = 0; i < dst.size(); ++i) {
        const std::size_t tile = i / 4 % pixels / tilePixels;
        const int spread = (1 << (tile % 9)) - 1;
        dst[i] =
            static_cast<std::uint8_t>(src[i] + static_cast<int>(rng.below(static_cast<std::uint64_t>(spread) + 1)));
      }
      const std::int64_t fix = round % 2 == 0 ? 64 : 1 + static_cast<std::int64_t>(rng.below(200));
      const BlendSpec spec =
          makeBlendSpec(fix, ColClamp::Clamp, round % 4 == 1 ? AlphaWrite::Keep : AlphaWrite::Source);
      std::vector<std::uint32_t> wantMask(tiles, 0), gotMask(tiles, 0);
      std::vector<std::uint8_t> want = dst, got = dst;
      HashChain wantChain, gotChain;
      wantChain.addHeader(static_cast<int>(pixels), static_cast<int>(rows));
      gotChain = wantChain;
      for (int pass = 0; pass < 10; ++pass) {
        const std::vector<std::uint8_t>* toward = &src;
        std::vector<std::uint8_t> other;
        if (pass == 8) {  // a new frame: the marks start again
          other.resize(src.size());
          for (auto& b : other) b = static_cast<std::uint8_t>(rng.below(256));
          toward = &other;
          std::fill(wantMask.begin(), wantMask.end(), 0u);
          std::fill(gotMask.begin(), gotMask.end(), 0u);
        }
        std::vector<int> wantDelta(tiles, 0), gotDelta(tiles, 0);
        blendHashRowsScalar(want.data(), toward->data(), pixels, rows, tilePixels, spec, wantMask.data(),
                            wantDelta.data(), &wantChain);
        simd::kernels().blendHashRows(got.data(), toward->data(), pixels, rows, tilePixels, spec, gotMask.data(),
                                      gotDelta.data(), &gotChain);
        const std::string where = target + " " + std::to_string(pixels) + "x" + std::to_string(rows) + " fix " +
                                  std::to_string(fix) + " pass " + std::to_string(pass);
        ASSERT_EQ(got, want) << where;
        ASSERT_EQ(gotMask, wantMask) << where;
        ASSERT_EQ(gotDelta, wantDelta) << where;
        ASSERT_EQ(gotChain.count, wantChain.count) << where;
        for (int l = 0; l < 4; ++l) ASSERT_EQ(gotChain.lanes[l], wantChain.lanes[l]) << where << " lane " << l;
        if (pass == 3 && fix == 64) {  // the case meant: some tiles settled, some still moving
          const std::uint32_t all = rows == 32 ? ~std::uint32_t{0} : (std::uint32_t{1} << rows) - 1;
          const auto settledTiles = std::count(gotMask.begin(), gotMask.end(), all);
          EXPECT_GT(settledTiles, 0) << where;
          EXPECT_LT(settledTiles, static_cast<std::ptrdiff_t>(tiles)) << where;
        }
      }
    }
  });
}

// FIX 64 has its own change and fixed-point test in the kernels (HalfChange, gs/simd/blend_simd.cpp):
// every (Cs, Cd) pair in every byte of a pixel, each pair alone in its tile of a one-row image among
// bytes at their fixed point, so that a tile's change and its row's settled mark are that pair's
// alone; the fused blend + hash and the tile blend of every target against the scalar reference.
TEST(BlendSimd, HalfBlendChangeAndFixedPointMatchScalarOnEveryPair) {
  constexpr std::size_t kTile = 64, kTiles = 8, kPixels = kTile * kTiles;
  std::vector<std::uint8_t> src(4 * kPixels), dst(4 * kPixels);
  simd::forEachTarget([&](const std::string& target) {
    for (const AlphaWrite aw : {AlphaWrite::Source, AlphaWrite::Keep}) {
      const BlendSpec spec = makeBlendSpec(64, ColClamp::Clamp, aw);
      for (int channel = 0; channel < 4; ++channel) {
        for (int first = 0; first < 65536; first += static_cast<int>(kTiles)) {
          for (std::size_t i = 0; i < src.size(); ++i) src[i] = dst[i] = static_cast<std::uint8_t>(i * 37);
          for (std::size_t t = 0; t < kTiles; ++t) {
            const int pair = first + static_cast<int>(t);
            const std::size_t x = t * kTile + static_cast<std::size_t>(pair / static_cast<int>(kTiles)) % kTile;
            src[4 * x + static_cast<std::size_t>(channel)] = static_cast<std::uint8_t>(pair & 0xFF);
            dst[4 * x + static_cast<std::size_t>(channel)] = static_cast<std::uint8_t>(pair >> 8);
          }
          std::vector<std::uint8_t> want = dst, got = dst, gotTiles = dst;
          std::vector<std::uint32_t> wantMask(kTiles, 0), gotMask(kTiles, 0), tileMask(kTiles, 0);
          std::vector<int> wantDelta(kTiles, 0), gotDelta(kTiles, 0);
          HashChain wantChain, gotChain;
          blendHashRowsScalar(want.data(), src.data(), kPixels, 1, kTile, spec, wantMask.data(), wantDelta.data(),
                              &wantChain);
          simd::kernels().blendHashRows(got.data(), src.data(), kPixels, 1, kTile, spec, gotMask.data(),
                                        gotDelta.data(), &gotChain);
          const auto where = [&] {
            return target + " channel " + std::to_string(channel) + " pairs from " + std::to_string(first) +
                   (aw == AlphaWrite::Keep ? " alpha kept" : "");
          };
          ASSERT_EQ(got, want) << where();
          ASSERT_EQ(gotDelta, wantDelta) << where();
          ASSERT_EQ(gotMask, wantMask) << where();
          ASSERT_EQ(gotChain.lanes[0], wantChain.lanes[0]) << where();
          for (std::size_t t = 0; t < kTiles; ++t) {
            const int d =
                simd::kernels().blendRectDelta(gotTiles.data() + 4 * t * kTile, 4 * kPixels, src.data() + 4 * t * kTile,
                                               4 * kPixels, kTile, 1, spec, &tileMask[t]);
            ASSERT_EQ(d, wantDelta[t]) << where() << " tile " << t;
          }
          ASSERT_EQ(gotTiles, want) << where();
          ASSERT_EQ(tileMask, wantMask) << where();
        }
      }
    }
  });
}

TEST(BlendSimd, DispatchNamesATarget) {
  const std::string name = simd::kernels().name;
  EXPECT_FALSE(name.empty());
  EXPECT_NE(name, "scalar");
}

}  // namespace
}  // namespace vbim::gs
