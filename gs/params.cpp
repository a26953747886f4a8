#include "gs/params.hpp"

#include "runtime/param_table.hpp"

namespace vbim::gs {

void describeParams(ParamTable& t, GsParams& p) {
  t.addInt("gs.gif_bytes_per_tick", &p.gif_bytes_per_tick, 1, 64, "bytes/tick",
           "GIF->GS is 64 bits per bus clock = 1.18 GB/s (LINUXKIT 1.2 GB/s [D]; docs/hardware.md#gs-rates)");
  t.addInt("gs.upload_setup_qwords", &p.upload_setup_qwords, 0, 1024, "qwords",
           "A+D GIFtag + BITBLTBUF, TRXPOS, TRXREG, TRXDIR, then the IMAGE GIFtag (T-GS Transfers)");
  t.addInt("gs.macroblock_setup_qwords", &p.macroblock_setup_qwords, 0, 1024, "qwords",
           "per macroblock after the first with gs.upload_strategy = macroblocks: A+D GIFtag + TRXPOS (the "
           "macroblock's corner) and TRXDIR (starts the transfer), then the IMAGE GIFtag; BITBLTBUF and TRXREG "
           "(16x16) stay set (T-GS Transfers)");
  t.addInt("gs.textured_pixels_per_clock", &p.textured_pixels_per_clock, 1, 16, "px/GS clock",
           "textured fill rate 8 px/clk = 1.18 Gpix/s (WIKI-GS Specifications)");
  t.addInt("gs.page_break_overhead_pct", &p.page_break_overhead_pct, 0, 400, "%",
           "assumption: DRAM page breaks while sweeping a sprite cost about a quarter more; no public figure "
           "(docs/hardware.md#gs-page-breaks)");

  t.addInt("gs.frame_buffers", &p.frame_buffers, 0, 3, "buffers",
           "double buffering, as a game has (VRAM budget example, docs/hardware.md#vram)");
  t.addInt("gs.frame_width", &p.frame_width, 64, 2048, "px", "640x448 NTSC interlaced frame (docs/hardware.md#vram)");
  t.addInt("gs.frame_height", &p.frame_height, 32, 2048, "px", "640x448 NTSC interlaced frame (docs/hardware.md#vram)");
  t.addChoice("gs.frame_format", &p.frame_format, {"ct32", "ct24", "ct16"},
              "PSMCT32 frame buffers (VRAM budget example, docs/hardware.md#vram)");
  t.addChoice("gs.depth_format", &p.depth_format, {"none", "z32", "z24", "z16"},
              "16-bit Z (VRAM budget example, docs/hardware.md#vram)");
  t.addInt("gs.sky_width", &p.sky_width, 0, 1024, "px", "assumption: a 256x256 sky dome texture, the second stream");
  t.addInt("gs.sky_height", &p.sky_height, 0, 1024, "px", "assumption: a 256x256 sky dome texture, the second stream");
  t.addChoice("gs.upload_mode", &p.upload_mode, {"full", "strips"},
              "full: the whole frame is uploaded to a staging texture; strips: uploaded and blended in horizontal "
              "strips through a small staging area (Hoffman & Mitchell, GDC 2001: 'performed in place ... to reduce "
              "VRAM use')");
  t.addInt("gs.strip_rows", &p.strip_rows, 32, 1024, "rows",
           "assumption: one PSMCT32 page high (32 rows); must be a multiple of 32");
  t.addChoice("gs.upload_strategy", &p.upload_strategy, {kUploadStrategies.begin(), kUploadStrategies.end()},
              "macroblocks: the IPU writes 16x16 macroblocks in macroblock order (T-IPU IDEC), uploaded one IMAGE "
              "transfer each; ee-reorder: the EE copies them into a raster image first (ee.reorder_cycles_per_qword), "
              "then one transfer; raster: one transfer and no reorder, vbim's model before macroblock order "
              "(docs/porting.md)");

  t.addChoice("gs.texture_format", &p.texture_format, {"ct32", "ct16"},
              "ct32: PSMCT32 textures from the IPU's RGB32 output; ct16: the 16-bit lightmap path, PSMCT16 textures "
              "and staging areas from its RGB16 output (OFM = 1, DTE = 1), blended with DTHE and the usual DIMX "
              "(half the VRAM and upload bytes; docs/porting.md, \"The 16-bit lightmap path\")");

  t.addChoice("gs.video", &p.video, {"ntsc", "ntsc-p", "pal", "pal-p"},
              "vsync rate: NTSC 59.94 Hz interlaced, PAL 50 Hz (PCSX2 Counters.cpp)");
  t.addInt("gs.fix", &p.fix, 0, 255, "1/128",
           "assumption: 0x40, a 50 % temporal low-pass per vsync; Hoffman & Mitchell give no value "
           "(docs/hardware.md#blend-weight)");
  t.addChoice("gs.colclamp", &p.colclamp, {"clamp", "wrap"},
              "COLCLAMP bit 0 = 1: clamp to 0..255 (T-GS AlphaBlending)");
  t.addChoice("gs.alpha_write", &p.alpha_write, {"source", "keep"},
              "source: the lightmap's alpha is the frame's As; keep: FRAME.FBMSK protects it (SDK-GS GS_SET_FRAME)");
  t.addChoice("gs.catchup", &p.catchup, {kCatchupPolicies.begin(), kCatchupPolicies.end()},
              "blend-through: keep blending toward the newest due frame (Hoffman & Mitchell, GDC 2001: 'smooth "
              "catch up frames'); hard-skip and play-late for comparison");
  t.addInt("gs.catchup_fix", &p.catchup_fix, 0, 255, "1/128",
           "assumption: off (0); a larger FIX while behind schedule shortens catch-up at the cost of bigger steps");
  t.addBool("gs.loop", &p.loop,
            "Hoffman & Mitchell, GDC 2001: the lighting video loops; the blend hides the jump from the last frame "
            "to the first");
  t.addBool("gs.convergence_aware", &p.convergence_aware,
            "host-side speed-up: skip 64x32 tiles already at the blend's fixed point; bit-identical, "
            "no effect on simulated time");
}

}  // namespace vbim::gs
