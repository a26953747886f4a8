// Every constant and setting of the GS model, as named parameters under "gs." with units and
// sources (docs/timing/gs.md lists them; `vbim config --defaults` prints them).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace vbim {
class ParamTable;
}

namespace vbim::gs {

// The catch-up policies, by the one name each has everywhere (gs.catchup, `--policy`, the API, docs):
// the seeds' default that keeps blending toward late frames, a hard skip to the due frame, and
// playing late frames as if on time (docs/player.md, "Catch-up").
inline constexpr std::array<std::string_view, 3> kCatchupPolicies{"blend-through", "hard-skip", "play-late"};

// The upload strategies, by the one name each has everywhere (gs.upload_strategy, docs/porting.md).
inline constexpr std::array<std::string_view, 3> kUploadStrategies{"macroblocks", "ee-reorder", "raster"};

struct GsParams {
  // GIF -> GS transfer and drawing (docs/hardware.md#gs-rates, #gs-page-breaks).
  std::int64_t gif_bytes_per_tick = 8;         // 64-bit GIF bus, one word per bus clock
  std::int64_t upload_setup_qwords = 6;        // GIFtag + BITBLTBUF, TRXPOS, TRXREG, TRXDIR + IMAGE GIFtag
  std::int64_t macroblock_setup_qwords = 4;    // per further macroblock: GIFtag + TRXPOS, TRXDIR + IMAGE GIFtag
  std::int64_t textured_pixels_per_clock = 8;  // textured fill rate
  std::int64_t page_break_overhead_pct = 25;   // extra draw time for DRAM page breaks (assumption)

  // VRAM layout besides the lightmap (whose size comes from the stream).
  std::int64_t frame_buffers = 2;
  std::int64_t frame_width = 640;
  std::int64_t frame_height = 448;
  std::string frame_format = "ct32";
  std::string depth_format = "z16";  // or "none"
  std::int64_t sky_width = 256;      // 0: no sky texture
  std::int64_t sky_height = 256;
  std::string upload_mode = "full";  // or "strips"
  std::int64_t strip_rows = 32;      // rows per strip in strip mode (a multiple of 32: one page high)
  // How the IPU's output, 16x16 macroblocks in macroblock order, reaches the staging texture
  // (docs/porting.md): one IMAGE transfer per macroblock, the EE reordering it into a raster image
  // first (then one transfer), or "raster": one transfer with no reorder, as if the IPU wrote rows.
  std::string upload_strategy = "macroblocks";  // or "ee-reorder", "raster"
  // The texels of the blended textures (lightmap, sky) and their staging areas: ct32, or ct16 (the
  // IPU's RGB16 output with DTE = 1, blended into a PSMCT16 texture with DTHE: gs/blend16.hpp).
  std::string texture_format = "ct32";  // or "ct16"

  // Presentation.
  std::string video = "ntsc";             // ntsc, ntsc-p, pal, pal-p
  std::int64_t fix = 64;                  // ALPHA.FIX per vsync
  std::string colclamp = "clamp";         // or "wrap"
  std::string alpha_write = "source";     // or "keep" (FBMSK protects the lightmap's alpha)
  std::string catchup = "blend-through";  // or "hard-skip", "play-late"
  std::int64_t catchup_fix = 0;           // FIX while behind schedule; 0 = same as fix
  bool loop = true;                       // wrap from the last frame to the first
  bool convergence_aware = true;          // host-side shortcut; bit-identical, no simulated-time effect
};

// Registers every field under "gs." with its unit, range and source.
void describeParams(ParamTable& table, GsParams& params);

}  // namespace vbim::gs
