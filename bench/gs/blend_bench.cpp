// The in-place blend of a 512x512 RGBA8 frame, ((Cs - Cd) * FIX >> 7) + Cd, side by side with
// memcpy of the same 1 MiB. Target (issue #6): the blend at least half as fast as memcpy, i.e.
// blend_vs_memcpy = memcpy time / blend time >= 0.5. Anchors on a machine like this one
// (docs/dependencies.md#speed-anchors): memcpy 26-30 us, 16-bit-lane AVX2 blend ~67 us, AVX-512 44 us,
// scalar 470-670 us.
//
// BM_BlendVsMemcpy alternates both in one loop (same cache state, same moment) and reports the
// ratio; the others time each kernel alone. BM_SteadyConverged is the convergence-aware mode on a
// lightmap already at its fixed point: the cost of a long steady stretch.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstring>
#include <ctime>
#include <string>
#include <utility>
#include <vector>

#include "gs/simd/blend_simd.hpp"
#include "gs/tiled_blender.hpp"
#include "runtime/image.hpp"
#include "runtime/rng.hpp"

namespace {

using vbim::Rgba8Image;
using namespace vbim::gs;

constexpr int kSide = 512;
constexpr std::size_t kPixels = static_cast<std::size_t>(kSide) * kSide;

Rgba8Image randomFrame(std::uint64_t seed) {
  vbim::Rng rng(seed);
  Rgba8Image img(kSide, kSide);
  for (auto& b : img.pixels) b = static_cast<std::uint8_t>(rng.below(256));
  return img;
}

const BlendSpec kSpec = makeBlendSpec(64);

// This thread's CPU time: the machine is shared, so wall time mostly measures the neighbours.
struct CpuClock {
  using duration = std::chrono::nanoseconds;
  using time_point = std::chrono::time_point<CpuClock>;
  static time_point now() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return time_point(duration(static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec));
  }
};

void BM_Memcpy(benchmark::State& state) {
  const Rgba8Image src = randomFrame(1);
  Rgba8Image dst = randomFrame(2);
  for (auto _ : state) {
    std::memcpy(dst.pixels.data(), src.pixels.data(), dst.pixels.size());
    benchmark::DoNotOptimize(dst.pixels.data());
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * kPixels * 4);
}
BENCHMARK(BM_Memcpy)->Unit(benchmark::kMicrosecond);

void blendBench(benchmark::State& state, const BlendKernels& k, bool delta) {
  const Rgba8Image a = randomFrame(1), b = randomFrame(3);
  Rgba8Image dst = randomFrame(2);
  bool flip = false;
  for (auto _ : state) {
    const Rgba8Image& src = flip ? a : b;  // alternate targets so the lightmap keeps moving
    flip = !flip;
    if (delta) {
      benchmark::DoNotOptimize(k.blendDelta(dst.pixels.data(), src.pixels.data(), kPixels, kSpec));
    } else {
      k.blend(dst.pixels.data(), src.pixels.data(), kPixels, kSpec);
    }
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * kPixels * 4);
  state.SetLabel(k.name);
}
void BM_BlendScalar(benchmark::State& state) {
  blendBench(state, scalarKernels(), false);
}
void BM_BlendSimd(benchmark::State& state) {
  blendBench(state, simd::kernels(), false);
}
void BM_BlendSimdWithPop(benchmark::State& state) {
  blendBench(state, simd::kernels(), true);
}
BENCHMARK(BM_BlendScalar)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BlendSimd)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BlendSimdWithPop)->Unit(benchmark::kMicrosecond);

// Side by side: each iteration does one memcpy and one blend of the same buffer size, timed apart
// in thread CPU time.
void BM_BlendVsMemcpy(benchmark::State& state) {
  const BlendKernels& k = simd::kernels();
  const Rgba8Image a = randomFrame(1), b = randomFrame(3);
  Rgba8Image dst = randomFrame(2), copy = randomFrame(4);
  using Clock = CpuClock;
  Clock::duration blendTime{}, copyTime{};
  bool flip = false;
  for (auto _ : state) {
    const Rgba8Image& src = flip ? a : b;
    flip = !flip;
    const auto t0 = Clock::now();
    std::memcpy(copy.pixels.data(), src.pixels.data(), copy.pixels.size());
    benchmark::ClobberMemory();
    const auto t1 = Clock::now();
    k.blend(dst.pixels.data(), src.pixels.data(), kPixels, kSpec);
    benchmark::ClobberMemory();
    const auto t2 = Clock::now();
    copyTime += t1 - t0;
    blendTime += t2 - t1;
  }
  const double n = static_cast<double>(state.iterations());
  const double copyUs = std::chrono::duration<double, std::micro>(copyTime).count() / n;
  const double blendUs = std::chrono::duration<double, std::micro>(blendTime).count() / n;
  state.counters["memcpy_us"] = copyUs;
  state.counters["blend_us"] = blendUs;
  state.counters["blend_vs_memcpy"] = copyUs / blendUs;  // target >= 0.5
  state.SetLabel(k.name);
}
BENCHMARK(BM_BlendVsMemcpy)->Unit(benchmark::kMicrosecond)->MinTime(1.0);

// Every compiled target the CPU supports, forced in turn: what a machine without AVX-512 gets.
// Counters are CPU microseconds per 512x512 blend.
void BM_BlendPerTarget(benchmark::State& state) {
  const Rgba8Image src = randomFrame(1);
  Rgba8Image dst = randomFrame(2);
  using Clock = CpuClock;
  std::vector<std::pair<std::string, double>> results;
  for (auto _ : state) {
    results.clear();
    simd::forEachTarget([&](const std::string& target) {
      const auto t0 = Clock::now();
      for (int i = 0; i < 20; ++i) simd::kernels().blend(dst.pixels.data(), src.pixels.data(), kPixels, kSpec);
      benchmark::ClobberMemory();
      results.emplace_back(target, std::chrono::duration<double, std::micro>(Clock::now() - t0).count() / 20);
    });
  }
  for (const auto& [name, us] : results) state.counters[name + "_us"] = us;
}
BENCHMARK(BM_BlendPerTarget)->Unit(benchmark::kMillisecond)->Iterations(3);

// A long steady stretch: the lightmap sits at the fixed point for its target, so the
// convergence-aware blender skips every tile; compared with blending everything.
void steady(benchmark::State& state, bool aware) {
  const Rgba8Image target = randomFrame(1);
  Rgba8Image lm = randomFrame(2);
  TiledBlender blender(kSide, kSide, simd::kernels(), aware);
  for (int i = 0; i < 20; ++i) blender.blend(lm, target, kSpec, 7);  // converge
  for (auto _ : state) {
    const auto r = blender.blend(lm, target, kSpec, 7);
    benchmark::DoNotOptimize(r.pop);
  }
}
void BM_SteadyConvergedAware(benchmark::State& state) {
  steady(state, true);
}
void BM_SteadyConvergedBlendAll(benchmark::State& state) {
  steady(state, false);
}
BENCHMARK(BM_SteadyConvergedAware)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SteadyConvergedBlendAll)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
