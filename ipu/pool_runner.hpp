// Slice-parallel decode on the kernel's WorkerPool: the SliceRunner to give the decoder core, which
// does not depend on the kernel (Decoder::decode(bytes, pool) and decodeToRgba(..., pool) use it).
#pragma once

#include <cstddef>
#include <functional>

#include "ipu/picture_decoder.hpp"

namespace vbim {
class WorkerPool;
}

namespace vbim::ipu {

class PoolSliceRunner final : public SliceRunner {
 public:
  explicit PoolSliceRunner(WorkerPool& pool) : pool_(pool) {}
  unsigned threads() const override;
  void run(std::size_t count, const std::function<void(std::size_t)>& fn) override;

 private:
  WorkerPool& pool_;
};

}  // namespace vbim::ipu
