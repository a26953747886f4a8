#include "gs/vram_plan.hpp"

#include <algorithm>

#include "gs/draw_setup.hpp"
#include "gs/error.hpp"
#include "gs/tiled_blender.hpp"

namespace vbim::gs {

namespace {

VramLayout placeBuffers(const GsParams& p, int lightmapWidth, int lightmapHeight, SkyTexture sky) {
  if (lightmapWidth <= 0 || lightmapHeight <= 0 || lightmapWidth > 1024 || lightmapHeight > 1024) {
    throw GsError("lightmap " + std::to_string(lightmapWidth) + "x" + std::to_string(lightmapHeight) +
                  " cannot be a GS texture: each side must be 1..1024 (TEX0.TW/TH are log2 sizes up to 10)");
  }
  std::vector<VramRequest> req;
  const Psm fb = psmByName(p.frame_format);
  for (std::int64_t i = 0; i < p.frame_buffers; ++i) {
    req.push_back({"frame" + std::to_string(i), fb, static_cast<int>(p.frame_width), static_cast<int>(p.frame_height)});
  }
  if (p.depth_format != "none") {
    req.push_back(
        {"depth", psmByName(p.depth_format), static_cast<int>(p.frame_width), static_cast<int>(p.frame_height)});
  }
  const Psm texels = texturePsm(p);
  req.push_back({"lightmap", texels, lightmapWidth, lightmapHeight});
  req.push_back({"staging", texels, lightmapWidth, drawRows(p, lightmapHeight)});
  if (p.sky_width > 0 && p.sky_height > 0) {
    req.push_back({"sky", texels, static_cast<int>(p.sky_width), static_cast<int>(p.sky_height)});
  }
  if (sky.width > 0 && sky.height > 0) {
    // The sky is blended in place too: its frames are uploaded to a staging area of their own.
    req.push_back({"sky staging", texels, sky.width, drawRows(p, sky.height)});
  }
  return VramLayout::place(req);
}

// True when `p` changed as given by `change` would fit the GS's VRAM.
template <typename Change>
bool fitsWith(const GsParams& p, int width, int height, SkyTexture sky, Change change) {
  GsParams q = p;
  change(q);
  try {
    placeBuffers(q, width, height, sky);
    return true;
  } catch (const GsError&) {
    return false;
  }
}

}  // namespace

Psm texturePsm(const GsParams& p) {
  if (p.texture_format == "ct32") return Psm::Ct32;
  if (p.texture_format == "ct16") return Psm::Ct16;
  throw GsError({"gs.texture_format"}, "unknown texture format '" + p.texture_format + "' (expected ct32 or ct16)");
}

void checkSkyFits(const GsParams& p, SkyTexture sky) {
  if (sky.width <= 0 || sky.height <= 0) return;
  if (sky.width > p.sky_width || sky.height > p.sky_height) {
    throw GsError({"gs.sky_width", "gs.sky_height"},
                  "the sky stream is " + std::to_string(sky.width) + "x" + std::to_string(sky.height) +
                      " but VRAM keeps a " + std::to_string(p.sky_width) + "x" + std::to_string(p.sky_height) +
                      " sky texture (gs.sky_width x gs.sky_height): set them to at least the stream's size");
  }
}

VramLayout planVram(const GsParams& p, int lightmapWidth, int lightmapHeight, SkyTexture sky) {
  checkSkyFits(p, sky);
  try {
    return placeBuffers(p, lightmapWidth, lightmapHeight, sky);
  } catch (const GsError& e) {
    // Name the way out when a setting of the platform config has one (docs/player.md, "VRAM").
    std::string hint;
    const bool strips = p.upload_mode == "strips";
    const auto toStrips = [](GsParams& q) { q.upload_mode = "strips"; };
    // A sky texture as high as half its width (a dome), but never lower than the sky stream.
    const std::int64_t smallerSkyHeight =
        std::max<std::int64_t>(std::min<std::int64_t>(p.sky_height, p.sky_width / 2), sky.height);
    const auto smallerSky = [&](GsParams& q) { q.sky_height = smallerSkyHeight; };
    if (!strips && fitsWith(p, lightmapWidth, lightmapHeight, sky, toStrips)) {
      hint =
          "; it fits with gs.upload_mode = \"strips\" in a platform config (--config FILE), which blends "
          "through a " +
          std::to_string(p.strip_rows) + "-row staging area instead of a whole frame";
    } else if (fitsWith(p, lightmapWidth, lightmapHeight, sky, [&](GsParams& q) {
                 toStrips(q);
                 smallerSky(q);
               })) {
      hint = "; it fits with gs.upload_mode = \"strips\" and gs.sky_height = " + std::to_string(smallerSkyHeight) +
             " (a sky dome texture as high as half its width) in a platform config (--config FILE)";
    } else if (!fitsWith(p, kTileHeight, kTileHeight, sky, [&](GsParams& q) {
                 toStrips(q);
                 smallerSky(q);
               })) {
      hint =
          "; the frame buffers, depth buffer and sky texture alone leave no room for a lightmap: lower "
          "gs.frame_width, gs.frame_height, gs.frame_buffers, gs.depth_format or gs.sky_width / gs.sky_height";
    } else {
      hint = "; author a smaller lightmap (each side a power of two up to 1024)";
    }
    throw GsError(vramLayoutKeys(), e.what() + hint);
  }
}

const std::vector<std::string>& vramLayoutKeys() {
  static const std::vector<std::string> keys{
      "gs.frame_buffers", "gs.frame_width", "gs.frame_height", "gs.frame_format", "gs.depth_format",
      "gs.sky_width",     "gs.sky_height",  "gs.upload_mode",  "gs.strip_rows",   "gs.texture_format"};
  return keys;
}

}  // namespace vbim::gs
