// OpenEXR files, written with the OpenEXR library: the only EXR writer of the project (small enough
// for the lean `vbim` program, like png_writer.hpp).
#pragma once

#include <filesystem>

#include "imageio/image_view.hpp"
#include "imageio/replace_file.hpp"

namespace vbim::imageio {

// Half: 16-bit floats (pictures; ~3 significant digits). Float: 32-bit, every value exactly as given
// (generator outputs, data layers).
enum class ExrSamples { Half, Float };

// Grey (1 channel, named Y), grey + alpha (2: Y, A), RGB (3) or RGBA (4), 1.0 = full scale; half
// samples PIZ-, float samples ZIP-compressed (both lossless). Written under a temporary name and
// renamed into place unless `placement` says the directory is staged (replace_file.hpp). Throws
// ImageIoError naming the file.
void writeExr(const std::filesystem::path& path, ImageView<float> image, ExrSamples stored = ExrSamples::Half,
              FilePlacement placement = FilePlacement::TemporaryThenRename);

}  // namespace vbim::imageio
