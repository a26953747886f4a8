// What the GS work of one vsync costs on the simulated clock (1 tick = 1 GS clock = 1 bus clock).
//   IMAGE transfer over PATH3: (setup qwords * 16 + payload bytes) / GIF bytes per tick.
//   Textured SPRITE draw with the blend: the register writes of gs/draw_setup.hpp over the GIF, then
//   pixels / (textured px per clock) * (1 + page-break overhead).
// Both round up to whole ticks. Sources: gs/params.cpp and docs/timing/gs.md.
#pragma once

#include <cstdint>

#include "gs/draw_setup.hpp"
#include "gs/params.hpp"
#include "runtime/clock.hpp"

namespace vbim::gs {

class GsTiming {
 public:
  explicit GsTiming(const GsParams& p) : p_(p) {}
  Tick imageTransfer(std::int64_t payloadBytes) const {
    return ceilDiv(p_.upload_setup_qwords * 16 + payloadBytes, p_.gif_bytes_per_tick);
  }
  Tick spriteDraw(std::int64_t width, std::int64_t height) const {
    const Tick setup = ceilDiv(kBlendDrawSetupQwords * 16, p_.gif_bytes_per_tick);
    return setup + ceilDiv(width * height * (100 + p_.page_break_overhead_pct), 100 * p_.textured_pixels_per_clock);
  }

 private:
  static constexpr std::int64_t ceilDiv(std::int64_t a, std::int64_t b) { return (a + b - 1) / b; }
  GsParams p_;
};

}  // namespace vbim::gs
