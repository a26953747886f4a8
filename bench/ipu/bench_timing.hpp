// Timing helpers of the IPU decode benches (decode_bench.cpp, gop_decode_bench.cpp).
#pragma once

#include <benchmark/benchmark.h>

#include <algorithm>
#include <ctime>
#include <vector>

namespace vbim::bench {

// Thread CPU time: the machine is shared, so wall time would measure the neighbours.
inline double cpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// CPU seconds per frame of one d.run(clip) decoding `frames` frames.
template <class D, class C>
double secondsPerFrame(D& d, const C& clip, int frames) {
  const double t0 = cpuSeconds();
  benchmark::DoNotOptimize(d.run(clip));
  return (cpuSeconds() - t0) / frames;
}

}  // namespace vbim::bench
