// The runs behind `vbim profile` (and the demo's profile pass): one player run of a configuration
// with a compact per-vsync series for the plots, and the search for the longest drive stall a
// configuration survives.
//
// "Survives" (docs/player.md, "Profiling"): a run with one drive stall of length D starting at
// `stallAt`, played until `stallAt + D + settle`, survives when
//   - criterion "no-late-frame": at no vsync was the newest due lightmap frame missing (behind == 0)
//                       and no frame became the target after it was due (framesLate == 0);
//   - criterion "pop":  the largest per-vsync change of a lightmap byte (pop, the first frame copied
//                       into the empty lightmap excluded) stays at or below the threshold. The
//                       default threshold ("auto") is the pop maximum of the same configuration
//                       without the stall over the longest window searched: the stall must not make
//                       a jump larger than normal playback makes (the samples change a lot from one
//                       stream frame to the next, so normal pops are large).
// The search is a bisection on the simulated clock over integer ticks in [0, maxStall] down to
// `resolution`: deterministic, the same answer on every machine. It assumes survival is monotone in
// D (a longer stall never helps), which holds for a single stall: the buffers only drain longer.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "iop/fault_plan.hpp"
#include "iop/sector_source.hpp"
#include "player/fault_spans.hpp"
#include "player/player.hpp"

namespace vbim::sweep {

// How close a re-encoded stream's lightmap is to the frames it was made from (measured by
// sweep/outputs/stream_quality.hpp): luma PSNR per frame in dB, its mean and minimum over frames.
struct StreamQuality {
  double meanDb = 0;
  double minDb = 0;
  std::int64_t frames = 0;
};

// A stream to play: a disc and the file on it, with a label for tables and legends, and its quality
// when it is a re-encode that was measured.
struct Stream {
  std::string label;
  std::shared_ptr<iop::SectorSource> disc;
  iop::DiscFile file;
  std::optional<StreamQuality> quality;
};

// A bare stream file on a notional disc, as `vbim play` places it (throws iop::DiscError for a file
// that is missing or not whole sectors).
std::shared_ptr<Stream> bareStream(const std::string& path);
// A stream held in memory (a re-encoded one) on a notional disc laid out as bareStream's, labelled
// `label` (its disc is named "<label> (re-encoded in memory)").
std::shared_ptr<Stream> memoryStream(const std::string& label, std::vector<std::uint8_t> bytes);

struct Case {
  const Stream* stream = nullptr;
  player::PlatformConfig config;  // ring size and catch-up policy already set
  iop::FaultPlan faults;
  std::uint64_t seed = 1;
  Tick duration = 0;
  bool reference = true;    // measure lag against a fault-free reference (costs a second pipeline)
  player::Kernels kernels;  // SIMD kernels injected by the caller (null: the scalar references, same bytes)
};

// One vsync, as the plots need it.
struct Sample {
  double t = 0;  // simulated seconds
  int ringBanks = 0;
  int lag = 0;
  int pop = 0;  // as CaseResult::pop
  int skyPop = 0;
  bool behind = false;
};

struct CaseResult {
  gs::PresenterCounters lightmap;
  player::RunTotals totals;
  std::int64_t ringUnderruns = 0;
  std::int64_t driveRetries = 0;
  std::int64_t framesLost = 0;
  std::int64_t streamBytes = 0;
  // The stream's length (descriptor: frames over all variants, game frames per second), for its
  // bitrate and sectors per frame; and the quality of a measured re-encode.
  std::int64_t streamFrames = 0;
  std::int64_t gameFpsNum = 1, gameFpsDen = 1;
  std::optional<StreamQuality> quality;
  // Busy time over the run's simulated time: the IPU's command time and the EE's work in the BDEC
  // flow of P and B pictures (zero for an intra-only stream: its IDEC path has no EE work modelled).
  Tick elapsed = 0;
  Tick ipuBusy = 0;
  Tick eeBusy = 0;
  // Largest lightmap pop, counting every vsync after the first frame was shown: unlike the player's
  // totals (which leave out every snapped frame), a hard-skip snap counts here, as a viewer sees it.
  player::Extreme pop;
  std::vector<Sample> series;  // empty unless asked for
  // With the series: when the drive was disturbed (as a run directory's faults.csv), for the plots.
  std::vector<player::FaultSpan> faults;
};

// Runs one case (throws what the player throws: streams::StreamProbeError, ConfigError, gs::GsError).
CaseResult runCase(const Case& c, bool keepSeries);

enum class Criterion { Late, Pop };
const char* toString(Criterion c);

struct StallSearch {
  Tick stallAt = 0;
  Tick maxStall = 0;
  Tick resolution = 0;
  Tick settle = 0;
  int popThreshold = -1;  // -1: auto (see above)
};

struct StallResult {
  // The longest survivable stall found, or nullopt when the case fails even without a stall.
  std::optional<Tick> longest;
  bool saturated = false;  // survived maxStall: the real limit is at least that
  int runs = 0;            // player runs the search took
  int popThreshold = -1;   // the threshold used (criterion pop)
};

// `base` supplies stream, config, seed and any other faults; the stall is added to its plan. The
// reference pipeline is not built (lag is not a criterion).
StallResult longestSurvivableStall(const Case& base, const StallSearch& search, Criterion criterion);

}  // namespace vbim::sweep
