// The GIF packets a console sends by PATH3 (GIF DMA, channel 2, normal mode) for the in-place blend:
// the IMAGE upload of a decoded frame into its staging texture, the blend draw of gs/draw_setup.hpp,
// and the same draw with FIX = 0x80 that copies the first (or a snapped) frame in. `vbim config
// --gs-setup --format gif|c` prints them (docs/porting.md, "Packets to paste"); their sizes are the
// model's charges (gs.upload_setup_qwords, gs.macroblock_setup_qwords, kBlendDrawSetupQwords).
//
// Layouts (T-GS "GIF" and "Transfers"; SDK-GS gif_tags.h GIF_SET_TAG, gs_gp.h GS_SET_BITBLTBUF,
// GS_SET_TRXPOS, GS_SET_TRXREG, GS_SET_TRXDIR; register addresses as gs_gp.h's GS_REG_*):
//   GIFtag low 64 bits  NLOOP 0-14, EOP 15, PRE 46, PRIM 47-57, FLG 58-59 (0 PACKED, 2 IMAGE), NREG 60-63
//   GIFtag high 64 bits REGS, 4 bits per register descriptor (0xE: A+D)
//   A+D qword           low 64 bits the value, bits 64-71 the register address
// An IMAGE GIFtag moves at most 0x7FFF qwords (NLOOP is 15 bits): a larger transfer takes several.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gs/draw_setup.hpp"
#include "gs/params.hpp"
#include "gs/vram.hpp"

namespace vbim::gs {

enum class GifFlag : std::uint8_t { Packed = 0, Reglist = 1, Image = 2 };
inline constexpr std::uint64_t kGifRegsAd = 0xE;  // REGS descriptor: A+D
inline constexpr std::int64_t kGifMaxNloop = 0x7FFF;

// The GIFtag's low 64 bits (PRE = 0, no PRIM).
std::uint64_t gifTag(std::int64_t nloop, bool eop, GifFlag flag, int nreg);

// The GS's PSM code of a format (gs_psm.h GS_PSM_*: PSMCT32 0x00, PSMCT24 0x01, PSMCT16 0x02, PSMZ32 0x30 ...).
std::uint64_t psmCode(Psm psm);

// Host-to-local transfer registers.
std::uint64_t bitbltbufTo(const VramRegion& dst);  // DBP = its base pointer, DBW = width / 64, DPSM; source 0
std::uint64_t trxpos(int dsax, int dsay);          // SSAX = SSAY = 0, DIR = 0 (upper left first)
std::uint64_t trxreg(int width, int height);       // RRW, RRH
inline constexpr std::uint64_t kTrxdirHostToLocal = 0;

struct Qword {
  std::uint64_t lo = 0;
  std::uint64_t hi = 0;
  std::string what;            // "GIFtag ...", "BITBLTBUF = ..."
  std::int64_t dataAfter = 0;  // an IMAGE GIFtag: the qwords of pixels the sender puts after it
};

struct GifPacket {
  std::string name;     // an identifier: "lightmap_draw", "sky_upload_next"
  std::string purpose;  // when to send it
  std::vector<Qword> qwords;
  std::int64_t setupQwords() const { return static_cast<std::int64_t>(qwords.size()); }
  std::int64_t dataQwords() const;  // pixels sent with it
};

// One A+D write.
Qword adWrite(std::string_view name, std::uint8_t address, std::uint64_t value);

// The blend draw: an A+D GIFtag (EOP) and the writes of blendDrawSetup(draw).
GifPacket drawPacket(const BlendDraw& draw, std::string name, std::string purpose);

// An upload of `width` x `height` pixels of `bytesPerPixel` to (x, y) of `staging`. `first`: the A+D
// GIFtag, BITBLTBUF, TRXPOS, TRXREG, TRXDIR; else (a further macroblock, BITBLTBUF and TRXREG
// kept) the A+D GIFtag, TRXPOS, TRXDIR. Then the IMAGE GIFtag(s), the last with EOP.
GifPacket uploadPacket(const VramRegion& staging, int x, int y, int width, int height, int bytesPerPixel, bool first,
                       std::string name, std::string purpose);

// What a console sends for one blended surface with `params` in `vram`: the upload of a frame (its
// first transfer, and with gs.upload_strategy = macroblocks the one for macroblock 1, the pattern
// of every further one), the blend draw, and the copy draw (FIX = 0x80). In strip mode, the first
// strip's. Throws GsError as blendDrawFor does.
std::vector<GifPacket> surfacePackets(const GsParams& params, const VramLayout& vram, BlendSurface surface, int width,
                                      int height);

}  // namespace vbim::gs
