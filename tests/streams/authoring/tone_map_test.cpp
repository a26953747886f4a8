#include <gtest/gtest.h>

#include "streams/authoring/error.hpp"
#include "streams/authoring/synthetic_day.hpp"
#include "streams/authoring/tone_map.hpp"

namespace vbim::streams {
namespace {

std::array<int, 3> mapOne(float v, const ToneMapping& m) {
  FloatRgbImage img(1, 1);
  img.rgb = {v, v * 2, v * 4};
  const Rgba8Image out = toneMap(img, m);
  return {out.pixels[0], out.pixels[1], out.pixels[2]};
}

TEST(StreamsToneMap, DefaultIsClampThenSrgbTo255) {
  ToneMapping m;
  EXPECT_EQ(mapOne(0.0f, m)[0], 0);
  EXPECT_EQ(mapOne(0.18f, m)[0], 118);  // sRGB(0.18) = 0.4613
  EXPECT_EQ(mapOne(0.5f, m)[0], 188);   // sRGB(0.5) = 0.7354
  EXPECT_EQ(mapOne(0.5f, m)[1], 255);   // 1.0
  EXPECT_EQ(mapOne(0.5f, m)[2], 255);   // 2.0 clamps
}

TEST(StreamsToneMap, ExposureCurveTransferAndWhiteAreApplied) {
  ToneMapping m;
  m.transfer = ToneMapping::Transfer::Linear;
  m.white = 128;  // the GS's 1.0
  EXPECT_EQ(mapOne(0.5f, m)[0], 64);
  m.exposure = 1;  // x2
  EXPECT_EQ(mapOne(0.25f, m)[0], 64);
  m.exposure = 0;
  m.curve = ToneMapping::Curve::Reinhard;
  EXPECT_EQ(mapOne(1.0f, m)[0], 64);   // 1/(1+1)
  EXPECT_EQ(mapOne(1.0f, m)[2], 102);  // 4/5
  parseTransfer("gamma:2", m);
  m.curve = ToneMapping::Curve::Clamp;
  EXPECT_EQ(mapOne(0.25f, m)[0], 64);  // sqrt
  EXPECT_THROW(parseTransfer("gamma:x", m), AuthoringError);
  EXPECT_THROW(parseCurve("aces"), AuthoringError);
  EXPECT_EQ(parseCurve("filmic"), ToneMapping::Curve::Filmic);
}

TEST(StreamsSyntheticDay, IsDeterministicDarkAtNightBrightAtNoonAndWeatherDiffers) {
  SyntheticDay d;
  d.width = d.height = 32;
  d.skyWidth = 32;
  d.skyHeight = 16;
  d.frames = 8;
  auto mean = [](const FloatRgbImage& img) {
    double s = 0;
    for (float v : img.rgb) s += v;
    return s / img.rgb.size();
  };
  EXPECT_EQ(syntheticLightmap(d, 3).rgb, syntheticLightmap(d, 3).rgb);
  EXPECT_LT(mean(syntheticLightmap(d, 0)) * 5, mean(syntheticLightmap(d, 4)));
  SyntheticDay o = d;
  o.weather = "overcast";
  EXPECT_NE(mean(syntheticLightmap(o, 4)), mean(syntheticLightmap(d, 4)));
  o.weather = "snow";
  EXPECT_THROW(syntheticLightmap(o, 0), AuthoringError);
}

}  // namespace
}  // namespace vbim::streams
