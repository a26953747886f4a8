// Writing a picture in the format its file name asks for: .png and .exr go to the project's own
// writers (png_writer.hpp, exr_writer.hpp), any other extension OpenImageIO writes (.tif, .jpg, ...)
// goes to OpenImageIO. Part of the full imageio library (vbim_imageio_full).
#pragma once

#include <cstdint>
#include <filesystem>

#include "imageio/image_view.hpp"

namespace vbim::imageio {

// 8-bit samples: .png as written by writePng; .exr is refused (EXR holds floats).
void writeImage(const std::filesystem::path& path, ImageView<std::uint8_t> image);
// 16-bit samples: .png as written by writePng (1 or 3 channels); .exr is refused.
void writeImage(const std::filesystem::path& path, ImageView<std::uint16_t> image);
// 32-bit floats: .exr as ExrSamples::Float (every value exact); .png is refused (PNG holds integers).
void writeImage(const std::filesystem::path& path, ImageView<float> image);

}  // namespace vbim::imageio
