// Shared set-up for the IOP tests: a scheduler, a disc, a drive, SIF0 and a ring, with the
// parameters a test wants. Plus the model's arithmetic written out independently of iop/.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "iop/drive.hpp"
#include "iop/memory_disc.hpp"
#include "iop/sif.hpp"
#include "iop/stream_ring.hpp"
#include "runtime/rng.hpp"
#include "runtime/scheduler.hpp"
#include "runtime/trace.hpp"

namespace vbim::iop::test {

inline constexpr std::int64_t kLayer = 2'298'496;

// docs/hardware.md#dvd-drive: CAV 4x sectors/s = 2700 x (0.40 + 0.60 x LSN / 2,298,496); one sector's time in ticks,
// rounded to the nearest tick.
inline Tick cavSectorTicks(std::int64_t lsn) {
  const __int128 num = static_cast<__int128>(147'456'000) * 100 * kLayer;
  const __int128 den =
      static_cast<__int128>(2700) * (40 * static_cast<__int128>(kLayer) + 60 * static_cast<__int128>(lsn));
  return static_cast<Tick>((2 * num + den) / (2 * den));
}
inline constexpr Tick kClvSectorTicks = 136'533;  // 147,456,000 / 1080, rounded
inline constexpr Tick kDmaTicks = 6'144 * 4;      // 6,144 IOP cycles per 2,048-byte sector

struct Rig {
  IopParams p;
  std::uint64_t seed = 1;
  Scheduler s;
  Tracer tracer;
  std::unique_ptr<MemoryDisc> disc;
  std::unique_ptr<Drive> drive;
  std::unique_ptr<SifChannel> sif;
  std::unique_ptr<StreamRing> ring;

  bool traced = true;  // false: the drive is built without a tracer

  Rig() { p.drive.initially_spinning = true; }
  // Once per rig: the drive's process lives in the scheduler and refers to the drive.
  void build(std::int64_t discSectors = kLayer, bool withRing = true) {
    if (!disc) {
      disc = std::make_unique<MemoryDisc>(discSectors);
      disc->addPatternFile("/STREAM.PSS", 0, discSectors);
    }
    drive = std::make_unique<Drive>(s, *disc, p.drive, Rng(seed), traced ? &tracer : nullptr);
    sif = std::make_unique<SifChannel>(s, p.sif, &tracer);
    if (withRing) ring = std::make_unique<StreamRing>(s, *drive, *sif, p.ring, &tracer);
  }
};

inline bool sectorHasPattern(const std::uint8_t* d, std::int64_t lba) {
  for (std::size_t i = 0; i < kSectorBytes; ++i) {
    if (d[i] != MemoryDisc::patternByte(lba, i)) return false;
  }
  return true;
}

}  // namespace vbim::iop::test
