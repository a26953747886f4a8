#include "streams/authoring/tone_map.hpp"

#include <algorithm>
#include <cmath>

#include "streams/authoring/error.hpp"

namespace vbim::streams {

namespace {

double applyCurve(double x, ToneMapping::Curve c) {
  x = std::max(0.0, x);
  switch (c) {
    case ToneMapping::Curve::Clamp:
      return std::min(1.0, x);
    case ToneMapping::Curve::Reinhard:
      return x / (1.0 + x);
    case ToneMapping::Curve::Filmic:  // Narkowicz's fit of the ACES reference rendering transform
      return std::clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
  }
  return x;
}

double applyTransfer(double x, const ToneMapping& m) {
  switch (m.transfer) {
    case ToneMapping::Transfer::Srgb:  // IEC 61966-2-1
      return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
    case ToneMapping::Transfer::Linear:
      return x;
    case ToneMapping::Transfer::Gamma:
      return std::pow(x, 1.0 / m.gamma);
  }
  return x;
}

std::uint8_t toCode(double v) {
  return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L));
}

}  // namespace

ToneMapping::Curve parseCurve(const std::string& s) {
  if (s == "clamp") return ToneMapping::Curve::Clamp;
  if (s == "reinhard") return ToneMapping::Curve::Reinhard;
  if (s == "filmic") return ToneMapping::Curve::Filmic;
  throw AuthoringError("tone curve '" + s + "': expected clamp, reinhard or filmic");
}

void parseTransfer(const std::string& s, ToneMapping& m) {
  if (s == "srgb") {
    m.transfer = ToneMapping::Transfer::Srgb;
  } else if (s == "linear") {
    m.transfer = ToneMapping::Transfer::Linear;
  } else if (s.rfind("gamma:", 0) == 0) {
    m.transfer = ToneMapping::Transfer::Gamma;
    try {
      m.gamma = std::stod(s.substr(6));
    } catch (const std::exception&) {
      m.gamma = 0;
    }
    if (!(m.gamma > 0.1 && m.gamma < 10)) throw AuthoringError("transfer '" + s + "': gamma must be in (0.1, 10)");
  } else {
    throw AuthoringError("transfer '" + s + "': expected srgb, linear or gamma:G");
  }
}

Rgba8Image toneMap(const FloatRgbImage& in, const ToneMapping& m) {
  Rgba8Image out(in.width, in.height);
  const double scale = std::exp2(m.exposure);
  const std::size_t n = static_cast<std::size_t>(in.width) * in.height;
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c)
      out.pixels[i * 4 + c] = toCode(m.white * applyTransfer(applyCurve(in.rgb[i * 3 + c] * scale, m.curve), m));
    out.pixels[i * 4 + 3] = 0x80;  // alpha 1.0 in the GS convention
  }
  return out;
}

Rgba8Image quantiseEncoded(const FloatRgbImage& in) {
  Rgba8Image out(in.width, in.height);
  const std::size_t n = static_cast<std::size_t>(in.width) * in.height;
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) out.pixels[i * 4 + c] = toCode(255.0 * std::clamp(in.rgb[i * 3 + c], 0.0f, 1.0f));
    out.pixels[i * 4 + 3] = 0x80;
  }
  return out;
}

Rgba8Image encodeFrame(const FloatRgbImage& in, bool storedAsFloat, InputEncoding enc, const ToneMapping& m) {
  const bool linear = enc == InputEncoding::Linear || (enc == InputEncoding::Auto && storedAsFloat);
  return linear ? toneMap(in, m) : quantiseEncoded(in);
}

}  // namespace vbim::streams
