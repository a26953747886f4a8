// A lean `vbim play --no-trace`: plays a bare stream file with the player and SIMD kernels, the
// rows going to a sink that keeps nothing, and links nothing but the model (no OpenImageIO, no
// FFmpeg), so its peak resident set is the player's own. memory_test.cpp runs it as a child.
//   player_memory_probe STREAM DURATION CONFIG.toml
#include <iostream>
#include <memory>

#include "gs/blend_simd.hpp"
#include "iop/fault_plan.hpp"
#include "iop/file_disc.hpp"
#include "ipu/simd/simd_kernels.hpp"
#include "runtime/player/player.hpp"
#include "runtime/player/scenario.hpp"

int main(int argc, char** argv) {
  using namespace vbim;
  if (argc != 4) {
    std::cerr << "usage: player_memory_probe STREAM DURATION CONFIG.toml\n";
    return 2;
  }
  try {
    iop::FileDisc probe(argv[1], player::kBareFileLba);
    const iop::DiscFile file = probe.file();
    iop::FileDisc disc(argv[1], player::kBareFileLba,
                       player::kBareFileLba + file.sectors() + player::kBareFilePadSectors);
    player::PlayerOptions o;
    o.config = player::loadPlatformFile(argv[3]);
    o.duration = iop::parseDuration(argv[2]);
    o.trace = false;
    o.kernels.blend = &gs::simd::kernels();
    o.kernels.ipu = &ipu::simdKernels();
    player::Player p(disc, file, o);
    std::uint64_t fold = 0;
    p.setSink([&fold](const player::VsyncRow& r, const Rgba8Image&, const Rgba8Image*) { fold ^= r.hash; });
    p.runToEnd();
    std::cout << p.totals().vsyncs << " vsyncs, hash fold " << fold << "\n";
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
