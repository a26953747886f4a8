#include "ipu/kernels.hpp"

#include "ipu/idct.hpp"

namespace vbim::ipu {
namespace {

void idctScalarKernel(const std::int16_t* block, unsigned rowMask, unsigned, std::uint8_t* dst, int stride) {
  idctScalar(block, (rowMask & kIdctToggleOnly) ? (rowMask | 0x80) : rowMask, dst, stride);
}

}  // namespace

const Kernels& scalarKernels() {
  static const Kernels k{idctScalarKernel, cscRowsRgba32Scalar, "scalar"};
  return k;
}

}  // namespace vbim::ipu
