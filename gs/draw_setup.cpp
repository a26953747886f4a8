#include "gs/draw_setup.hpp"

#include <algorithm>
#include <string>

#include "gs/blend16.hpp"
#include "gs/error.hpp"

namespace vbim::gs {

namespace {

using U64 = std::uint64_t;

// TEX0.TW / TH: log2 of the texture's size, rounded up (the texture may be smaller than 2^n).
U64 log2Ceil(int n) {
  U64 k = 0;
  while ((1 << k) < n) ++k;
  return k;
}

// FBW / TBW: buffer width in units of 64 pixels.
U64 width64(int width) {
  return static_cast<U64>((width + 63) / 64);
}

// ZBUF.PSM holds the low four bits of the Z format's PSM (PSMZ32 0x30, PSMZ24 0x31, PSMZ16 0x32).
U64 zbufPsm(Psm psm) {
  switch (psm) {
    case Psm::Z24:
      return 0x1;
    case Psm::Z16:
      return 0x2;
    default:
      return 0x0;
  }
}

U64 fixed4(int coordinate) {
  return static_cast<U64>(coordinate) << 4;
}  // 12.4 / 10.4 fixed point

constexpr U64 kSprite = 6;
constexpr U64 kPsmct16 = 0x02;  // gs_psm.h GS_PSM_16
constexpr U64 kClampMode = 1;
constexpr U64 kZtstAlways = 1;

}  // namespace

BlendDrawSetup blendDrawSetup(const BlendDraw& d) {
  if (d.frame.psm != d.texture.psm || (d.frame.psm != Psm::Ct32 && d.frame.psm != Psm::Ct16)) {
    throw GsError("the blend draws a PSMCT32 texture into a PSMCT32 lightmap, or a PSMCT16 one into a PSMCT16 one");
  }
  const int w = d.width;
  const int rows = d.y1 - d.y0;
  const bool ct16 = d.frame.psm == Psm::Ct16;
  const U64 psm = ct16 ? kPsmct16 : 0;
  const U64 fbmsk = d.keepAlpha ? (ct16 ? 0x80000000u : 0xFF000000u) : 0u;
  BlendDrawSetup out{};
  int corner = 0;  // UV and XYZ2 are sent once per sprite corner
  for (std::size_t i = 0; i < kBlendDrawRegisters.size(); ++i) {
    const GsRegister& r = kBlendDrawRegisters[i];
    U64 v = 0;
    switch (r.address) {
      case 0x3F:  // TEXFLUSH: any value
        break;
      case 0x4C:  // FRAME_1: FBP, FBW, PSM, FBMSK
        v = static_cast<U64>(d.frame.firstPage) | width64(d.frame.width) << 16 | psm << 24 | fbmsk << 32;
        break;
      case 0x4E:  // ZBUF_1: ZBP, PSM, ZMSK = 1
        if (d.depth != nullptr) v = static_cast<U64>(d.depth->firstPage) | zbufPsm(d.depth->psm) << 24;
        v |= U64{1} << 32;
        break;
      case 0x47:  // TEST_1: ZTE = 1, ZTST = ALWAYS
        v = U64{1} << 16 | kZtstAlways << 17;
        break;
      case 0x06:  // TEX0_1: TBP0, TBW, PSM, TW, TH, TCC = 1, TFX = MODULATE (0)
        v = static_cast<U64>(d.texture.basePointer()) | width64(d.texture.width) << 14 | psm << 20 |
            log2Ceil(d.texture.width) << 26 | log2Ceil(d.texture.height) << 30 | U64{1} << 34;
        break;
      case 0x08:  // CLAMP_1: WMS = WMT = CLAMP
        v = kClampMode | kClampMode << 2;
        break;
      case 0x42:  // ALPHA_1: A = Cs (0), B = Cd (1), C = FIX (2), D = Cd (1), FIX
        v = U64{0} | U64{1} << 2 | U64{2} << 4 | U64{1} << 6 | static_cast<U64>(d.fix & 0xFF) << 32;
        break;
      case 0x46:  // COLCLAMP
        v = d.clamp ? 1 : 0;
        break;
      case 0x40:  // SCISSOR_1: SCAX0, SCAX1, SCAY0, SCAY1 (inclusive)
        v = static_cast<U64>(w - 1) << 16 | static_cast<U64>(d.height - 1) << 48;
        break;
      case 0x00:  // PRIM: SPRITE, TME, ABE, FST
        v = kSprite | U64{1} << 4 | U64{1} << 6 | U64{1} << 8;
        break;
      case 0x01:  // RGBAQ: 0x80 per channel, Q = 1.0f
        v = 0x80808080u | U64{0x3F800000} << 32;
        break;
      case 0x03:  // UV
        v = corner == 0 ? fixed4(d.textureRow0) << 16 : fixed4(w) | fixed4(d.textureRow0 + rows) << 16;
        break;
      case 0x05:  // XYZ2, Z = 0
        v = corner == 0 ? fixed4(d.y0) << 16 : fixed4(w) | fixed4(d.y1) << 16;
        ++corner;
        break;
      default:  // TEX1_1, PABE, FBA_1, XYOFFSET_1: 0
        break;
    }
    out[i] = RegisterWrite{r, v};
  }
  return out;
}

std::array<RegisterWrite, kSixteenBitRegisters.size()> sixteenBitSetup(const BlendDraw& d) {
  return {RegisterWrite{kSixteenBitRegisters[0], kTexa16}, RegisterWrite{kSixteenBitRegisters[1], dimxRegister()},
          RegisterWrite{kSixteenBitRegisters[2], d.dither ? 1u : 0u}};
}

std::vector<RegisterWrite> blendDrawWrites(const BlendDraw& d) {
  const BlendDrawSetup setup = blendDrawSetup(d);
  std::vector<RegisterWrite> writes(setup.begin(), setup.end());
  if (d.frame.psm == Psm::Ct16) {
    const auto more = sixteenBitSetup(d);
    writes.insert(writes.begin() + static_cast<std::ptrdiff_t>(kSixteenBitInsertAt), more.begin(), more.end());
  }
  return writes;
}

int drawRows(const GsParams& p, int height) {
  return p.upload_mode == "strips" ? std::min<int>(static_cast<int>(p.strip_rows), height) : height;
}

const char* blendSurfaceName(BlendSurface surface) {
  return surface == BlendSurface::Sky ? "sky" : "lightmap";
}

BlendDraw blendDrawFor(const VramLayout& vram, const GsParams& p, BlendSurface surface, int width, int height, int y0,
                       int y1) {
  const bool sky = surface == BlendSurface::Sky;
  if (sky && !vram.has("sky staging")) {
    throw GsError("the VRAM layout has no sky staging area: it was planned without the sky stream's size");
  }
  BlendDraw d{vram.region(sky ? "sky" : "lightmap"), vram.region(sky ? "sky staging" : "staging")};
  if (width <= 0 || height <= 0 || width > d.frame.width || height > d.frame.height || width != d.texture.width ||
      y0 < 0 || y1 <= y0 || y1 > height || y1 - y0 > d.texture.height) {
    throw GsError("a blend of rows " + std::to_string(y0) + ".." + std::to_string(y1) + " of a " +
                  std::to_string(width) + "x" + std::to_string(height) + " " + blendSurfaceName(surface) +
                  " picture does not fit the layout's " + d.frame.name + " (" + std::to_string(d.frame.width) + "x" +
                  std::to_string(d.frame.height) + ") and " + d.texture.name + " (" + std::to_string(d.texture.width) +
                  "x" + std::to_string(d.texture.height) + ")");
  }
  if (vram.has("depth")) d.depth = &vram.region("depth");
  d.width = width;
  d.height = height;
  d.y0 = y0;
  d.y1 = y1;
  d.textureRow0 = p.upload_mode == "strips" ? 0 : y0;
  d.fix = static_cast<int>(p.fix);
  d.clamp = p.colclamp == "clamp";
  d.keepAlpha = p.alpha_write == "keep";
  d.dither = d.frame.psm == Psm::Ct16 && d.fix != 0x80;
  return d;
}

}  // namespace vbim::gs
