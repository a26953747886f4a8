#include "gs/draw_checks.hpp"

#include <algorithm>

#include "gs/draw_setup.hpp"
#include "gs/error.hpp"
#include "gs/tiled_blender.hpp"

namespace vbim::gs {

CatchUp catchUpByName(const std::string& name) {
  if (name == "blend-through") return CatchUp::BlendThrough;
  if (name == "hard-skip") return CatchUp::HardSkip;
  if (name == "play-late") return CatchUp::PlayLate;
  throw GsError("unknown catch-up policy '" + name + "' (expected blend-through, hard-skip or play-late)");
}

VsyncClock clockFor(const GsParams& p) {
  VsyncRate rate{};
  if (!vsyncRateByName(p.video, rate)) {
    throw GsError("unknown video mode '" + p.video + "' (expected ntsc, ntsc-p, pal or pal-p)");
  }
  return VsyncClock(rate);
}

ColClamp colclampFor(const GsParams& p) {
  if (p.colclamp == "clamp") return ColClamp::Clamp;
  if (p.colclamp == "wrap") return ColClamp::Wrap;
  throw GsError("unknown COLCLAMP mode '" + p.colclamp + "' (expected clamp or wrap)");
}

AlphaWrite alphaFor(const GsParams& p) {
  if (p.alpha_write == "source") return AlphaWrite::Source;
  if (p.alpha_write == "keep") return AlphaWrite::Keep;
  throw GsError("unknown alpha write '" + p.alpha_write + "' (expected source or keep)");
}

bool checkedStrips(const GsParams& p) {
  if (p.upload_mode != "full" && p.upload_mode != "strips") {
    throw GsError({"gs.upload_mode"}, "unknown upload mode '" + p.upload_mode + "' (expected full or strips)");
  }
  if (p.strip_rows <= 0 || p.strip_rows % kTileHeight != 0) {
    throw GsError({"gs.strip_rows"}, "strip rows " + std::to_string(p.strip_rows) +
                                         " must be a positive multiple of 32 (one PSMCT32 page)");
  }
  return p.upload_mode == "strips";
}

// True when the IPU's macroblocks are uploaded one IMAGE transfer each (gs.upload_strategy).
bool checkedMacroblockUploads(const GsParams& p) {
  if (std::find(kUploadStrategies.begin(), kUploadStrategies.end(), p.upload_strategy) == kUploadStrategies.end()) {
    throw GsError({"gs.upload_strategy"},
                  "unknown upload strategy '" + p.upload_strategy + "' (expected macroblocks, ee-reorder or raster)");
  }
  return p.upload_strategy == "macroblocks";
}

namespace {

// Runs one check; a GsError it throws is re-thrown naming the key that was checked.
template <typename Check>
void checkKey(const char* key, Check check) {
  try {
    check();
  } catch (const GsError& e) {
    if (!e.keys().empty()) throw;
    throw GsError({key}, e.what());
  }
}

// Every check of checkParams but the VRAM layout's.
void checkSettings(const GsParams& p) {
  checkKey("gs.video", [&] { clockFor(p); });
  checkKey("gs.colclamp", [&] { colclampFor(p); });
  checkKey("gs.alpha_write", [&] { alphaFor(p); });
  checkKey("gs.fix", [&] { makeBlendSpec(p.fix, ColClamp::Clamp, AlphaWrite::Source); });
  checkKey("gs.catchup_fix", [&] { makeBlendSpec(p.catchup_fix, ColClamp::Clamp, AlphaWrite::Source); });
  checkKey("gs.catchup", [&] { catchUpByName(p.catchup); });
  checkedStrips(p);
  checkedMacroblockUploads(p);
  texturePsm(p);
}

}  // namespace

VramLayout checkParams(const GsParams& p, int lightmapWidth, int lightmapHeight, SkyTexture sky) {
  checkSettings(p);
  return planVram(p, lightmapWidth, lightmapHeight, sky);
}

VramLayout checkSkyParams(const GsParams& p, const VramLayout& console, int skyWidth, int skyHeight) {
  checkSettings(p);
  checkSkyFits(p, SkyTexture{skyWidth, skyHeight});
  blendDrawFor(console, p, BlendSurface::Sky, skyWidth, skyHeight, 0, drawRows(p, skyHeight));
  return console;
}

VramLayout checkConsole(const GsParams& p, int lightmapWidth, int lightmapHeight, SkyTexture sky) {
  VramLayout vram = checkParams(p, lightmapWidth, lightmapHeight, sky);
  if (sky.width > 0 && sky.height > 0) checkSkyParams(p, vram, sky.width, sky.height);
  return vram;
}

}  // namespace vbim::gs
