// Which 64x32 tiles of two lightmaps are known to hold the same bytes: the run's and its fault-free
// reference's (issue #31). A tile's bytes are named by its blender's change count
// (TiledBlender::tileChanges: every blend that moves a byte of the tile counts one, and nothing else
// writes a lightmap), so "run tile i at count a equals reference tile i at count b" stays true for
// good once seen. Two readers use the facts: the reference's blender, which copies the run's tile
// instead of blending it again when the run made the same blend from the same bytes
// (TiledBlender::Twin), and the lag's TiledDifference, which does not compare tiles known equal.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace vbim::gs {

class TwinTiles {
 public:
  explicit TwinTiles(std::size_t tiles) : run_(tiles, kNone), ref_(tiles, kNone) {}

  // Run tile i at change count runCount holds the bytes of reference tile i at refCount.
  void setEqual(std::size_t i, std::uint64_t runCount, std::uint64_t refCount) {
    run_[i] = runCount;
    ref_[i] = refCount;
  }
  // Whether that is known (the newest fact per tile is kept; older ones are about older bytes).
  bool equalAt(std::size_t i, std::uint64_t runCount, std::uint64_t refCount) const {
    return run_[i] == runCount && ref_[i] == refCount;
  }
  std::size_t size() const { return run_.size(); }

 private:
  static constexpr std::uint64_t kNone = ~std::uint64_t{0};  // no fact yet (no count reaches it)
  std::vector<std::uint64_t> run_;
  std::vector<std::uint64_t> ref_;
};

}  // namespace vbim::gs
