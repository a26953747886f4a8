#include "iop/sif.hpp"

#include <algorithm>

namespace vbim::iop {

SifChannel::SifChannel(Scheduler& s, const SifParams& p, Tracer* tracer) : s_(s), p_(p), tracer_(tracer) {
  if (tracer_ != nullptr) track_ = tracer_->track("sif0");
}

Tick SifChannel::transferTicks(std::size_t bytes) const {
  const __int128 num = static_cast<__int128>(bytes) * kBusHz;
  const __int128 den = p_.bandwidth_bytes_per_s;
  return fromUs(p_.setup_us) + static_cast<Tick>((num + den - 1) / den);
}

Task<void> SifChannel::transfer(std::size_t bytes) {
  const Tick start = std::max(s_.now(), freeAt_);
  const Tick cost = transferTicks(bytes);
  freeAt_ = start + cost;
  ++transfers_;
  bytes_ += static_cast<std::int64_t>(bytes);
  busy_ += cost;
  if (tracer_ != nullptr) tracer_->span(track_, start, freeAt_, "sif0");
  co_await s_.until(freeAt_);
}

}  // namespace vbim::iop
