// HDR -> 8-bit mapping applied to every input frame before encoding (docs/stream-format.md,
// "From images to 8-bit frames"):
//   linear input:  code = round(white * encode(curve(value * 2^exposure)))   per R, G, B
//   encoded input: code = round(255 * value)   (already display-encoded 8/16-bit files pass through)
#pragma once

#include <string>
#include <vector>

#include "runtime/image.hpp"

namespace vbim::streams {

// Linear-light RGB floats, row-major, 3 floats per pixel.
struct FloatRgbImage {
  int width = 0;
  int height = 0;
  std::vector<float> rgb;
  FloatRgbImage() = default;
  FloatRgbImage(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * h * 3, 0.0f) {}
  float* at(int x, int y) { return rgb.data() + (static_cast<std::size_t>(y) * width + x) * 3; }
};

struct ToneMapping {
  enum class Curve { Clamp, Reinhard, Filmic };
  enum class Transfer { Srgb, Linear, Gamma };
  double exposure = 0.0;  // stops: values are multiplied by 2^exposure
  Curve curve = Curve::Clamp;
  Transfer transfer = Transfer::Srgb;
  double gamma = 2.2;    // for Transfer::Gamma: encode(x) = x^(1/gamma)
  double white = 255.0;  // 8-bit code of 1.0 after the curve (128 = the GS's 1.0 for MODULATE)
};

// Parses "clamp" / "reinhard" / "filmic" and "srgb" / "linear" / "gamma:2.2"; throws AuthoringError.
ToneMapping::Curve parseCurve(const std::string& s);
void parseTransfer(const std::string& s, ToneMapping& m);

Rgba8Image toneMap(const FloatRgbImage& in, const ToneMapping& m);
// For display-encoded inputs: code = round(255 * clamp(value)).
Rgba8Image quantiseEncoded(const FloatRgbImage& in);

// How an input frame's values are taken: Auto treats files that stored floats as linear light and
// integer files as already display-encoded.
enum class InputEncoding { Auto, Linear, Encoded };

// One input frame to 8-bit: toneMap() if it is linear, quantiseEncoded() if it is encoded.
Rgba8Image encodeFrame(const FloatRgbImage& in, bool storedAsFloat, InputEncoding enc, const ToneMapping& m);

}  // namespace vbim::streams
