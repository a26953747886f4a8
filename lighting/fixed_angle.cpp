#include "lighting/fixed_angle.hpp"

#include <array>
#include <cmath>

namespace vbim::lighting {

namespace {

constexpr int kTableSteps = 4096;

const std::array<double, kTableSteps + 2>& atanTable() {
  static const std::array<double, kTableSteps + 2> table = [] {
    std::array<double, kTableSteps + 2> t{};
    for (int i = 0; i <= kTableSteps + 1; ++i) t[i] = std::atan(static_cast<double>(i) / kTableSteps);
    return t;
  }();
  return table;
}

double atanUnit(double t) {  // t in [0, 1]
  const auto& table = atanTable();
  const double s = t * kTableSteps;
  const int i = static_cast<int>(s);
  const double f = s - i;
  return table[i] + (table[i + 1] - table[i]) * f;
}

}  // namespace

std::uint16_t codeFromAngle(double radians) {
  if (!(radians > 0)) return 0;
  const double c = radians / kAngleUnit;
  // floor(c + 0.5), c > 0: the rounding the stream's angle codes are defined with (not lround's).
  // NOLINTNEXTLINE(bugprone-incorrect-roundings)
  return c >= 65535.0 ? 65535 : static_cast<std::uint16_t>(c + 0.5);
}

std::uint16_t codeFromTangent(double t) {
  if (!(t > 0)) return 0;
  const double a = t <= 1.0 ? atanUnit(t) : std::numbers::pi / 2 - atanUnit(1.0 / t);
  return codeFromAngle(a);
}

}  // namespace vbim::lighting
