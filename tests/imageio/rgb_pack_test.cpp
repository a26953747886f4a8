// RGB of RGBA (imageio/rgb_pack.hpp): the word-at-a-time packing is the byte-at-a-time reference's,
// into another buffer and in place, at every count around its four-texel steps and at odd
// alignments.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "imageio/rgb_pack.hpp"

namespace vbim::imageio {
namespace {

std::vector<std::uint8_t> texels(std::size_t count, std::uint32_t seed) {
  std::vector<std::uint8_t> v(count * 4 + 3);
  for (std::uint8_t& b : v) {
    seed = seed * 1664525u + 1013904223u;
    b = static_cast<std::uint8_t>(seed >> 24);
  }
  return v;
}

using Pack = void (*)(const std::uint8_t*, std::size_t, std::uint8_t*);

void expectTheReference(Pack pack, const std::string& name) {
  for (std::size_t count = 0; count <= 200; ++count) {
    for (std::size_t offset = 0; offset < 4; ++offset) {  // unaligned starts
      const std::vector<std::uint8_t> in = texels(count, static_cast<std::uint32_t>(count * 4 + offset));
      const std::uint8_t* rgba = in.data() + offset;
      std::vector<std::uint8_t> want(count * 3 + 8, 0xee);
      packRgbOfRgbaReference(rgba, count, want.data());
      std::vector<std::uint8_t> got(count * 3 + 8, 0xee);  // nothing written past the 3 * count bytes
      pack(rgba, count, got.data());
      EXPECT_EQ(got, want) << name << ": " << count << " texels at offset " << offset;
      std::vector<std::uint8_t> inPlace(in);
      pack(inPlace.data() + offset, count, inPlace.data() + offset);
      EXPECT_TRUE(std::equal(want.begin(), want.begin() + static_cast<std::ptrdiff_t>(count * 3),
                             inPlace.begin() + static_cast<std::ptrdiff_t>(offset)))
          << name << ": " << count << " texels in place at offset " << offset;
    }
  }
}

TEST(RgbPack, IsTheReferenceIntoAnotherBufferAndInPlace) {
  expectTheReference(packRgbOfRgba, "packRgbOfRgba");
  // The reference itself: the first three bytes of each texel.
  const std::uint8_t two[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  std::uint8_t out[6] = {};
  packRgbOfRgbaReference(two, 2, out);
  EXPECT_EQ(std::vector<std::uint8_t>(out, out + 6), (std::vector<std::uint8_t>{1, 2, 3, 5, 6, 7}));
}

}  // namespace
}  // namespace vbim::imageio
