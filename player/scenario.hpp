// The test API: build a scenario (disc, platform config, fault plan, seed), run it to a time, and read
// the frames, hashes and metrics, from your own GoogleTest suites. docs/test-api.md has a worked
// example (examples/stall-test/, compiled and run in ctest).
//
//   using namespace vbim;
//   auto run = player::Scenario::bareFile("day_clear.vbim")
//                  .seed(7)
//                  .stall(fromMs(5'000), fromMs(3'000))
//                  .start(fromMs(20'000));
//   run->runTo(fromMs(7'000));
//   EXPECT_TRUE(run->lastRow().lightmap.behind);   // starved during the stall
//   run->runToEnd();
//   EXPECT_EQ(run->lastRow().lag, 0);              // caught up with the fault-free run
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "iop/fault_plan.hpp"
#include "iop/file_disc.hpp"
#include "iop/sector_source.hpp"
#include "player/player.hpp"

namespace vbim::player {

// Where Scenario::bareFile (and `vbim play`) put a bare stream file on the notional disc: the IOP's
// placement of a bare file (iop/file_disc.hpp), named here for the test API.
using iop::kBareFileLba;
using iop::kBareFilePadSectors;

// A run in progress: the player plus every row recorded so far.
class Run {
 public:
  Run(std::shared_ptr<iop::SectorSource> disc, const iop::DiscFile& file, PlayerOptions options);

  void runTo(Tick t) { player_.runTo(t); }
  void runToEnd() { player_.runToEnd(); }
  Tick now() const { return player_.now(); }

  // Frames as they are now.
  const Rgba8Image& lightmap() const { return player_.lightmap(); }
  const Rgba8Image* sky() const { return player_.sky(); }
  // One row per vsync presented so far (hash, presenter records, pop, lag, ring occupancy).
  const std::vector<VsyncRow>& rows() const { return rows_; }
  const VsyncRow& lastRow() const { return rows_.back(); }
  std::vector<std::uint64_t> hashes() const;
  // The first row at or after time t (throws std::out_of_range if none yet).
  const VsyncRow& rowAt(Tick t) const;
  // Metrics: presenter counters, totals (pop / lag maxima, ring occupancy), stats.json text.
  const gs::PresenterCounters& counters() const {
    return const_cast<Player&>(player_).pipeline().lightmap().counters();
  }
  const RunTotals& totals() const { return player_.totals(); }
  std::string statsJson() const;
  Player& player() { return player_; }

 private:
  std::shared_ptr<iop::SectorSource> disc_;
  Player player_;
  std::vector<VsyncRow> rows_;
};

class Scenario {
 public:
  // A bare stream file placed at kBareFileLba (throws iop::DiscError if unreadable).
  static Scenario bareFile(const std::string& path);
  // Any disc and the stream file on it.
  Scenario(std::shared_ptr<iop::SectorSource> disc, iop::DiscFile file);

  Scenario& config(const PlatformConfig& c);
  Scenario& faults(const iop::FaultPlan& plan);
  // Convenience faults (added to the plan): a drive stall; a sector of the stream file that fails
  // `attempts` read attempts.
  Scenario& stall(Tick at, Tick duration);
  Scenario& readError(std::int64_t fileSector, std::int64_t attempts);
  Scenario& seed(std::uint64_t s);
  Scenario& branch(Tick at, int variant);
  Scenario& policy(const std::string& catchup);  // "blend-through", "hard-skip", "play-late"
  Scenario& kernels(Kernels k);
  Scenario& trace(bool on);

  const iop::DiscFile& file() const { return file_; }
  // The disc, e.g. for config::parseFaultPlan to resolve `file = "..."` entries.
  const iop::SectorSource& disc() const { return *disc_; }
  PlayerOptions& options() { return options_; }
  // Builds the run (probing the stream: throws streams::StreamProbeError) with vsyncs up to `duration`.
  std::unique_ptr<Run> start(Tick duration) const;

 private:
  std::shared_ptr<iop::SectorSource> disc_;
  iop::DiscFile file_;
  PlayerOptions options_;
};

}  // namespace vbim::player
