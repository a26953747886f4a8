// `vbim config --gs-setup`: the console's VRAM plan and the register writes of each blend draw, for
// a port to compare with its own (docs/porting.md, "GS: upload and in-place blend"), or, with
// --format gif / c, the GIF packets to send by PATH3 (gs/gif_packets.hpp). The values come from the
// functions the presenters use (checkParams' plan, blendDrawFor), so the listing and a run
// cannot disagree. Text only: no simulated time.
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>

#include "gs/params.hpp"
#include "gs/vram.hpp"

namespace vbim::gs {

struct PictureSize {
  int width = 0;
  int height = 0;
};

// Writes `vram` (the plan checkParams returned, checked for the sky with checkSkyParams),
// then one Markdown table per blended surface (the lightmap, then the sky if given): the first draw
// of a vsync, which in strip mode covers the first strip.
void writeGsSetup(std::ostream& out, const GsParams& params, const VramLayout& vram, PictureSize lightmap,
                  std::optional<PictureSize> sky);

enum class PacketFormat : std::uint8_t {
  Gif,  // every qword's 16 bytes in memory order, annotated
  C,    // a C99 header: one aligned uint64_t [][2] array per packet
};

// The packets of surfacePackets for the lightmap and the sky, with what to send when and what
// to restore afterwards. `source` names the command's input in the header.
void writeGsPackets(std::ostream& out, const GsParams& params, const VramLayout& vram, PictureSize lightmap,
                    std::optional<PictureSize> sky, PacketFormat format, const std::string& source);

}  // namespace vbim::gs
