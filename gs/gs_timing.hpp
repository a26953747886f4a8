// What the GS work of one vsync costs on the simulated clock (1 tick = 1 GS clock = 1 bus clock).
//   IMAGE transfer over PATH3: (setup qwords * 16 + payload bytes) / GIF bytes per tick. Uploading
//   the IPU's macroblocks one transfer each costs the full setup once and a shorter one per further
//   macroblock (gs.macroblock_setup_qwords: only TRXPOS and TRXDIR change). An IMAGE GIFtag moves at
//   most 0x7FFF qwords (NLOOP is 15 bits: T-GS GIF, SDK-GS GIF_SET_TAG), so a transfer larger than
//   that (a raster upload of more than 512 KiB) carries one more GIFtag qword per further 0x7FFF
//   qwords, as gs/gif_packets.cpp's uploadPacket sends it.
//   Textured SPRITE draw with the blend: the register writes of gs/draw_setup.hpp over the GIF (three
//   more on the 16-bit path), then
//   pixels / (textured px per clock) * (1 + page-break overhead).
// Both round up to whole ticks. Sources: gs/params.cpp and docs/timing/gs.md.
#pragma once

#include <cstdint>

#include "gs/draw_setup.hpp"
#include "gs/gif_packets.hpp"
#include "gs/params.hpp"
#include "runtime/clock.hpp"

namespace vbim::gs {

class GsTiming {
 public:
  explicit GsTiming(const GsParams& p) : p_(p) {}
  Tick imageTransfer(std::int64_t payloadBytes, std::int64_t transfers = 1) const {
    return ceilDiv(setupQwords(transfers, payloadBytes) * 16 + payloadBytes, p_.gif_bytes_per_tick);
  }
  // The setup qwords of `transfers` back-to-back IMAGE transfers of `payloadBytes` in all (shared
  // evenly) into one buffer: each transfer's own, and the further IMAGE GIFtags of transfers over
  // kGifMaxNloop qwords.
  std::int64_t setupQwords(std::int64_t transfers, std::int64_t payloadBytes = 0) const {
    if (transfers <= 0) return 0;
    const std::int64_t perTransfer = ceilDiv(ceilDiv(payloadBytes, 16), transfers);
    const std::int64_t extraTags = perTransfer > kGifMaxNloop ? ceilDiv(perTransfer, kGifMaxNloop) - 1 : 0;
    return p_.upload_setup_qwords + (transfers - 1) * p_.macroblock_setup_qwords + transfers * extraTags;
  }
  Tick spriteDraw(std::int64_t width, std::int64_t height) const {
    const std::int64_t qwords = p_.texture_format == "ct16" ? kBlendDrawSetupQwords16 : kBlendDrawSetupQwords;
    const Tick setup = ceilDiv(qwords * 16, p_.gif_bytes_per_tick);
    return setup + ceilDiv(width * height * (100 + p_.page_break_overhead_pct), 100 * p_.textured_pixels_per_clock);
  }

 private:
  static constexpr std::int64_t ceilDiv(std::int64_t a, std::int64_t b) { return (a + b - 1) / b; }
  GsParams p_;
};

}  // namespace vbim::gs
