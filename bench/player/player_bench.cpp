// The player's speed (issue #7 item 8): a 512x512 lightmap plus a 256x128 sky at 59.94 Hz, 2 s of
// game time per stream frame (24 frames, a 48 s loop), played for 120 s of simulated time, no
// faults, no trace. Target: at least 200x real time (counter sim_x_realtime).
//
// Where the time goes: after the timed runs, the host cost of each component's unit of work is
// measured on its own (the EE demux's stream reader per sector, one IPU picture decode with its
// timing model per picture, one GS tile blend, one frame hash) and multiplied by how many of each
// the run did (the player's own counters); share_ipu_decode is the part of share_ipu that is the
// decode itself, without the timing model. The shares are reported as counters; "other" is the
// remainder (scheduler, coroutines, buffers). Times are this thread's CPU time (the machine is
// shared). Arguments: 1 = SIMD kernels (as `vbim play`), 0 = scalar references.
#include <benchmark/benchmark.h>

#include <chrono>
#include <ctime>
#include <memory>

#include "config/platform_config_toml.hpp"
#include "gs/simd/blend_simd.hpp"
#include "gs/tiled_blender.hpp"
#include "iop/memory_disc.hpp"
#include "ipu/ipu_unit.hpp"
#include "ipu/simd/simd_kernels.hpp"
#include "player/frame_hash.hpp"
#include "player/player.hpp"
#include "player/scenario.hpp"
#include "streams/authoring/bench_stream.hpp"
#include "streams/demuxer.hpp"

