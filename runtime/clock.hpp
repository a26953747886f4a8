// The one time base of the model: Tick = one 147.456 MHz EE bus cycle (also the GS clock).
// Sources: PCSX2 Common.h (PS2CLK = 294912000, BIAS = 2), CDVD.cpp (PSXCLK = 36864000);
// see ../docs/timing-model.md. EE = 2 ticks' rate (1 EE cycle = half a tick), IOP = tick / 4.
#pragma once

#include <cstdint>
#include <limits>

namespace vbim {

using Tick = std::int64_t;

inline constexpr Tick kNever = std::numeric_limits<Tick>::max();
inline constexpr std::int64_t kBusHz = 147'456'000;  // ticks per second
inline constexpr std::int64_t kEeHz = 294'912'000;
inline constexpr std::int64_t kIopHz = 36'864'000;
inline constexpr std::int64_t kTicksPerMs = kBusHz / 1000;          // 147,456: exact
inline constexpr std::int64_t kTicksPerIopCycle = kBusHz / kIopHz;  // 4: exact
static_assert(kBusHz % 1000 == 0 && kBusHz % kIopHz == 0 && kEeHz == 2 * kBusHz);

// IOP cycles <-> ticks: exact both ways when the tick count is a multiple of 4.
constexpr Tick fromIopCycles(std::int64_t iop) {
  return iop * kTicksPerIopCycle;
}
// Whole IOP cycles elapsed by tick t (floor).
constexpr std::int64_t toIopCycles(Tick t) {
  return t >= 0 ? t / kTicksPerIopCycle : -((-t + kTicksPerIopCycle - 1) / kTicksPerIopCycle);
}

// EE cycles <-> ticks: one EE cycle is half a tick, so ticks -> EE is exact, EE -> ticks rounds
// up (an EE-side cost of 3 cycles occupies 2 bus ticks).
constexpr std::int64_t toEeCycles(Tick t) {
  return t * 2;
}
constexpr Tick fromEeCycles(std::int64_t ee) {
  return ee >= 0 ? (ee + 1) / 2 : -((-ee) / 2);
}

// Milliseconds and microseconds. 1 ms is exactly 147,456 ticks; 1 us is 147.456 ticks, so
// microsecond conversions round to the nearest tick (half away from zero).
constexpr Tick fromMs(std::int64_t ms) {
  return ms * kTicksPerMs;
}
constexpr Tick fromUs(std::int64_t us) {
  const std::int64_t n = us * 147'456;
  return n >= 0 ? (n + 500) / 1000 : -((-n + 500) / 1000);
}
constexpr Tick fromNs(std::int64_t ns) {
  const __int128 n = static_cast<__int128>(ns) * 147'456;
  return static_cast<Tick>(n >= 0 ? (n + 500'000) / 1'000'000 : -((-n + 500'000) / 1'000'000));
}
// Rational seconds num/den, rounded to the nearest tick: exact for every duration that is a
// whole number of ticks.
constexpr Tick fromSecondsRational(std::int64_t num, std::int64_t den) {
  const __int128 n = static_cast<__int128>(num) * kBusHz;
  const __int128 d = den;
  return static_cast<Tick>(n >= 0 ? (2 * n + d) / (2 * d) : -((-2 * n + d) / (2 * d)));
}
// For user-facing values (config files, --at 12.5s). Rounds to the nearest tick.
Tick fromSeconds(double s);
// For reports only: never feed back into the model.
constexpr double toSeconds(Tick t) {
  return static_cast<double>(t) / static_cast<double>(kBusHz);
}
constexpr double toMs(Tick t) {
  return static_cast<double>(t) * 1000.0 / static_cast<double>(kBusHz);
}

// Microseconds with three decimals, computed in integers so trace files are byte-identical on
// every compiler ("12.345"). Rounds to the nearest nanosecond.
void formatMicros(Tick t, char* out, std::size_t size);

}  // namespace vbim
