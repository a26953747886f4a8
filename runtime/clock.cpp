#include "runtime/clock.hpp"

#include <cmath>
#include <cstdio>
#include <string_view>

#include "runtime/vsync.hpp"

namespace vbim {

Tick fromSeconds(double s) {
  return static_cast<Tick>(std::llround(s * static_cast<double>(kBusHz)));
}

void formatMicros(Tick t, char* out, std::size_t size) {
  // t ticks = t * 1e9 / 147456000 ns = t * 15625 / 2304 ns; rounded to the nearest ns.
  const bool neg = t < 0;
  const __int128 a = static_cast<__int128>(neg ? -t : t) * 15625;
  const auto ns = static_cast<long long>((a + 1152) / 2304);
  std::snprintf(out, size, "%s%lld.%03lld", neg ? "-" : "", ns / 1000, ns % 1000);
}

bool vsyncRateByName(std::string_view name, VsyncRate& out) {
  for (const VsyncRate& r : {kNtsc, kNtscProgressive, kPal, kPalProgressive}) {
    if (r.name == name) {
      out = r;
      return true;
    }
  }
  return false;
}

}  // namespace vbim
