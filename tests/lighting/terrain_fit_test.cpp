// Fitting a terrain to whole 16x16 macroblocks (lighting/terrain_fit.hpp): crops and pads are centred,
// pads repeat the edges, the georeference moves with the window, and colour maps on another grid
// are resampled exactly where the mapping says.
#include "lighting/terrain_fit.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lighting/error.hpp"

namespace vbim::lighting {
namespace {

// Heights in units: 1000 * row + column, so every texel says where it came from.
Terrain numbered(int w, int h) {
  Terrain t;
  t.width = w;
  t.height = h;
  t.heights.resize(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) t.heights[static_cast<std::size_t>(y) * w + x] = 1000 * y + x;
  return t;
}

TEST(TerrainFit, CropIsCentredWithTheOddTexelEastAndSouth) {
  const GridWindow w = fitWindow(95, 139, TerrainFit::Crop, "dem.tif");
  EXPECT_EQ(w.width, 80);  // 15 texels off: 7 west, 8 east
  EXPECT_EQ(w.x0, 7);
  EXPECT_EQ(w.height, 128);  // 11 off: 5 north, 6 south
  EXPECT_EQ(w.y0, 5);
  const Terrain t = windowTerrain(numbered(95, 139), w);
  EXPECT_EQ(t.width, 80);
  EXPECT_EQ(t.at(0, 0), 5 * 1000 + 7);
  EXPECT_EQ(t.at(79, 127), 132 * 1000 + 86);
}

TEST(TerrainFit, PadIsCentredAndRepeatsTheEdges) {
  const GridWindow w = fitWindow(93, 32, TerrainFit::Pad, "dem.tif");
  EXPECT_EQ(w.width, 96);  // 3 texels added: 1 west, 2 east
  EXPECT_EQ(w.x0, -1);
  EXPECT_EQ(w.height, 32);  // already whole macroblocks
  EXPECT_EQ(w.y0, 0);
  Terrain src = numbered(93, 32);
  src.albedo = FloatImage(93, 32, 3);
  for (int x = 0; x < 93; ++x) src.albedo.at(x, 3)[1] = static_cast<float>(x);
  const Terrain t = windowTerrain(src, w);
  EXPECT_EQ(t.at(0, 3), 3000);  // the west edge repeated
  EXPECT_EQ(t.at(1, 3), 3000);
  EXPECT_EQ(t.at(2, 3), 3001);
  EXPECT_EQ(t.at(94, 3), 3092);
  EXPECT_EQ(t.at(95, 3), 3092);  // the east edge repeated twice
  ASSERT_EQ(t.albedo.width, 96);
  EXPECT_EQ(t.albedo.at(0, 3)[1], 0.0f);
  EXPECT_EQ(t.albedo.at(50, 3)[1], 49.0f);
  EXPECT_EQ(t.albedo.at(95, 3)[1], 92.0f);
}

TEST(TerrainFit, WholeMacroblocksAndNoneAreLeftAlone) {
  for (const TerrainFit fit : {TerrainFit::Crop, TerrainFit::Pad}) {
    const GridWindow w = fitWindow(64, 48, fit, "hf.png");
    EXPECT_EQ(w.x0, 0);
    EXPECT_EQ(w.y0, 0);
    EXPECT_EQ(w.width, 64);
    EXPECT_EQ(w.height, 48);
  }
  const GridWindow w = fitWindow(95, 139, TerrainFit::None, "dem.tif");
  EXPECT_EQ(w.width, 95);
  EXPECT_EQ(w.height, 139);
}

TEST(TerrainFit, TooShortToCropIsRefusedWithTheWayOut) {
  try {
    fitWindow(64, 12, TerrainFit::Crop, "strip.tif");
    FAIL();
  } catch (const LightingError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("strip.tif: the height is 12 texels"), std::string::npos) << what;
    EXPECT_NE(what.find("pad"), std::string::npos) << what;
  }
  EXPECT_EQ(fitWindow(64, 12, TerrainFit::Pad, "strip.tif").height, 16);
  EXPECT_EQ(parseTerrainFit("pad", "--terrain-fit"), TerrainFit::Pad);
  EXPECT_THROW(parseTerrainFit("stretch", "--terrain-fit"), LightingError);
}

TEST(TerrainFit, TheGeoreferenceMovesWithTheWindow) {
  const Georeference geo{{6.0, 0.01, 0, 50.0, 0, -0.02}, "WKT"};
  const Georeference cropped = windowGeoreference(geo, {7, 5, 80, 128});
  EXPECT_NEAR(cropped.geoTransform[0], 6.07, 1e-12);  // the west edge of column 7
  EXPECT_NEAR(cropped.geoTransform[3], 49.9, 1e-12);  // the north edge of row 5
  EXPECT_DOUBLE_EQ(cropped.geoTransform[1], 0.01);    // cells unchanged
  EXPECT_DOUBLE_EQ(cropped.geoTransform[5], -0.02);
  EXPECT_EQ(cropped.srsWkt, "WKT");
  const Georeference padded = windowGeoreference(geo, {-1, -2, 96, 32});
  EXPECT_NEAR(padded.geoTransform[0], 5.99, 1e-12);
  EXPECT_NEAR(padded.geoTransform[3], 50.04, 1e-12);
}

TEST(TerrainFit, ResamplingFollowsTheMapping) {
  FloatImage src(4, 3, 1);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) src.at(x, y)[0] = static_cast<float>(10 * y + x);
  // Identity, and the window's offset on top of it: exact copies.
  const FloatImage same = resampleImage(src, {}, 4, 3);
  EXPECT_EQ(same.pixels, src.pixels);
  const FloatImage shifted = resampleImage(src, windowMapping({}, {1, 1, 2, 2}), 2, 2);
  EXPECT_EQ(shifted.pixels, (std::vector<float>{11, 12, 21, 22}));
  // Flipped columns, half steps down the rows (bilinear between rows), clamped past the edges.
  const FloatImage flipped = resampleImage(src, {3, -1, 0, 0.5}, 5, 5);
  EXPECT_FLOAT_EQ(flipped.at(0, 0)[0], 3.0f);
  EXPECT_FLOAT_EQ(flipped.at(3, 1)[0], 5.0f);   // column 0, row 0.5
  EXPECT_FLOAT_EQ(flipped.at(4, 4)[0], 20.0f);  // clamped to column 0, row 2
}

}  // namespace
}  // namespace vbim::lighting
