// Item 6: horizons for 512x512 in all 8 directions (<= 50 ms, one core); 4096x4096 (<= 4 s, two
// cores); one frame's relight of 512x512 (<= 2 ms). Also the per-frame sun sweep, the precompute
// steps, and the O(n) scan against brute force as a ratio.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <map>
#include <numbers>

#include "lighting/azimuth_sweep.hpp"
#include "lighting/day_cycle.hpp"
#include "lighting/horizon_scan.hpp"
#include "lighting/procedural_terrain.hpp"
#include "lighting/ray_sweep.hpp"
#include "runtime/worker_pool.hpp"

namespace vbim::lighting {
namespace {

// CPU seconds of every thread of the process: with a loaded machine, wall time says little.
double processCpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + (u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
}

const Terrain& terrain(int size) {
  static std::map<int, Terrain> cache;
  auto it = cache.find(size);
  if (it == cache.end()) {
    it = cache
             .emplace(size,
                      proceduralTerrain({.size = size, .cellSize = 10.0 * 512 / size, .reliefMetres = 900, .seed = 1}))
             .first;
  }
  return it->second;
}

void BM_Horizons8(benchmark::State& state) {
  const Terrain& t = terrain(static_cast<int>(state.range(0)));
  const auto threads = static_cast<unsigned>(state.range(1));
  WorkerPool pool(threads - 1);
  const double cpu0 = processCpuSeconds();
  for (auto _ : state) {
    HorizonMaps m = computeHorizons(t, threads > 1 ? &pool : nullptr);
    benchmark::DoNotOptimize(m.code[0].data());
  }
  // All threads' CPU time per run; divided by the thread count it is the wall time on idle cores.
  state.counters["cpu_s_all_threads"] = (processCpuSeconds() - cpu0) / static_cast<double>(state.iterations());
  state.counters["Mtexel_dirs/s"] =
      benchmark::Counter(static_cast<double>(t.texels()) * 8 * state.iterations() / 1e6, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Horizons8)->Args({512, 1})->Args({4096, 2})->Unit(benchmark::kMillisecond)->UseRealTime();

// The article scanned brute force; the hull scan against it on one 256x256 direction.
void BM_ScanFastVsBrute(benchmark::State& state) {
  const Terrain& t = terrain(256);
  std::vector<std::uint16_t> out(t.texels());
  for (auto _ : state) {
    if (state.range(0) == 0) {
      scanHorizon(t, 0, out.data());
    } else {
      scanHorizonBruteForce(t, 0, out.data());
    }
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_ScanFastVsBrute)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

struct FrameFixture {
  Precomputed pre;
  DayCycleParams params;
  CloudLayer clouds;
  std::vector<float> horizon;
  FrameLighting light;
  explicit FrameFixture(int patches, bool cloudy)
      : pre(precompute(terrain(512), patches)), params(makeParams(patches, cloudy)), clouds(params.clouds) {
    horizon.resize(pre.terrain.texels());
    DayCycleGenerator g(terrain(16), params);  // only for the lighting of a mid-morning frame
    light = g.frameLighting(params.frames / 3);
    sweepAzimuth(pre.terrain, light.key.azimuth, horizon.data());
  }
  static DayCycleParams makeParams(int patches, bool cloudy) {
    DayCycleParams p;
    p.skyPatches = patches;
    p.clouds.enabled = cloudy;
    return p;
  }
};

void BM_Relight512(benchmark::State& state) {
  static FrameFixture* fixtures[9][2] = {};
  const int patches = static_cast<int>(state.range(0));
  const bool cloudy = state.range(1) != 0;
  if (!fixtures[patches][cloudy]) fixtures[patches][cloudy] = new FrameFixture(patches, cloudy);
  FrameFixture& f = *fixtures[patches][cloudy];
  FloatImage out;
  for (auto _ : state) {
    relight(f.pre, f.light, f.horizon.data(), f.clouds, f.params, out);
    benchmark::DoNotOptimize(out.pixels.data());
  }
}
BENCHMARK(BM_Relight512)->Args({1, 0})->Args({2, 0})->Args({8, 0})->Args({2, 1})->Unit(benchmark::kMicrosecond);

void BM_SunSweep512(benchmark::State& state) {
  const Terrain& t = terrain(512);
  std::vector<float> out(t.texels());
  const double azimuth = state.range(0) * std::numbers::pi / 180.0;
  for (auto _ : state) {
    sweepAzimuth(t, azimuth, out.data());
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_SunSweep512)->Arg(-170)->Arg(-120)->Arg(-90)->Unit(benchmark::kMicrosecond);

// The per-texel ray sweep (lighting/ray_sweep.hpp): sizes 512 and 4096, one core.
void BM_RaySweep(benchmark::State& state) {
  const Terrain& t = terrain(static_cast<int>(state.range(0)));
  std::vector<float> out(t.texels());
  const double azimuth = state.range(1) * std::numbers::pi / 180.0;
  for (auto _ : state) {
    sweepRays(t, azimuth, out.data());
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_RaySweep)
    ->Args({512, -170})
    ->Args({512, -120})
    ->Args({512, -90})
    ->Args({4096, -120})
    ->Unit(benchmark::kMillisecond);

// Sky factors with 8, 16 or 32 directions (lighting.sky_directions), horizons included.
void BM_SkyDirections512(benchmark::State& state) {
  const Terrain& t = terrain(512);
  const std::vector<Vec3> normals = terrainNormals(t);
  for (auto _ : state) {
    const HorizonMaps h = computeHorizons(t);
    SkyFactors s = computeSkyFactors(t, h, normals, 2, static_cast<int>(state.range(0)));
    benchmark::DoNotOptimize(s.k.data());
  }
}
BENCHMARK(BM_SkyDirections512)->Arg(8)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond);

void BM_Precompute512(benchmark::State& state) {
  for (auto _ : state) {
    Precomputed p = precompute(terrain(512), 2);
    benchmark::DoNotOptimize(p.sky.k.data());
  }
}
BENCHMARK(BM_Precompute512)->Unit(benchmark::kMillisecond);

void BM_Frame512(benchmark::State& state) {
  DayCycleParams p;
  static DayCycleGenerator g(terrain(512), p);
  FloatImage light, sky;
  int i = 0;
  for (auto _ : state) {
    g.renderFrame(i, light, sky);
    i = (i + 17) % g.frameCount();
  }
}
BENCHMARK(BM_Frame512)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace vbim::lighting

BENCHMARK_MAIN();
