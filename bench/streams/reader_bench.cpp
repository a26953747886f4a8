// The stream reader on the committed sample: how many sectors per second of host time it parses, pack
// parsing alone versus the whole demux (picture reassembly, descriptor, CRC checks). The ratio says
// where the reader's host time goes; the EE demux (issue #7) models the console's time separately.
#include <benchmark/benchmark.h>

#include <fstream>
#include <iterator>
#include <vector>

#include "streams/demuxer.hpp"
#include "streams/format.hpp"
#include "streams/pack_parser.hpp"

namespace {

using namespace vbim::streams;

const std::vector<std::uint8_t>& sample() {
  static const std::vector<std::uint8_t> bytes = [] {
    std::ifstream in(VBIM_SAMPLES_DIR "/day_weather.vbim", std::ios::binary);
    return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), {});
  }();
  return bytes;
}

void BM_PackParse(benchmark::State& state) {
  const auto& b = sample();
  const auto sectors = static_cast<std::uint32_t>(b.size() / kSectorBytes);
  ParsedPack pack;
  for (auto _ : state) {
    for (std::uint32_t lsn = 0; lsn < sectors; ++lsn) {
      benchmark::DoNotOptimize(
          parsePack(std::span(b).subspan(std::size_t{lsn} * kSectorBytes, kSectorBytes), lsn, pack));
    }
  }
  state.counters["sectors_per_s"] = benchmark::Counter(double(sectors), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_Demux(benchmark::State& state) {
  const auto& b = sample();
  const auto sectors = static_cast<std::uint32_t>(b.size() / kSectorBytes);
  for (auto _ : state) {
    Demuxer dm;
    for (std::uint32_t lsn = 0; lsn < sectors; ++lsn)
      dm.feed(std::span(b).subspan(std::size_t{lsn} * kSectorBytes, kSectorBytes), lsn);
    dm.finish();
    benchmark::DoNotOptimize(dm.pictures().size());
  }
  state.counters["sectors_per_s"] = benchmark::Counter(double(sectors), benchmark::Counter::kIsIterationInvariantRate);
}

BENCHMARK(BM_PackParse);
BENCHMARK(BM_Demux);

}  // namespace

BENCHMARK_MAIN();
