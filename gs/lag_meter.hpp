// Lag: how far a presenter's lightmap is from a stall-free reference presenter's at the same vsync.
// Both run in the same scheduler; the reference is fed on time (every frame ready when due). After
// both have presented vsync n, the meter compares the two lightmaps: the largest per-byte
// difference and the sum of differences (for a mean).
#pragma once

#include <cstdint>
#include <vector>

#include "gs/presenter.hpp"

namespace vbim::gs {

struct LagSample {
  std::int64_t vsync = 0;
  int maxDiff = 0;           // largest per-byte |run - reference|
  std::int64_t sumDiff = 0;  // sum over every byte
};

// Largest and summed per-byte difference of two same-sized images.
LagSample compareImages(const Rgba8Image& a, const Rgba8Image& b);

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
