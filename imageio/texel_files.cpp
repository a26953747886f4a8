#include "imageio/texel_files.hpp"

#include <vector>

#include "imageio/exr_writer.hpp"
#include "imageio/png_writer.hpp"
#include "imageio/rgba8.hpp"

namespace vbim::imageio {

void writeTexelImage(const std::filesystem::path& path, const Rgba8Image& texels, bool exr, bool gsAlpha) {
  Rgba8Image img = texels;
  if (!gsAlpha) {
    for (std::size_t i = 3; i < img.pixels.size(); i += 4) img.pixels[i] = 255;
  }
  if (exr) {
    std::vector<float> scaled(img.pixels.size());  // 8-bit texels as 0..1 (alpha 0x80 = 0.502)
    for (std::size_t i = 0; i < scaled.size(); ++i) scaled[i] = static_cast<float>(img.pixels[i]) / 255.0f;
    writeExr(path, ImageView<float>{img.width, img.height, 4, scaled.data()});
  } else {
    writePng(path, rgbaView(img));
  }
}

}  // namespace vbim::imageio
