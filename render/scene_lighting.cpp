#include "render/scene_lighting.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lighting/error.hpp"
#include "render/error.hpp"

namespace vbim::render {

namespace {

float luminance(const float* rgb) {
  return 0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2];
}

// Below this direct term (stream units, luminance) a texel's sun visibility cannot be measured
// against the codec noise (one 8-bit step is ~0.004 at mid grey after sRGB decoding).
constexpr float kMinDirect = 0.03f;

}  // namespace

float srgbToLinear(std::uint8_t code) {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) {
      const double v = i / 255.0;
      t[static_cast<std::size_t>(i)] =
          static_cast<float>(v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4));
    }
    return t;
  }();
  return table[code];
}

SceneLighting::SceneLighting(lighting::Terrain terrain, const lighting::DayCycleParams& params, int loopFrame)
    : loopFrame_(loopFrame) {
  lighting::DayCycleParams p = params;
  p.clouds.enabled = false;  // cloud shadows are in the streamed lightmap; the prediction is cloud-free
  try {
    generator_ = std::make_unique<lighting::DayCycleGenerator>(std::move(terrain), p);
  } catch (const lighting::LightingError& e) {
    throw RenderError(std::string("lighting settings: ") + e.what());
  }
  if (loopFrame_ < 0 || loopFrame_ >= generator_->frameCount()) {
    throw RenderError("loop frame " + std::to_string(loopFrame_) + " is outside the day's " +
                      std::to_string(generator_->frameCount()) + " frames");
  }
  // A horizon below everything: the unshadowed prediction.
  openHorizon_.assign(this->terrain().texels(), -std::numeric_limits<float>::infinity());
}

int SceneLighting::frameOfSeq(std::int64_t seq) const {
  const std::int64_t f = generator_->frameCount();
  if (seq < 0) return 0;
  if (seq < f) return static_cast<int>(seq);
  return static_cast<int>(loopFrame_ + (seq - f) % (f - loopFrame_));
}

FrameLight SceneLighting::evaluate(std::int64_t seq, const Rgba8Image& lightmap, const Rgba8Image* sky) {
  const lighting::Terrain& t = terrain();
  if (lightmap.width != t.width || lightmap.height != t.height) {
    throw RenderError("the lightmap is " + std::to_string(lightmap.width) + "x" + std::to_string(lightmap.height) +
                      " but the terrain is " + std::to_string(t.width) + "x" + std::to_string(t.height) +
                      " (give the terrain the stream was authored from: --terrain, or --size for the procedural one)");
  }
  const int frame = frameOfSeq(seq);
  lighting::FrameLighting fl = generator_->frameLighting(frame);
  const lighting::DayCycleParams& p = params();
  const lighting::CloudLayer noClouds(lighting::CloudParams{});
  lighting::relight(generator_->precomputed(), fl, openHorizon_.data(), noClouds, p, lit_);
  lighting::FrameLighting skyOnlyLight = fl;
  skyOnlyLight.keyIrradiance = {0, 0, 0};
  lighting::relight(generator_->precomputed(), skyOnlyLight, openHorizon_.data(), noClouds, p, skyOnly_);

  FrameLight out;
  out.hour = fl.hour;
  const lighting::Dir3 d = fl.key.direction;  // (east, south, up) -> (x, y, z) = (east, up, south)
  out.sunDirection = {static_cast<float>(d.x), static_cast<float>(d.z), static_cast<float>(d.y)};
  out.width = t.width;
  out.height = t.height;

  // The stream's scale from the lit texels.
  const std::size_t n = t.texels();
  std::vector<float> decoded(n * 3);
  std::vector<float> ratios;
  ratios.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* px = lightmap.pixels.data() + i * 4;
    bool clipped = false;
    for (int c = 0; c < 3; ++c) {
      decoded[i * 3 + c] = srgbToLinear(px[c]);
      clipped = clipped || px[c] >= 250;
    }
    const float pred = luminance(&lit_.pixels[i * 3]);
    if (!clipped && pred > 0.02f) ratios.push_back(luminance(&decoded[i * 3]) / pred);
  }
  float a = 1.0f;
  if (ratios.size() >= n / 16 + 1) {
    const std::size_t q = ratios.size() * 3 / 4;
    std::nth_element(ratios.begin(), ratios.begin() + static_cast<std::ptrdiff_t>(q), ratios.end());
    a = std::max(ratios[q], 1e-3f);
  }
  out.streamScale = a;
  for (int c = 0; c < 3; ++c)
    out.sunIrradiance[static_cast<std::size_t>(c)] = a * fl.keyIrradiance[static_cast<std::size_t>(c)];

  out.sunVisibility.assign(n, 0.0f);
  for (std::size_t i = 0; i < n; ++i) {
    const float skyPart = a * luminance(&skyOnly_.pixels[i * 3]);
    const float direct = a * luminance(&lit_.pixels[i * 3]) - skyPart;
    if (direct < kMinDirect) continue;  // facing away from the sun, or the sun is down
    out.sunVisibility[i] = std::clamp((luminance(&decoded[i * 3]) - skyPart) / direct, 0.0f, 1.0f);
  }

  // Sky colour: cosine-weighted mean of the dome (row 0 = zenith, last row = horizon).
  if (sky != nullptr && sky->width > 0 && sky->height > 0) {
    double sum[3] = {0, 0, 0}, weight = 0;
    for (int y = 0; y < sky->height; ++y) {
      const double theta = (y + 0.5) / sky->height * (M_PI / 2);
      const double w = std::cos(theta) * std::sin(theta);
      for (int x = 0; x < sky->width; ++x) {
        const std::uint8_t* px = sky->pixels.data() + (static_cast<std::size_t>(y) * sky->width + x) * 4;
        for (int c = 0; c < 3; ++c) sum[c] += w * srgbToLinear(px[c]);
        weight += w;
      }
    }
    for (int c = 0; c < 3; ++c) out.skyIrradiance[static_cast<std::size_t>(c)] = static_cast<float>(sum[c] / weight);
  } else {
    for (int q = 0; q < p.skyPatches; ++q) {
      for (int c = 0; c < 3; ++c) {
        out.skyIrradiance[static_cast<std::size_t>(c)] +=
            a * fl.patch[static_cast<std::size_t>(q)][static_cast<std::size_t>(c)] / static_cast<float>(p.skyPatches);
      }
    }
  }
  return out;
}

}  // namespace vbim::render
