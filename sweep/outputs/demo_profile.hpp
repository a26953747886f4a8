// `vbim demo`'s profile pass: the occupancy and the lag and pop of the demo's own run (from its
// vsync rows), and a small survivable-stall curve (five ring sizes, the default policy, both
// criteria) on the same stream: plots/*.png, *.svg and plots/survivable_stall.csv. A few seconds of
// host time.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "player/player.hpp"
#include "sweep/profile_run.hpp"

namespace vbim::sweep {

class DemoProfile {
 public:
  // Every vsync row of the demo's run, in order.
  void onRow(const player::VsyncRow& row);
  // Writes plots/ into `dir` (which exists); `disc` is the demo's stream file. `checkStop` is called
  // before each stall search (a few tenths of a second each); it may throw to stop.
  void write(const std::string& disc, const std::filesystem::path& dir, const std::function<void()>& checkStop = {});
  // Host seconds write() took (the demo's summary only; never hashed).
  double seconds() const { return seconds_; }

 private:
  std::vector<Sample> series_;
  bool shown_ = false;
  double seconds_ = 0;
};

}  // namespace vbim::sweep
