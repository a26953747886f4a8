// Loads one image file with OpenImageIO (EXR, HDR, PNG, TIFF, ...) as linear or display-encoded RGB.
#pragma once

#include <filesystem>

#include "streams/authoring/tone_map.hpp"

namespace vbim::streams {

struct LoadedImage {
  FloatRgbImage rgb;
  bool floatingPoint = false;  // stored as half/float/double (taken as linear light by default)
};

// Grey images are replicated to RGB; channels after the third are ignored. Throws AuthoringError
// naming the file.
LoadedImage loadImage(const std::filesystem::path& path);

enum class InputEncoding { Auto, Linear, Encoded };

// Loads and maps to 8-bit: Auto treats floating-point files as linear (tone-mapped) and integer
// files as already encoded.
Rgba8Image loadFrame(const std::filesystem::path& path, InputEncoding enc, const ToneMapping& m);

}  // namespace vbim::streams
