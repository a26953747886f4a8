// The fused lightmap blend + frame-hash pass of the player (BlendKernels::blendHashRows, the GS's
// share of a 512x512 play: issue #31) on every compiled SIMD target this CPU supports, next to its
// two halves alone: the hash chain (gs/hash_chain.hpp) over the same 1 MiB and the blend without the
// chain. Each iteration is what a changed vsync costs: the 16 tile rows of a 512x512 lightmap blended
// at FIX 64 toward a frame it has not converged to, each row folded into the chain.
//
// Counters: CPU microseconds per 512x512 lightmap (this thread's CPU time; the machine is shared),
// per target: `<target>_fused_us`, `<target>_blend_us`, and `hash_us` (the chain is scalar). The
// hash is bound by its four multiply chains (4 cycles per 32 bytes); the fused pass is as fast as it
// can be when its time is near the hash's.
#include <benchmark/benchmark.h>

#include <chrono>
#include <ctime>
#include <map>
#include <string>
#include <vector>

#include "gs/hash_chain.hpp"
#include "gs/simd/blend_simd.hpp"
#include "gs/tiled_blender.hpp"
#include "runtime/image.hpp"
#include "runtime/rng.hpp"

namespace {

using vbim::Rgba8Image;
using namespace vbim::gs;

constexpr int kSide = 512;

Rgba8Image randomFrame(std::uint64_t seed) {
  vbim::Rng rng(seed);
  Rgba8Image img(kSide, kSide);
  for (auto& b : img.pixels) b = static_cast<std::uint8_t>(rng.below(256));
  return img;
}

double threadCpuUs() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e6 + static_cast<double>(ts.tv_nsec) / 1e3;
}

// One changed vsync: every tile row blended (settled marks cleared: a new source), folded when
// `hash`. Alternating sources keep the lightmap moving.
// hot: the first tile row 16 times (128 KiB that stay in L2), the same work without the trip to L3.
std::uint64_t vsync(const BlendKernels& k, Rgba8Image& lm, const Rgba8Image& src, bool hash, bool hot = false) {
  const BlendSpec spec = makeBlendSpec(64);
  const std::size_t tilesX = kSide / kTileWidth;
  std::vector<std::uint32_t> settled(tilesX);
  std::vector<int> delta(tilesX);
  HashChain chain;
  chain.addHeader(kSide, kSide);
  for (int y0 = 0; y0 < kSide; y0 += kTileHeight) {
    std::fill(settled.begin(), settled.end(), 0u);
    const int y = hot ? 0 : y0;
    k.blendHashRows(lm.row(y), src.row(y), kSide, kTileHeight, kTileWidth, spec, settled.data(), delta.data(),
                    hash ? &chain : nullptr);
  }
  return chain.lanes[0] ^ static_cast<std::uint64_t>(delta[0]);
}

void BM_BlendHashPerTarget(benchmark::State& state) {
  const Rgba8Image a = randomFrame(1), b = randomFrame(3);
  Rgba8Image lm = randomFrame(2);
  constexpr int kReps = 20;
  std::map<std::string, double> us;
  for (auto _ : state) {
    simd::forEachTarget([&](const std::string& target) {
      for (const int mode : {0, 1, 2, 3}) {
        const bool hash = mode == 0 || mode == 2;
        const bool hot = mode >= 2;
        const double t0 = threadCpuUs();
        for (int i = 0; i < kReps; ++i) {
          benchmark::DoNotOptimize(vsync(simd::kernels(), lm, i % 2 ? a : b, hash, hot));
        }
        const double t = (threadCpuUs() - t0) / kReps;
        double& best = us[target + (mode == 0   ? "_fused_us"
                                    : mode == 1 ? "_blend_us"
                                    : mode == 2 ? "_fused_hot_us"
                                                : "_blend_hot_us")];
        best = best == 0 ? t : std::min(best, t);  // the least disturbed repetition
      }
    });
    const double t0 = threadCpuUs();
    for (int i = 0; i < kReps; ++i) {
      HashChain c;
      c.addHeader(kSide, kSide);
      c.addBytes(lm.pixels.data(), lm.pixels.size());
      benchmark::DoNotOptimize(c.lanes[0]);
    }
    const double t = (threadCpuUs() - t0) / kReps;
    double& best = us["hash_us"];
    best = best == 0 ? t : std::min(best, t);
  }
  for (const auto& [name, v] : us) state.counters[name] = v;
}
BENCHMARK(BM_BlendHashPerTarget)->Unit(benchmark::kMillisecond)->Iterations(10);

}  // namespace

BENCHMARK_MAIN();
