// libFuzzer target: the player as a whole (probe, drive, ring, demux, IPU timing model, GS) on any
// bytes as the stream file of a disc, for a short simulated run. It must refuse the stream with a
// vbim::Error or play it (concealing damage), never crash, read freed memory or hang.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "iop/memory_disc.hpp"
#include "player/player.hpp"
#include "runtime/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  constexpr std::int64_t kLba = 1000;
  vbim::iop::MemoryDisc disc(kLba + static_cast<std::int64_t>(size / 2048) + 64);
  disc.addFile("\\VIDEO\\DAY.PSS;1", kLba, std::vector<std::uint8_t>(data, data + size));
  const auto file = disc.find("\\VIDEO\\DAY.PSS;1");
  if (!file) return 0;
  vbim::player::PlayerOptions o;
  o.duration = vbim::fromMs(1500);
  o.trace = false;
  try {
    vbim::player::Player p(disc, *file, o);
    p.runToEnd();
  } catch (const vbim::Error&) {
  }
  return 0;
}
