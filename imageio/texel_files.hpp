// A lightmap or sky picture of a run (the GS's 8-bit texels) as a file: PNG, or EXR (8-bit texels as
// 0..1 floats). RGB, no alpha channel, unless `gsAlpha`: viewers then show the picture as the GS
// uses it (the lightmap's alpha is not blended on screen), and an opaque picture has no alpha to
// write (a quarter fewer bytes than alpha 255 everywhere, which vbim play wrote until issue #31);
// with `gsAlpha` the texels are written as they are in VRAM, RGBA (0x80 is the GS's 1.0: GS User's
// Manual, ALPHA register), the bytes hashes.txt hashes.
#pragma once

#include <filesystem>

#include "imageio/replace_file.hpp"
#include "runtime/image.hpp"

namespace vbim::imageio {

// vbim play's default PNG level: stored, no compression (png_encoder.hpp): images then cost under
// 10 % of a play's CPU (issue #31; docs/player.md, "Saving frames").
inline constexpr int kDefaultTexelPngLevel = 0;

struct TexelFileFormat {
  bool exr = false;
  bool gsAlpha = false;
  int pngLevel = kDefaultTexelPngLevel;  // 0 to kMaxPngLevel (png_encoder.hpp)
};

// `texels` is only read (a PNG packs RGB as it writes its rows, an EXR as it scales to floats).
// `placement`: replace_file.hpp (a run's frames are InStagedDirectory). Throws ImageIoError when the
// file cannot be written.
void writeTexelImage(const std::filesystem::path& path, const Rgba8Image& texels, const TexelFileFormat& format,
                     FilePlacement placement = FilePlacement::TemporaryThenRename);

}  // namespace vbim::imageio
