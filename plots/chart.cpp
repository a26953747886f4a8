#include "plots/chart.hpp"

#include <array>

namespace vbim::plots {

Rgb paletteColor(std::size_t i) {
  // Okabe and Ito, "Color Universal Design" (2002): blue, orange, bluish green, vermillion,
  // reddish purple, sky blue; then two greys.
  static constexpr std::array<Rgb, 8> k{{{0, 114, 178},
                                         {230, 159, 0},
                                         {0, 158, 115},
                                         {213, 94, 0},
                                         {204, 121, 167},
                                         {86, 180, 233},
                                         {115, 115, 115},
                                         {51, 51, 51}}};
  return k[i % k.size()];
}

}  // namespace vbim::plots
