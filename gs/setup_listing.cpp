#include "gs/setup_listing.hpp"

#include <cstdio>
#include <string>
#include <vector>

#include "gs/draw_setup.hpp"
#include "gs/gif_packets.hpp"

namespace vbim::gs {

namespace {

std::string hex(std::uint64_t v, int digits = 0) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "0x%0*llX", digits, static_cast<unsigned long long>(v));
  return buf;
}

void writeDraw(std::ostream& out, const GsParams& params, const VramLayout& vram, BlendSurface surface,
               PictureSize size) {
  const int rows = drawRows(params, size.height);
  const BlendDraw draw = blendDrawFor(vram, params, surface, size.width, size.height, 0, rows);
  const int draws = (size.height + rows - 1) / rows;
  out << "\n## " << blendSurfaceName(surface) << " " << size.width << "x" << size.height << ": " << draw.frame.name
      << " at page " << draw.frame.firstPage << ", blended from " << draw.texture.name << " at page "
      << draw.texture.firstPage << " (block " << draw.texture.basePointer() << ")\n\n";
  if (draws > 1) {
    out << "Draw 1 of " << draws << " per vsync, rows 0.." << rows << " (strip mode); each next draw covers the next "
        << rows << " rows after its strip's upload: only the rows of XYZ2 change.\n\n";
  } else {
    out << "One draw per vsync (rows 0.." << rows << ").\n\n";
  }
  out << "| # | register | address | value |\n|---|---|---|---|\n";
  const std::vector<RegisterWrite> setup = blendDrawWrites(draw);
  for (std::size_t i = 0; i < setup.size(); ++i) {
    out << "| " << i + 1 << " | `" << setup[i].reg.name << "` | " << hex(setup[i].reg.address, 2) << " | `"
        << hex(setup[i].value) << "` |\n";
  }
}

// What a port restores after the packets, and in which order it sends them (docs/porting.md,
// "Packets to paste"). One line per element, without a comment marker.
std::vector<std::string> notes(const GsParams& params) {
  std::vector<std::string> n{
      "Send by PATH3 (GIF DMA channel 2, normal mode, QWC = the packet's qwords), 16-byte aligned.",
      "Per vsync and surface: with a new frame, the upload packet(s) and the frame's pixels after each IMAGE",
      "GIFtag; then the draw (it starts with TEXFLUSH). For the first frame, and a frame gs.catchup = hard-skip",
      "copies in, send the *_draw_copy packet (FIX = 0x80) instead of *_draw.",
  };
  if (params.upload_mode == "strips") {
    n.emplace_back("Strip mode: each strip is uploaded to the staging area and drawn in turn; the draw shown is the");
    n.emplace_back("first strip's (the next ones move XYZ2's rows).");
  }
  n.insert(n.end(), {
                        "GS registers are write-only: the game keeps its own copies and sends them again after the",
                        "blend. The packets overwrite context 1 (FRAME_1, ZBUF_1, TEST_1, TEX0_1, TEX1_1, CLAMP_1,",
                        "ALPHA_1, SCISSOR_1, XYOFFSET_1, FBA_1) and the shared PABE, COLCLAMP, PRIM, RGBAQ, UV and the",
                        "transfer registers (BITBLTBUF, TRXPOS, TRXREG, TRXDIR, which need no restoring).",
                    });
  if (params.texture_format == "ct16") {
    n.emplace_back("16-bit path: the draws also write TEXA, DIMX and DTHE (1 for the blend, 0 for the copy);");
    n.emplace_back("restore the game's. They rely on SCANMSK = 0, which they do not write.");
  } else {
    n.emplace_back(
        "They rely on SCANMSK = 0 and DTHE = 0, which they do not write: set them if the game changed them.");
  }
  return n;
}

std::vector<GifPacket> allPackets(const GsParams& params, const VramLayout& vram, PictureSize lightmap,
                                  std::optional<PictureSize> sky) {
  std::vector<GifPacket> all = surfacePackets(params, vram, BlendSurface::Lightmap, lightmap.width, lightmap.height);
  if (sky) {
    for (GifPacket& p : surfacePackets(params, vram, BlendSurface::Sky, sky->width, sky->height)) {
      all.push_back(std::move(p));
    }
  }
  return all;
}

void writeBytes(std::ostream& out, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) {
    char b[4];
    std::snprintf(b, sizeof b, "%02x ", static_cast<unsigned>((v >> (8 * i)) & 0xFF));
    out << b;
  }
}

void writeGif(std::ostream& out, const std::vector<GifPacket>& packets) {
  for (const GifPacket& p : packets) {
    out << "\n## " << p.name << ": " << p.setupQwords() << " qwords"
        << (p.dataQwords() > 0 ? " + " + std::to_string(p.dataQwords()) + " qwords of pixels" : "") << "\n# "
        << p.purpose << "\n";
    for (std::size_t i = 0; i < p.qwords.size(); ++i) {
      const Qword& q = p.qwords[i];
      char off[16];
      std::snprintf(off, sizeof off, "%04zx  ", i * 16);
      out << off;
      writeBytes(out, q.lo);
      out << " ";
      writeBytes(out, q.hi);
      out << "; " << q.what << (q.dataAfter > 0 ? ", then " + std::to_string(q.dataAfter) + " qwords of pixels" : "")
          << "\n";
    }
  }
}

void writeC(std::ostream& out, const std::vector<GifPacket>& packets) {
  out << "\n#include <stdint.h>\n";
  for (const GifPacket& p : packets) {
    out << "\n/* " << p.purpose << " */\n"
        << "static const uint64_t vbim_" << p.name << "[" << p.qwords.size()
        << "][2] __attribute__((aligned(16))) = {\n";
    for (const Qword& q : p.qwords) {
      out << "    {" << hex(q.lo, 16) << "ULL, " << hex(q.hi, 16) << "ULL}, /* " << q.what
          << (q.dataAfter > 0 ? ", then " + std::to_string(q.dataAfter) + " qwords of pixels" : "") << " */\n";
    }
    out << "};\n";
  }
}

}  // namespace

void writeGsSetup(std::ostream& out, const GsParams& params, const VramLayout& vram, PictureSize lightmap,
                  std::optional<PictureSize> sky) {
  out << "# GS setup: VRAM and the blend draws' register writes (A+D, after one GIFtag)\n\n## VRAM\n\n";
  out << vram.describe();
  writeDraw(out, params, vram, BlendSurface::Lightmap, lightmap);
  if (sky) writeDraw(out, params, vram, BlendSurface::Sky, *sky);
}

void writeGsPackets(std::ostream& out, const GsParams& params, const VramLayout& vram, PictureSize lightmap,
                    std::optional<PictureSize> sky, PacketFormat format, const std::string& source) {
  const std::vector<GifPacket> packets = allPackets(params, vram, lightmap, sky);
  const bool c = format == PacketFormat::C;
  out << (c ? "/* " : "# ") << "GS packets of the in-place blend for " << source << " (vbim config --gs-setup --format "
      << (c ? "c" : "gif") << ")\n";
  const char* lead = c ? " * " : "# ";
  if (!c) out << "# Each line: a qword's 16 bytes in memory order (little-endian), then what it is.\n";
  for (const std::string& line : notes(params)) out << lead << line << "\n";
  if (c) out << " */\n";
  if (c) {
    writeC(out, packets);
  } else {
    writeGif(out, packets);
  }
}

}  // namespace vbim::gs
