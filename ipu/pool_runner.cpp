// Slice-parallel decode on the kernel's worker pool.
#include "ipu/pool_runner.hpp"

#include "runtime/worker_pool.hpp"

namespace vbim::ipu {

unsigned PoolSliceRunner::threads() const {
  return pool_.threads();
}

void PoolSliceRunner::run(std::size_t count, const std::function<void(std::size_t)>& fn) {
  pool_.parallelFor(count, fn);
}

PictureReport Decoder::decode(std::span<const std::uint8_t> bytes, WorkerPool& pool) {
  PoolSliceRunner runner(pool);
  return decode(bytes, &runner);
}

PictureReport decodeToRgba(Decoder& decoder, std::span<const std::uint8_t> bytes, Rgba8Image& out, WorkerPool& pool,
                           CscThresholds th) {
  PoolSliceRunner runner(pool);
  return decodeToRgba(decoder, bytes, out, th, &runner);
}

}  // namespace vbim::ipu
