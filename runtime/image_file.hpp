// Pictures to files with two small, common libraries (libpng's simplified API, OpenEXR), so the
// commands that only write pictures (vbim play, vbim decode) need not load OpenImageIO, whose
// ~200 shared libraries and static tables cost the process ~120 MB before it does anything
// (issue #7: playback under 64 MB). Reading arbitrary image formats stays with OpenImageIO in the
// authoring and lighting tools.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>

namespace vbim {

// Names the file and what went wrong.
class ImageFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// 8-bit RGBA (width * height * 4 bytes, rows top to bottom) as an RGBA PNG.
void writePng(const std::filesystem::path& path, int width, int height, const std::uint8_t* rgba);

// RGBA floats (width * height * 4, 1.0 = full scale) as a half-float RGBA OpenEXR file.
void writeExr(const std::filesystem::path& path, int width, int height, const float* rgba);

}  // namespace vbim
