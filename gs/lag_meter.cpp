#include "gs/lag_meter.hpp"

#include <algorithm>
#include <cstdlib>

#include "gs/error.hpp"

namespace vbim::gs {

LagSample compareImages(const Rgba8Image& a, const Rgba8Image& b) {
  if (!a.sameSize(b)) throw GsError("lag between lightmaps of different sizes");
  LagSample s;
  const std::uint8_t* pa = a.pixels.data();
  const std::uint8_t* pb = b.pixels.data();
  int mx = 0;
  std::int64_t sum = 0;
  for (std::size_t i = 0, n = a.pixels.size(); i < n; ++i) {
    const int d = std::abs(static_cast<int>(pa[i]) - static_cast<int>(pb[i]));
    mx = std::max(mx, d);
    sum += d;
  }
  s.maxDiff = mx;
  s.sumDiff = sum;
  return s;
}

LagMeter::LagMeter(Presenter& run, Presenter& reference, Tracer* tracer, const std::string& name)
    : run_(run), ref_(reference), tracer_(tracer) {
  if (tracer_ != nullptr && tracer_->enabled()) counter_ = tracer_->counter(name + ".lag");
}

Task<void> LagMeter::measure(Tick end) {
  const VsyncClock clock = run_.clock();
  for (std::int64_t n = 0; clock.time(n) < end; ++n) {
    while (run_.presented() <= n) co_await run_.presentedEvent().wait();
    while (ref_.presented() <= n) co_await ref_.presentedEvent().wait();
    LagSample s = compareImages(run_.lightmap(), ref_.lightmap());
    s.vsync = n;
    maxLag_ = std::max(maxLag_, s.maxDiff);
    samples_.push_back(s);
    if (tracer_ != nullptr && tracer_->enabled()) tracer_->value(counter_, run_.clock().time(n), s.maxDiff);
  }
}

}  // namespace vbim::gs
