// Vertical sync source. The n-th vsync is at floor(n * kBusHz / rate) with the rate an exact
// rational, so 24 simulated hours of vsyncs do not drift by a single tick.
// Rates: PCSX2 Counters.cpp (59.94 / 59.82 / 50 / 49.76 Hz) and broadcast NTSC 60000/1001.
#pragma once

#include <cstdint>
#include <string_view>

#include "runtime/clock.hpp"

namespace vbim {

struct VsyncRate {
  std::int64_t num;  // rate = num / den Hz
  std::int64_t den;
  std::string_view name;
};

inline constexpr VsyncRate kNtsc{60000, 1001, "ntsc"};             // 59.94006 Hz interlaced
inline constexpr VsyncRate kNtscProgressive{5982, 100, "ntsc-p"};  // 59.82 Hz non-interlaced
inline constexpr VsyncRate kPal{50, 1, "pal"};                     // 50 Hz interlaced
inline constexpr VsyncRate kPalProgressive{4976, 100, "pal-p"};    // 49.76 Hz non-interlaced

// Looks a rate up by name ("ntsc", "ntsc-p", "pal", "pal-p"); returns false if unknown.
bool vsyncRateByName(std::string_view name, VsyncRate& out);

class VsyncClock {
 public:
  constexpr explicit VsyncClock(VsyncRate rate, Tick origin = 0) : rate_(rate), origin_(origin) {}

  // Time of vsync n (n = 0 is the origin). Exact: floor(n * kBusHz * den / num).
  constexpr Tick time(std::int64_t n) const {
    const __int128 p = static_cast<__int128>(n) * kBusHz * rate_.den;
    return origin_ + static_cast<Tick>(p / rate_.num);
  }
  // Number of vsyncs at or before t (t >= origin): the largest n with time(n) <= t.
  constexpr std::int64_t countAt(Tick t) const {
    if (t < origin_) return -1;
    const __int128 q = static_cast<__int128>(t - origin_) * rate_.num;
    std::int64_t n = static_cast<std::int64_t>(q / (static_cast<__int128>(kBusHz) * rate_.den));
    while (time(n + 1) <= t) ++n;  // guards the floor at exact boundaries
    while (n > 0 && time(n) > t) --n;
    return n;
  }
  constexpr VsyncRate rate() const { return rate_; }
  constexpr Tick origin() const { return origin_; }

 private:
  VsyncRate rate_;
  Tick origin_;
};

}  // namespace vbim
