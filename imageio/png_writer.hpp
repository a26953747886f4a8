// PNG files, written by libpng's simplified API (png_encoder.hpp writes the pictures made in bulk,
// at a chosen zlib level: `vbim play`'s and `vbim decode`'s). Small enough
// for the lean `vbim` program (cli/main.cpp), which must not load OpenImageIO (its ~200 shared
// libraries cost ~120 MB before it does anything; `vbim play` stays under 64 MB, issue #7).
#pragma once

#include <cstdint>
#include <filesystem>

#include "imageio/image_view.hpp"

namespace vbim::imageio {

// Default: zlib's default level with adaptive row filters (smallest files). Fast: libpng's
// PNG_IMAGE_FLAG_FAST (zlib level 3, no row filters): bigger files in a fraction of the time, for
// pictures written in bulk (rendered frames).
enum class PngSpeed { Default, Fast };

// 8-bit grey (1 channel), grey + alpha (2), RGB (3) or RGBA (4), samples as given; the file is
// tagged sRGB. Written under a temporary name and renamed into place. Throws ImageIoError naming
// the file.
void writePng(const std::filesystem::path& path, ImageView<std::uint8_t> image, PngSpeed speed = PngSpeed::Default);

// 16-bit grey (1 channel) or RGB (3), samples exactly as given (data such as horizon codes); the
// file is tagged linear (gamma 1.0). No alpha: libpng's simplified API would take 16-bit colours as
// premultiplied by it and change them.
void writePng(const std::filesystem::path& path, ImageView<std::uint16_t> image, PngSpeed speed = PngSpeed::Default);

}  // namespace vbim::imageio
