// The per-vsync frame hash on a 512x512 lightmap + 256x128 sky (player/frame_hash.hpp), against
// copying the same bytes: handing the hash to a second host thread needs a snapshot of both images
// (the simulation writes VRAM on), so the copy is what an overlap would cost the simulation thread.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstring>
#include <random>

#include "player/frame_hash.hpp"

namespace {

struct Frame {
  vbim::Rgba8Image lightmap{512, 512};
  vbim::Rgba8Image sky{256, 128};
  Frame() {
    std::mt19937 rng(3);
    for (auto& b : lightmap.pixels) b = static_cast<std::uint8_t>(rng());
    for (auto& b : sky.pixels) b = static_cast<std::uint8_t>(rng());
  }
};

void hashFrame(benchmark::State& state) {
  const Frame f;
  for (auto _ : state) benchmark::DoNotOptimize(vbim::player::frameHash(f.lightmap, &f.sky));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(f.lightmap.pixels.size() + f.sky.pixels.size()));
}
BENCHMARK(hashFrame)->Unit(benchmark::kMicrosecond);

void snapshotFrame(benchmark::State& state) {
  const Frame f;
  Frame copy;
  for (auto _ : state) {
    std::memcpy(copy.lightmap.pixels.data(), f.lightmap.pixels.data(), f.lightmap.pixels.size());
    std::memcpy(copy.sky.pixels.data(), f.sky.pixels.data(), f.sky.pixels.size());
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(f.lightmap.pixels.size() + f.sky.pixels.size()));
}
BENCHMARK(snapshotFrame)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
