// Lag: how far a presenter's lightmap is from a stall-free reference presenter's at the same vsync.
// Both run in the same scheduler; the reference is fed on time (every frame ready when due). After
// both have presented vsync n, the meter compares the two lightmaps: the largest per-byte
// difference and the sum of differences (for a mean).
#pragma once

#include <cstdint>
#include <vector>

#include "gs/image_compare.hpp"
#include "gs/presenter.hpp"
#include "gs/twin_tiles.hpp"

namespace vbim::gs {

struct LagSample {
  std::int64_t vsync = 0;
  int maxDiff = 0;           // largest per-byte |run - reference|
  std::int64_t sumDiff = 0;  // sum over every byte
};

// Largest and summed per-byte difference of two same-sized images (throws GsError otherwise), with
// the kernels' compareRect (the scalar reference by default; any kernels give the same numbers).
LagSample compareImages(const Rgba8Image& a, const Rgba8Image& b, const BlendKernels& kernels = scalarKernels());

// The difference of two presenters' lightmaps, kept per 64x32 tile and brought up to date by
// comparing again only the tiles that either presenter's blender changed since the last update
// (TiledBlender::tileChanges: the blender is the only writer of a lightmap). The totals are those
// of compareImages on the whole images, at a cost proportional to the tiles that moved: none on a
// vsync where neither lightmap changed, few once they converge.
class TiledDifference {
 public:
  // Throws GsError for lightmaps of different sizes. With `equal` (the tiles known equal, kept with
  // the reference's blender: TiledBlender::Twin), a moved tile known equal is not compared, and a
  // compared tile found equal is added to it.
  TiledDifference(const Presenter& run, const Presenter& reference, CompareRectFn compare, TwinTiles* equal = nullptr);
  // The difference of the two lightmaps as they are now.
  ByteDifference update();

 private:
  const Presenter& run_;
  const Presenter& ref_;
  CompareRectFn compare_;
  TwinTiles* equal_;
  int tilesX_;
  int tilesY_;
  std::vector<std::uint64_t> runSeen_;  // each blender's tileChanges() at the last update
  std::vector<std::uint64_t> refSeen_;
  std::vector<ByteDifference> tiles_;  // each tile's difference at the last update
  bool first_ = true;                  // no tile compared yet
};

class LagMeter {
 public:
  LagMeter(Presenter& run, Presenter& reference, Tracer* tracer = nullptr, const std::string& name = "gs");
  // The process: measures vsyncs 0, 1, ... while their time is before `end`.
  Task<void> measure(Tick end);
  const std::vector<LagSample>& samples() const { return samples_; }
  int maxLag() const { return maxLag_; }

 private:
  Presenter& run_;
  Presenter& ref_;
  Tracer* tracer_;
  Tracer::CounterId counter_ = 0;
  std::vector<LagSample> samples_;
  int maxLag_ = 0;
};

}  // namespace vbim::gs
