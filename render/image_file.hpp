// PNG in and out for the renderer (OpenImageIO).
#pragma once

#include <filesystem>

#include "runtime/image.hpp"

namespace vbim::render {

// Reads any 8-bit RGB(A) image OIIO can open; alpha is set to 0x80. Throws RenderError naming the file.
Rgba8Image readRgba8(const std::filesystem::path& path);
// Writes RGB (alpha dropped) as PNG. Throws RenderError naming the file.
void writePng(const std::filesystem::path& path, const Rgba8Image& image);

}  // namespace vbim::render
