// `vbim profile STREAM...`: a profile sweep as the command makes it: the discs opened (bare stream
// files or the stream on ISO 9660 images), re-encoded when asked, the platform config and fault plans
// read, the times and the stall search checked, the sweep run (sweep/profile_sweep.hpp) and its
// outputs written into an output directory, complete or absent (sweep/outputs/profile_outputs.hpp).
// Not model code: it reads TOML (config/); the re-encoding (FFmpeg) is the caller's to give.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sweep/profile_sweep.hpp"

namespace vbim::runs {

struct ProfileRequest {
  std::vector<std::string> discs;
  std::string file;  // the stream on each disc image (--file), or empty: its only VBIM stream
  std::string config;
  std::vector<std::string> faults;
  std::vector<std::string> rings{"4:8", "4:16", "4:32", "4:64", "5:160"};
  std::vector<int> qscales;
  std::vector<std::int64_t> bitrates;
  std::vector<std::string> policies{"blend-through"};
  std::uint64_t seed = 1;
  std::string duration = "20s";
  std::string stallAt = "3s";
  std::string maxStall = "20s";
  std::string resolution = "50ms";
  std::string settle = "5s";
  std::string popThreshold = "auto";
  bool search = true;
  bool force = false;
  bool json = false;  // the summary as JSON on stdout (runs/profile_json.hpp), for the command
  std::string out;
};

// The first disc's stream re-encoded at each quantiser and bitrate (sweep/outputs/reencoded_streams.hpp,
// FFmpeg: given by the programs that link it).
using Reencoder = std::function<std::vector<std::shared_ptr<sweep::Stream>>(
    const sweep::Stream& first, const std::string& path, const std::vector<int>& qscales,
    const std::vector<std::int64_t>& bitrates)>;

// True when the request re-encodes a stream (--qscale, --bitrate): it needs a Reencoder.
bool reencodes(const ProfileRequest& r);

// What the command is told while the sweep runs: the number of sweep runs and stall searches first,
// then each as it ends.
struct ProfileObserver {
  std::function<void(std::size_t total)> onStart;
  sweep::SweepObserver sweep;
  // Once the outputs are written, just before they take their names: a throw here (the command's
  // Ctrl-C check) leaves no output.
  std::function<void()> beforeCommit;
};

struct ProfileResult {
  sweep::ProfileData data;
  std::vector<std::string> written;  // the files, as named in the finished output directory
};

// Throws vbim::Error on bad input (an option, a file, a config the GS refuses: named as
// config::gsConfigMessage says it, or a re-encode asked for without `reencode`) and RunFailure when
// an output cannot be written. An existing, non-empty `out` is refused before the sweep.
ProfileResult profileRun(const ProfileRequest& r, const Reencoder& reencode, const ProfileObserver& observer);

// What `vbim profile` says of a sweep run as it ends: its line ("sweep  STREAM  ring B:S  faults F
// POLICY: late N, pop max P, lag max L", then STARVED or STUCK when the display stopped) and, for
// such a run, the health warning (player::healthWarning, said against the run; "" otherwise).
struct SweepRunReport {
  std::string line;
  std::string warning;
};
SweepRunReport sweepRunReport(const sweep::SweepRun& run);

// ... and of a stall search: "stall  STREAM  ring B:S  POLICY  CRITERION: T s (N runs)", the longest
// stall survived (">= T s" when the search reached its maximum) or "fails without a stall".
std::string stallSearchLine(const sweep::StallRow& row);

}  // namespace vbim::runs
