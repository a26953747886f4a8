#include "gs/gif_packets.hpp"

#include <algorithm>
#include <cstdio>

namespace vbim::gs {

namespace {

using U64 = std::uint64_t;

std::string hex(U64 v) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "0x%llX", static_cast<unsigned long long>(v));
  return buf;
}

Qword tagQword(std::int64_t nloop, bool eop, GifFlag flag) {
  const bool image = flag == GifFlag::Image;
  Qword q;
  // IMAGE ignores NREG and REGS (T-GS GIF); PACKED A+D is one register descriptor, 0xE.
  q.lo = gifTag(nloop, eop, flag, image ? 0 : 1);
  q.hi = image ? 0 : kGifRegsAd;
  q.what = std::string("GIFtag NLOOP=") + std::to_string(nloop) + " EOP=" + (eop ? "1" : "0") +
           (image ? " IMAGE" : " PACKED NREG=1 REGS=A+D");
  if (image) q.dataAfter = nloop;
  return q;
}

}  // namespace

U64 gifTag(std::int64_t nloop, bool eop, GifFlag flag, int nreg) {
  return (static_cast<U64>(nloop) & 0x7FFF) | static_cast<U64>(eop ? 1 : 0) << 15 |
         (static_cast<U64>(flag) & 0x3) << 58 | (static_cast<U64>(nreg) & 0xF) << 60;
}

U64 psmCode(Psm psm) {
  switch (psm) {
    case Psm::Ct32:
      return 0x00;
    case Psm::Ct24:
      return 0x01;
    case Psm::Ct16:
      return 0x02;
    case Psm::Z32:
      return 0x30;
    case Psm::Z24:
      return 0x31;
    case Psm::Z16:
      return 0x32;
  }
  return 0;
}

U64 bitbltbufTo(const VramRegion& dst) {
  const auto dbw = static_cast<U64>((dst.width + 63) / 64);
  return static_cast<U64>(dst.basePointer()) << 32 | dbw << 48 | psmCode(dst.psm) << 56;
}

U64 trxpos(int dsax, int dsay) {
  return (static_cast<U64>(dsax) & 0x7FF) << 32 | (static_cast<U64>(dsay) & 0x7FF) << 48;
}

U64 trxreg(int width, int height) {
  return (static_cast<U64>(width) & 0xFFF) | (static_cast<U64>(height) & 0xFFF) << 32;
}

std::int64_t GifPacket::dataQwords() const {
  std::int64_t n = 0;
  for (const Qword& q : qwords) n += q.dataAfter;
  return n;
}

Qword adWrite(std::string_view name, std::uint8_t address, U64 value) {
  return Qword{value, address, std::string(name) + " = " + hex(value), 0};
}

GifPacket drawPacket(const BlendDraw& draw, std::string name, std::string purpose) {
  GifPacket p{std::move(name), std::move(purpose), {}};
  const std::vector<RegisterWrite> writes = blendDrawWrites(draw);
  p.qwords.push_back(tagQword(static_cast<std::int64_t>(writes.size()), true, GifFlag::Packed));
  for (const RegisterWrite& w : writes) p.qwords.push_back(adWrite(w.reg.name, w.reg.address, w.value));
  return p;
}

GifPacket uploadPacket(const VramRegion& staging, int x, int y, int width, int height, int bytesPerPixel, bool first,
                       std::string name, std::string purpose) {
  GifPacket p{std::move(name), std::move(purpose), {}};
  p.qwords.push_back(tagQword(first ? 4 : 2, false, GifFlag::Packed));
  if (first) p.qwords.push_back(adWrite("BITBLTBUF", 0x50, bitbltbufTo(staging)));
  p.qwords.push_back(adWrite("TRXPOS", 0x51, trxpos(x, y)));
  if (first) p.qwords.push_back(adWrite("TRXREG", 0x52, trxreg(width, height)));
  p.qwords.push_back(adWrite("TRXDIR", 0x53, kTrxdirHostToLocal));
  // The pixels in qwords, rounded up (a transfer moves whole qwords).
  std::int64_t left = (static_cast<std::int64_t>(width) * height * bytesPerPixel + 15) / 16;
  while (left > 0) {
    const std::int64_t n = std::min(left, kGifMaxNloop);
    left -= n;
    p.qwords.push_back(tagQword(n, left == 0, GifFlag::Image));
  }
  return p;
}

std::vector<GifPacket> surfacePackets(const GsParams& params, const VramLayout& vram, BlendSurface surface, int width,
                                      int height) {
  const int rows = drawRows(params, height);
  const BlendDraw draw = blendDrawFor(vram, params, surface, width, height, 0, rows);
  const std::string s = blendSurfaceName(surface);
  // PSMCT32 staging: the IPU's RGB32 output; PSMCT16: its RGB16 output (gs/blend16.hpp).
  const int bytesPerPixel = draw.texture.psm == Psm::Ct16 ? 2 : 4;
  const std::string mbQwords = std::to_string(16 * 16 * bytesPerPixel / 16);
  const std::string perRow = std::to_string((width + 15) / 16);
  std::vector<GifPacket> out;
  if (params.upload_strategy == "macroblocks") {
    out.push_back(uploadPacket(draw.texture, 0, 0, 16, 16, bytesPerPixel, true, s + "_upload",
                               "a new frame: the first IMAGE transfer, macroblock 0 (16x16 at 0, 0), then its " +
                                   mbQwords + " qwords from fromIPU"));
    out.push_back(uploadPacket(draw.texture, 16, 0, 16, 16, bytesPerPixel, false, s + "_upload_next",
                               "each further macroblock m: this, with TRXPOS DSAX = 16 * (m mod " + perRow +
                                   "), DSAY = 16 * (m div " + perRow + ") (shown: m = 1), then its " + mbQwords +
                                   " qwords"));
  } else {
    out.push_back(uploadPacket(draw.texture, 0, 0, width, rows, bytesPerPixel, true, s + "_upload",
                               "a new frame: one IMAGE transfer of the raster image (" + std::to_string(width) + "x" +
                                   std::to_string(rows) + ")"));
  }
  BlendDraw copy = draw;
  copy.fix = 0x80;
  copy.dither = false;
  out.push_back(
      drawPacket(draw, s + "_draw", "every vsync after the upload: the blend, FIX = " + hex(draw.fix & 0xFF)));
  out.push_back(drawPacket(copy, s + "_draw_copy",
                           std::string("instead of the blend for the first frame (and a frame hard-skip copies in): "
                                       "FIX = 0x80, ") +
                               (draw.dither ? "DTHE = 0: ALPHA_1 and DTHE are the only qwords that differ"
                                            : "ALPHA_1 is the only qword that differs")));
  return out;
}

}  // namespace vbim::gs
