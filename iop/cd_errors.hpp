// CDVD error codes as libcdvd reports them (SDK-CD SCECdEr*; docs/hardware.md#dvd-drive), and the stream layer's
// pseudo-error 273 (SDK-ST: set by a read that returned nothing while the stream does not own the
// drive, e.g. before start or while paused).
#pragma once

#include <cstdint>

namespace vbim::iop {

enum CdError : std::uint32_t {
  kCdErNone = 0x00,
  kCdErAbort = 0x01,       // SCECdErABRT: command broken (sceCdBreak, timeout)
  kCdErRead = 0x30,        // SCECdErREAD: unrecoverable read error
  kCdErEndOfMedia = 0x32,  // SCECdErEOM: read ran past the last sector
  kCdErStreamIdle = 273,   // SDK-ST pseudo-error 0x111 (meaning inferred [?])
};

}  // namespace vbim::iop