namespace {

using namespace vbim;

constexpr int kFrames = 24;
const Tick kPlay = fromMs(120'000);

double cpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

const std::vector<std::uint8_t>& content() {
  static const std::vector<std::uint8_t> bytes =
      streams::authorBenchStream(kFrames, streams::BenchContent::SyntheticDay);
  return bytes;
}

struct Disc {
  std::shared_ptr<iop::MemoryDisc> disc;
  iop::DiscFile file;
};

Disc makeDisc() {
  const auto& bytes = content();
  const auto sectors = static_cast<std::int64_t>(bytes.size() / iop::kSectorBytes);
  Disc d;
  d.disc = std::make_shared<iop::MemoryDisc>(player::kBareFileLba + sectors + player::kBareFilePadSectors);
  d.disc->addFile("bench.vbim", player::kBareFileLba, bytes);
  d.file = *d.disc->find("bench.vbim");
  return d;
}

player::Kernels kernels(bool simd) {
  player::Kernels k;
  if (simd) {
    k.blend = &gs::simd::kernels();
    k.ipu = &ipu::simdKernels();
  }
  return k;
}

// A 512x512 lightmap does not fit next to two 640x448 CT32 frame buffers with a full-size staging
// texture: upload in strips through a small staging area (Hoffman & Mitchell's in-place blend) and size the
// sky texture to the stream's 256x128.
player::PlatformConfig benchConfig() {
  return config::loadPlatformToml("gs.upload_mode = \"strips\"\ngs.sky_height = 128\n", "<bench config>");
}

// Host seconds per unit of work, each measured alone.
struct UnitCosts {
  double demuxPerSector = 0, decodePerPicture = 0, blendPerTile = 0, hashPerFrame = 0;
  double functionalDecodePerPicture = 0;  // the part of decodePerPicture that is the decode itself
};

UnitCosts measureUnits(bool simd) {
  UnitCosts u;
  const auto& bytes = content();
  const std::size_t sectors = bytes.size() / iop::kSectorBytes;
  std::vector<streams::Picture> pictures;
  {
    const double t0 = cpuSeconds();
    streams::Demuxer d;
    for (std::size_t i = 0; i < sectors; ++i) {
      d.feed(std::span<const std::uint8_t>(bytes.data() + i * iop::kSectorBytes, iop::kSectorBytes),
             static_cast<std::uint32_t>(i));
      for (auto& p : d.pictures()) pictures.push_back(std::move(p));
      d.pictures().clear();
    }
    u.demuxPerSector = (cpuSeconds() - t0) / static_cast<double>(sectors);
  }
  {
    Scheduler s;
    ipu::DecoderOptions o;
    o.kernels = simd ? &ipu::simdKernels() : nullptr;
    ipu::IpuUnit unit(s, ipu::IpuParams{}, nullptr, o);
    struct Run {
      static Task<void> all(ipu::IpuUnit& u, const std::vector<streams::Picture>& pics) {
        Rgba8Image out;
        for (const auto& p : pics) (void)co_await u.decode(p.data, out);
      }
    };
    s.spawn("bench.decode", Run::all(unit, pictures));
    const double t0 = cpuSeconds();
    s.run();
    u.decodePerPicture = (cpuSeconds() - t0) / static_cast<double>(pictures.size());
    ipu::Decoder plain(o);
    Rgba8Image out;
    const double t1 = cpuSeconds();
    for (const auto& p : pictures) ipu::decodeToRgba(plain, p.data, out);
    u.functionalDecodePerPicture = (cpuSeconds() - t1) / static_cast<double>(pictures.size());
  }
  {
    Rgba8Image dst(512, 512), src(512, 512);
    for (std::size_t i = 0; i < src.pixels.size(); ++i) src.pixels[i] = static_cast<std::uint8_t>(i * 7);
    const gs::BlendKernels& k = simd ? gs::simd::kernels() : gs::scalarKernels();
    gs::TiledBlender b(512, 512, k, false);
    const int reps = 50;
    const double t0 = cpuSeconds();
    for (int i = 0; i < reps; ++i) b.blend(dst, src, gs::makeBlendSpec(64), static_cast<std::uint64_t>(i));
    constexpr int kTiles = (512 / gs::kTileWidth) * (512 / gs::kTileHeight);
    u.blendPerTile = (cpuSeconds() - t0) / (reps * kTiles);
    Rgba8Image sky(256, 128);
    const double t1 = cpuSeconds();
    std::uint64_t h = 0;
    for (int i = 0; i < reps; ++i) {
      dst.pixels[static_cast<std::size_t>(i)] ^= 1;
      h ^= player::frameHash(dst, &sky);
    }
    benchmark::DoNotOptimize(h);
    u.hashPerFrame = (cpuSeconds() - t1) / reps;
  }
  return u;
}

void BM_PlayerSpeed(benchmark::State& state) {
  const bool simd = state.range(0) != 0;
  const Disc d = makeDisc();
  double cpu = 0;
  std::int64_t runs = 0, sectors = 0, pictures = 0, tiles = 0, tilesSkipped = 0, hashes = 0, vsyncs = 0;
  for (auto _ : state) {
    player::PlayerOptions o;
    o.config = benchConfig();
    o.duration = kPlay;
    o.trace = false;
    o.kernels = kernels(simd);
    player::Player p(*d.disc, d.file, o);
    std::int64_t changed = 0;
    p.setSink([&changed](const player::VsyncRow& r, const Rgba8Image&, const Rgba8Image*) {
      changed += (r.vsync == 0 || r.lightmap.pop != 0 || (r.sky && r.sky->pop != 0)) ? 1 : 0;
    });
    const double t0 = cpuSeconds();
    p.runToEnd();
    cpu += cpuSeconds() - t0;
    ++runs;
    sectors = p.pipeline().demux().reader().stats().sectors;
    pictures = p.pipeline().decode().pictures;
    const auto& lm = p.pipeline().lightmap().counters();
    const auto& sk = p.pipeline().sky()->counters();
    tiles = lm.tilesBlended + sk.tilesBlended;
    tilesSkipped = lm.tilesSkipped + sk.tilesSkipped;
    hashes = changed;
    vsyncs = p.totals().vsyncs;
  }
  const double perRun = cpu / static_cast<double>(runs);
  state.counters["sim_x_realtime"] = toSeconds(kPlay) / perRun;
  state.counters["host_s_per_run"] = perRun;
  state.counters["vsyncs"] = static_cast<double>(vsyncs);
  state.counters["stream_bytes"] = static_cast<double>(content().size());
  state.counters["tiles_blended"] = static_cast<double>(tiles);
  state.counters["tiles_skipped"] = static_cast<double>(tilesSkipped);
  const UnitCosts u = measureUnits(simd);
  const double demux = u.demuxPerSector * static_cast<double>(sectors);
  const double ipu = u.decodePerPicture * static_cast<double>(pictures);
  const double gs = u.blendPerTile * static_cast<double>(tiles);
  const double hash = u.hashPerFrame * static_cast<double>(hashes);
  state.counters["share_demux"] = demux / perRun;
  state.counters["share_ipu"] = ipu / perRun;
  // Of share_ipu, the decode itself (no simulated timing): the rest is IpuUnit moving every qword
  // through its FIFOs on the scheduler.
  state.counters["share_ipu_decode"] = u.functionalDecodePerPicture * static_cast<double>(pictures) / perRun;
  state.counters["share_gs_blend"] = gs / perRun;
  state.counters["share_hash"] = hash / perRun;
  state.counters["share_other"] = 1.0 - (demux + ipu + gs + hash) / perRun;
}
BENCHMARK(BM_PlayerSpeed)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
