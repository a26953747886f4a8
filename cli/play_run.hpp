// The body of `vbim play`, shared with `vbim demo`: one run of the player on a disc, every output
// written into an OutputDir (complete or absent).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "cli/output_dir.hpp"
#include "imageio/texel_files.hpp"
#include "iop/fault_plan.hpp"
#include "player/player.hpp"

namespace vbim::cli {

struct PlayRequest {
  std::string disc;
  std::string discLabel;   // how the summary names the disc (default: the path given)
  std::string file;        // the stream file on an ISO 9660 image (--file), or empty: the default
  std::string config;      // platform config TOML, or empty
  std::string faults;      // fault plan TOML path, or empty
  std::string faultsText;  // a fault plan given inline (the demo's built-in one), used if faults is empty
  std::uint64_t seed = 1;
  std::string duration = "60s";
  std::string policy;  // blend-through|hard-skip|play-late, or empty (the config's gs.catchup)
  std::int64_t every = 0;
  std::vector<std::string> at;
  std::string format = "png";
  int pngLevel = imageio::kDefaultTexelPngLevel;  // --png-level: 0 stored, 1 to 9 compressed (zlib)
  std::string alpha = "opaque";                   // pictures' alpha: opaque (255) or gs (the texels as in VRAM)
  std::vector<std::string> branches;              // "12.5s=1": switch to variant 1 at 12.5 s
  bool force = false;
  bool trace = true;
  std::string traceDetail = "coalesced";  // or "full": every same-instant toggle in signals.vcd
  unsigned threads = 1;                   // host threads for the IPU's slice-parallel decode (same bytes)
  std::string out;
  // Hooks for callers that add outputs (vbim demo's profile plots): every recorded vsync, and the
  // output directory just before it is committed.
  std::function<void(const player::VsyncRow&)> onRow;
  std::function<void(const OutputDir&)> beforeCommit;
};

// Returns a one-paragraph summary; throws cli::Exit on bad input.
std::string runPlay(const PlayRequest& r, bool progress);

// A lightmap or sky picture of a run: PNG (at format.pngLevel) or EXR, alpha 255 unless
// format.gsAlpha (the texels as in VRAM; set in place in `texels`, the caller's copy). Throws
// cli::Exit(1) when it cannot be written.
void writeRunImage(const std::filesystem::path& path, Rgba8Image& texels, const imageio::TexelFileFormat& format);

}  // namespace vbim::cli
