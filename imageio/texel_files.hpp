// A lightmap or sky picture of a run (the GS's 8-bit texels) as a file: PNG, or EXR (8-bit texels as
// 0..1 floats). Alpha 255 unless `gsAlpha`: viewers then show the picture as the GS uses it (the
// lightmap's alpha is not blended on screen); with `gsAlpha` the texels are written as they are in
// VRAM (0x80 is the GS's 1.0: GS User's Manual, ALPHA register), the bytes hashes.txt hashes.
#pragma once

#include <filesystem>

#include "runtime/image.hpp"

namespace vbim::imageio {

// Throws ImageIoError when the file cannot be written.
void writeTexelImage(const std::filesystem::path& path, const Rgba8Image& texels, bool exr, bool gsAlpha);

}  // namespace vbim::imageio
