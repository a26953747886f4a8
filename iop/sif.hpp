// SIF0 (IOP -> EE) as a timed channel: each sceSifSetDma chunk costs a fixed setup plus its bytes
// at the channel bandwidth, and chunks go one at a time in the order they were started. Both
// constants are assumptions: no measured SIF0 rate or per-DMA latency exists (docs/hardware.md#sif-rate).
#pragma once

#include <cstddef>
#include <cstdint>

#include "iop/params.hpp"
#include "runtime/scheduler.hpp"
#include "runtime/trace.hpp"

namespace vbim::iop {

class SifChannel {
 public:
  SifChannel(Scheduler& s, const SifParams& p, Tracer* tracer = nullptr);

  // Time one chunk of `bytes` holds the channel: setup + ceil(bytes x 147.456 MHz / bandwidth).
  Tick transferTicks(std::size_t bytes) const;
  // Waits for the channel, then for the transfer; resumes when the data has arrived in EE RAM.
  Task<void> transfer(std::size_t bytes);

  std::int64_t transfers() const { return transfers_; }
  std::int64_t bytes() const { return bytes_; }
  Tick busyTime() const { return busy_; }

 private:
  Scheduler& s_;
  SifParams p_;
  Tracer* tracer_;
  Tracer::TrackId track_ = 0;
  Tick freeAt_ = 0;
  std::int64_t transfers_ = 0;
  std::int64_t bytes_ = 0;
  Tick busy_ = 0;
};

}  // namespace vbim::iop
