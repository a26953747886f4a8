// One run of the player on a disc, as `vbim play` and `vbim demo` make it: the disc opened (a bare
// stream file or the stream on an ISO 9660 image), the platform config and fault plan read, the
// options checked, and every output written into a run directory (player::RunDirWriter through an
// OutputDir: complete or absent), or, without `out`, nothing written at all: the summary only.
// Not model code: it reads TOML (config/), writes pictures (imageio/) and digests (OpenSSL); the
// simulated clock's cost is the player's, the host's is in the summary.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "imageio/texel_files.hpp"
#include "player/player.hpp"
#include "runs/output_dir.hpp"

namespace vbim::runs {

struct PlayRequest {
  std::string disc;
  std::string discLabel;   // how the summary and stats.json name the disc (default: the path given)
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
  std::string alpha = "opaque";                   // pictures' alpha: opaque (RGB, none) or gs (the texels as in VRAM)
  std::vector<std::string> branches;              // "12.5s=1": switch to variant 1 at 12.5 s
  bool force = false;
  bool json = false;  // PlayResult::summary as JSON (runs/play_json.hpp)
  bool trace = true;
  std::string traceDetail =
      "coalesced";       // "full": every same-instant toggle in signals.vcd; "ipu": ipu_commands.csv too
  unsigned threads = 1;  // host threads for the IPU's slice-parallel decode (same bytes)
  // The run directory, or empty: the run is played and summarised, and nothing is written (no
  // directory, no temporary one); --every and --at, which ask for pictures, are refused then.
  std::string out;
  // Hooks for callers that add outputs (vbim demo's profile plots): every recorded vsync, and the
  // output directory just before it is committed (only with `out`).
  std::function<void(const player::VsyncRow&)> onRow;
  std::function<void(const OutputDir&)> beforeCommit;
};

struct PlayResult {
  std::string summary;        // one paragraph: what was played, frames, pop, lag, ring, pictures
  std::string warning;        // a run that stopped showing frames (player::healthWarning), or empty
  bool jsonReplaced = false;  // --json: bytes of the inputs not UTF-8 written as U+FFFD (kNotUtf8Warning)
};

// Called after each simulated second with the time played and the run's length, in seconds (a
// progress line; a place to stop the run by throwing).
using PlayProgressFn = std::function<void(double played, double total)>;

// Throws vbim::Error on bad input (an option, a file, a config the GS refuses: named as
// config::gsConfigMessage says it) and RunFailure (runs/error.hpp) when an output cannot be written.
PlayResult playRun(const PlayRequest& r, const PlayProgressFn& onSecond);

// A lightmap or sky picture of a run: PNG (at format.pngLevel) or EXR, RGB (opaque) unless
// format.gsAlpha (RGBA, the texels as in VRAM); `texels` is only read.
// `path` is in a run's directory while an OutputDir stages it (play, replay): the file is written
// under its own name, no temporary of its own and no rename (imageio/replace_file.hpp), as nothing
// in the staged directory is seen before OutputDir::commit renames it whole, and a failed or
// interrupted run removes it whole. Throws RunFailure when it cannot be written.
void writeRunImage(const std::filesystem::path& path, const Rgba8Image& texels, const imageio::TexelFileFormat& format);

}  // namespace vbim::runs
