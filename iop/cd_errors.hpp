// CDVD error codes as libcdvd reports them (SDK-CD SCECdEr*; docs/hardware.md#dvd-drive), and the stream layer's
// pseudo-error 273 (SDK-ST: set by a read that returned nothing while the stream does not own the
// drive, e.g. before start or while paused).
//
// The one enumeration that keeps constant names (kCdEr*, after the SDK's SCECdEr* it mirrors) rather
// than CamelCase: it is unscoped because these are numeric codes, stored in and compared with the
// uint32 error words libcdvd returns (sceCdGetError, sceCdStStat), not a closed set of cases; bare
// CamelCase names (`Read`, `None`) would leak into vbim::iop as plain words.
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
