#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "render/error.hpp"
#include "render/renderer.hpp"
#include "render/scene_lighting.hpp"
#include "render_test_scene.hpp"

namespace vbim::render {
namespace {

// Noon of the small scene (frame 12 of 24 = 12 h). Regenerate after an intended change of the
// picture: run render_tests --gtest_filter=RenderGolden.* and copy the printed hash.
constexpr std::uint64_t kGoldenNoon = 0x79becdedf1abf57bULL;

TEST(RenderGolden, NoonPictureIsBitExact) {
  const lighting::Terrain terrain = test::smallTerrain();
  const test::StreamedFrame f = test::streamedFrame(12);
  SceneLighting lighting(terrain, test::smallDay());
  Renderer renderer(lighting.terrain(), terrain.albedo, test::smallSettings());
  const FrameLight light = lighting.evaluate(12, f.lightmap, &f.sky);
  const Rgba8Image a = renderer.render(f.lightmap, &f.sky, light);
  const Rgba8Image b = renderer.render(f.lightmap, &f.sky, light);
  EXPECT_EQ(test::hashImage(a), test::hashImage(b)) << "two renders of the same frame differ";
  const char* threads = std::getenv("LP_NUM_THREADS");
  std::printf("noon picture hash 0x%016llx (LP_NUM_THREADS=%s)\n", static_cast<unsigned long long>(test::hashImage(a)),
              threads ? threads : "unset");
  EXPECT_EQ(test::hashImage(a), kGoldenNoon);
  // Not a blank picture: sky at the top, terrain at the bottom, different colours.
  const std::uint8_t* top = a.row(2) + 48 * 4;
  const std::uint8_t* bottom = a.row(60) + 48 * 4;
  EXPECT_GT(top[2], top[0]) << "the sky should be blue";
  EXPECT_GT(bottom[1], bottom[2]) << "the valley grass should be green";
}

// Mean luminance of the pixels where the objects are (where a render with them differs from one without).
struct ObjectPixels {
  double mean = 0;
  int count = 0;
};

ObjectPixels objectBrightness(const Rgba8Image& with, const Rgba8Image& without) {
  ObjectPixels r;
  double sum = 0;
  for (std::size_t i = 0; i < with.pixels.size(); i += 4) {
    if (with.pixels[i] == without.pixels[i] && with.pixels[i + 1] == without.pixels[i + 1] &&
        with.pixels[i + 2] == without.pixels[i + 2])
      continue;
    sum += 0.2126 * with.pixels[i] + 0.7152 * with.pixels[i + 1] + 0.0722 * with.pixels[i + 2];
    ++r.count;
  }
  r.mean = r.count ? sum / r.count : 0;
  return r;
}

TEST(RenderObjects, DarkerUnderAShadowedTexelThanUnderALitOne) {
  const lighting::Terrain terrain = test::smallTerrain();
  const test::StreamedFrame lit = test::streamedFrame(10);  // 10 h: sun high in the south-east
  SceneLighting lighting(terrain, test::smallDay());
  RenderSettings s = test::smallSettings();
  s.width = 192;
  s.height = 128;
  Renderer withObjects(lighting.terrain(), terrain.albedo, s);
  s.objects = false;
  Renderer without(lighting.terrain(), terrain.albedo, s);

  // The same frame with the terrain around the objects in shadow: those texels keep only the sky
  // term, as the generator writes a shadowed texel (its sky part is what the lightmap holds at night
  // of the sun: here, a fifth of the lit value is a safe upper bound for the sky share at 10 h).
  Rgba8Image shadowed = lit.lightmap;
  const double cell = terrain.cellSize;
  int darkened = 0;
  for (const auto& p : withObjects.objectPositions()) {
    const int cx = static_cast<int>(std::lround(p[0] / cell)), cz = static_cast<int>(std::lround(p[2] / cell));
    for (int z = cz - 3; z <= cz + 3; ++z) {
      for (int x = cx - 3; x <= cx + 3; ++x) {
        if (x < 0 || z < 0 || x >= terrain.width || z >= terrain.height) continue;
        std::uint8_t* px = shadowed.row(z) + x * 4;
        for (int c = 0; c < 3; ++c) px[c] = static_cast<std::uint8_t>(px[c] * 0.45);  // sRGB 0.45 ~ linear 0.17
        ++darkened;
      }
    }
  }
  ASSERT_GT(darkened, 0);
  const FrameLight lightLit = lighting.evaluate(10, lit.lightmap, &lit.sky);
  const FrameLight lightShadowed = lighting.evaluate(10, shadowed, &lit.sky);
  const ObjectPixels a = objectBrightness(withObjects.render(lit.lightmap, &lit.sky, lightLit),
                                          without.render(lit.lightmap, &lit.sky, lightLit));
  const ObjectPixels b = objectBrightness(withObjects.render(shadowed, &lit.sky, lightShadowed),
                                          without.render(shadowed, &lit.sky, lightShadowed));
  ASSERT_GT(a.count, 50) << "the objects should cover some pixels";
  EXPECT_LT(b.mean, a.mean * 0.8) << "objects under shadowed texels: " << b.mean << ", under lit ones: " << a.mean;
}

TEST(RenderBadInput, NoGlContext) {
  const lighting::Terrain terrain = test::smallTerrain();
  const GlContextFactory failing = []() -> std::unique_ptr<GlContext> {
    throw RenderError("no GL context available: simulated failure");
  };
  try {
    Renderer r(terrain, terrain.albedo, test::smallSettings(), failing);
    FAIL() << "expected RenderError";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("no GL context"), std::string::npos) << e.what();
  }
  const GlContextFactory empty = []() -> std::unique_ptr<GlContext> { return nullptr; };
  EXPECT_THROW(Renderer(terrain, terrain.albedo, test::smallSettings(), empty), RenderError);
}

TEST(RenderBadInput, CameraOutsideTheTerrain) {
  const lighting::Terrain terrain = test::smallTerrain();
  RenderSettings s = test::smallSettings();
  s.camera = parseCamera("5000,100,50,600,600");  // the map is 1260 m wide
  try {
    Renderer r(terrain, terrain.albedo, s);
    FAIL() << "expected RenderError";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("outside the terrain"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parseCamera("1,2,3"), RenderError);
  EXPECT_THROW(parseCamera("1,2,x,4,5"), RenderError);
  EXPECT_THROW(parseCamera("1,2,-3,4,5"), RenderError);
}

TEST(RenderBadInput, LightmapOfAnotherSize) {
  const lighting::Terrain terrain = test::smallTerrain();
  SceneLighting lighting(terrain, test::smallDay());
  const Rgba8Image wrong(32, 32);
  EXPECT_THROW(lighting.evaluate(3, wrong, nullptr), RenderError);
}

}  // namespace
}  // namespace vbim::render
