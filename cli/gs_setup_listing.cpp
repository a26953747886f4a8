#include "cli/gs_setup_listing.hpp"

#include <cstdio>
#include <string>

#include "gs/draw_setup.hpp"

namespace vbim::cli {

namespace {

std::string hex(std::uint64_t v, int digits = 0) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "0x%0*llX", digits, static_cast<unsigned long long>(v));
  return buf;
}

void writeDraw(std::ostream& out, const gs::GsParams& params, const gs::VramLayout& vram, gs::BlendSurface surface,
               PictureSize size) {
  const int rows = gs::drawRows(params, size.height);
  const gs::BlendDraw draw = gs::blendDrawFor(vram, params, surface, size.width, size.height, 0, rows);
  const int draws = (size.height + rows - 1) / rows;
  out << "\n## " << gs::blendSurfaceName(surface) << " " << size.width << "x" << size.height << ": " << draw.frame.name
      << " at page " << draw.frame.firstPage << ", blended from " << draw.texture.name << " at page "
      << draw.texture.firstPage << " (block " << draw.texture.basePointer() << ")\n\n";
  if (draws > 1) {
    out << "Draw 1 of " << draws << " per vsync, rows 0.." << rows << " (strip mode); each next draw covers the next "
        << rows << " rows after its strip's upload: only the rows of XYZ2 change.\n\n";
  } else {
    out << "One draw per vsync (rows 0.." << rows << ").\n\n";
  }
  out << "| # | register | address | value |\n|---|---|---|---|\n";
  const gs::BlendDrawSetup setup = gs::blendDrawSetup(draw);
  for (std::size_t i = 0; i < setup.size(); ++i) {
    out << "| " << i + 1 << " | `" << setup[i].reg.name << "` | " << hex(setup[i].reg.address, 2) << " | `"
        << hex(setup[i].value) << "` |\n";
  }
}

}  // namespace

void writeGsSetup(std::ostream& out, const gs::GsParams& params, const gs::VramLayout& vram, PictureSize lightmap,
                  std::optional<PictureSize> sky) {
  out << "# GS setup: VRAM and the blend draws' register writes (A+D, after one GIFtag)\n\n## VRAM\n\n";
  out << vram.describe();
  writeDraw(out, params, vram, gs::BlendSurface::Lightmap, lightmap);
  if (sky) writeDraw(out, params, vram, gs::BlendSurface::Sky, *sky);
}

}  // namespace vbim::cli
