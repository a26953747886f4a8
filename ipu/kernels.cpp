#include "ipu/kernels.hpp"

#include <cstddef>

#include "ipu/idct.hpp"
#include "ipu/idct_libmpeg2.hpp"

namespace vbim::ipu {
namespace {

std::uint8_t clampPixel(int v) {
  return static_cast<std::uint8_t>(v < 0 ? 0 : (v > 255 ? 255 : v));
}

// The signed 8x8 result of each kind, before any clip. The masks only speed up the exact form (the
// libmpeg2 forms skip their own zero rows); F[7][7] is in the block whatever the masks say.
template <IdctKind K>
void transform(const std::int16_t* block, unsigned rowMask, std::int16_t* out) {
  if constexpr (K == IdctKind::Pcsx2) {
    idctPcsx2(block, out);
  } else if constexpr (K == IdctKind::Libmpeg2) {
    idctLibmpeg2(block, out);
  } else {
    idctSignedUnclipped(block, (rowMask & kIdctToggleOnly) ? (rowMask | 0x80) : rowMask, out);
  }
}

template <IdctKind K>
void copyKernel(const std::int16_t* block, unsigned rowMask, unsigned, std::uint8_t* dst, int stride) {
  if constexpr (K == IdctKind::Exact) {
    idctScalar(block, (rowMask & kIdctToggleOnly) ? (rowMask | 0x80) : rowMask, dst, stride);
  } else {
    std::int16_t r[64];
    transform<K>(block, rowMask, r);
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) dst[static_cast<std::ptrdiff_t>(y) * stride + x] = clampPixel(r[8 * y + x]);
  }
}

// A non-intra block whose residual is one value: that value added to every sample.
bool constantResidual(IdctKind k, const std::int16_t* block, unsigned rowMask, int& value) {
  if (!(rowMask & kIdctFirstOnly)) return false;
  if (k != IdctKind::Exact) {
    value = nonIntraDcResidual(block[0]);
    return nonIntraDcShortcut(block[0]);
  }
  value = exactIdctConstant(block[0]);
  return exactIdctIsConstant(block[0], block[63]);  // the exact transform's own value, not a rule
}

template <IdctKind K>
void addKernel(const std::int16_t* block, unsigned rowMask, unsigned, std::uint8_t* dst, int stride) {
  int v = 0;
  if (constantResidual(K, block, rowMask, v)) {
    for (int y = 0; y < 8; ++y) {
      for (int x = 0; x < 8; ++x) {
        std::uint8_t& p = dst[static_cast<std::ptrdiff_t>(y) * stride + x];
        p = clampPixel(p + v);
      }
    }
    return;
  }
  std::int16_t r[64];
  transform<K>(block, rowMask, r);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      std::uint8_t& p = dst[static_cast<std::ptrdiff_t>(y) * stride + x];
      p = clampPixel(p + r[8 * y + x]);
    }
  }
}

constexpr const char* kNames[kIdctKinds] = {"pcsx2", "libmpeg2", "exact"};

}  // namespace

const char* idctKindName(IdctKind k) {
  return kNames[static_cast<int>(k)];
}

std::optional<IdctKind> idctKindByName(std::string_view name) {
  for (const IdctKind k : kAllIdctKinds)
    if (name == kNames[static_cast<int>(k)]) return k;
  return std::nullopt;
}

const Kernels& scalarKernels() {
  static const Kernels k{{{copyKernel<IdctKind::Pcsx2>, addKernel<IdctKind::Pcsx2>},
                          {copyKernel<IdctKind::Libmpeg2>, addKernel<IdctKind::Libmpeg2>},
                          {copyKernel<IdctKind::Exact>, addKernel<IdctKind::Exact>}},
                         cscRowsRgba32Scalar,
                         &scalarMcKernels(),
                         "scalar"};
  return k;
}

}  // namespace vbim::ipu
