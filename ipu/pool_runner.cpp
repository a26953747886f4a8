// Slice-parallel decode on the kernel's worker pool.
#include "ipu/picture_decoder.hpp"
#include "runtime/worker_pool.hpp"

namespace vbim::ipu {
namespace {

class PoolRunner final : public SliceRunner {
 public:
  explicit PoolRunner(WorkerPool& pool) : pool_(pool) {}
  unsigned threads() const override { return pool_.threads(); }
  void run(std::size_t count, const std::function<void(std::size_t)>& fn) override { pool_.parallelFor(count, fn); }

 private:
  WorkerPool& pool_;
};

}  // namespace

PictureReport Decoder::decode(std::span<const std::uint8_t> bytes, WorkerPool& pool) {
  PoolRunner runner(pool);
  return decode(bytes, &runner);
}

PictureReport decodeToRgba(Decoder& decoder, std::span<const std::uint8_t> bytes, Rgba8Image& out, WorkerPool& pool,
                           CscThresholds th) {
  PoolRunner runner(pool);
  return decodeToRgba(decoder, bytes, out, th, &runner);
}

}  // namespace vbim::ipu
