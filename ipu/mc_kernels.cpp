#include "ipu/mc_kernels.hpp"

namespace vbim::ipu {
namespace {

template <bool Average, int Width, int Case>
void predictScalar(std::uint8_t* dst, std::ptrdiff_t dstStride, const std::uint8_t* src, std::ptrdiff_t srcStride,
                   int rows) {
  const std::ptrdiff_t right = Case & 1 ? 1 : 0;
  const std::ptrdiff_t down = Case & 2 ? srcStride : 0;
  for (int r = 0; r < rows; ++r) {
    const std::uint8_t* p = src + r * srcStride;
    std::uint8_t* d = dst + r * dstStride;
    for (int c = 0; c < Width; ++c) {
      int v;
      if constexpr (Case == 3) {
        v = (p[c] + p[c + right] + p[c + down] + p[c + down + right] + 2) >> 2;
      } else if constexpr (Case != 0) {
        v = (p[c] + p[c + right + down] + 1) >> 1;
      } else {
        v = p[c];
      }
      d[c] = static_cast<std::uint8_t>(Average ? (d[c] + v + 1) >> 1 : v);
    }
  }
}

template <bool Average, int Width>
constexpr void fill(McPredictFn (&out)[4]) {
  out[0] = predictScalar<Average, Width, 0>;
  out[1] = predictScalar<Average, Width, 1>;
  out[2] = predictScalar<Average, Width, 2>;
  out[3] = predictScalar<Average, Width, 3>;
}

template <bool Average, int LumaCase, int ChromaCase>
void blockScalar(const McBlock& b) {
  predictScalar<Average, 16, LumaCase>(b.dy, b.dyStride, b.sy, b.syStride, b.rows);
  predictScalar<Average, 8, ChromaCase>(b.dcb, b.dcStride, b.scb, b.scStride, b.rows / 2);
  predictScalar<Average, 8, ChromaCase>(b.dcr, b.dcStride, b.scr, b.scStride, b.rows / 2);
}

template <bool Average, int LumaCase>
constexpr void fillBlock(McBlockFn (&out)[4]) {
  out[0] = blockScalar<Average, LumaCase, 0>;
  out[1] = blockScalar<Average, LumaCase, 1>;
  out[2] = blockScalar<Average, LumaCase, 2>;
  out[3] = blockScalar<Average, LumaCase, 3>;
}

template <bool Average>
constexpr void fillBlocks(McBlockFn (&out)[4][4]) {
  fillBlock<Average, 0>(out[0]);
  fillBlock<Average, 1>(out[1]);
  fillBlock<Average, 2>(out[2]);
  fillBlock<Average, 3>(out[3]);
}

McKernels makeScalar() {
  McKernels k{};
  fill<false, 8>(k.predict[0][0]);
  fill<false, 16>(k.predict[0][1]);
  fill<true, 8>(k.predict[1][0]);
  fill<true, 16>(k.predict[1][1]);
  fillBlocks<false>(k.block[0]);
  fillBlocks<true>(k.block[1]);
  k.name = "scalar";
  return k;
}

}  // namespace

const McKernels& scalarMcKernels() {
  static const McKernels k = makeScalar();
  return k;
}

}  // namespace vbim::ipu
