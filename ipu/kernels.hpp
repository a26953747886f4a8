// The hot loops of the decoder behind function pointers: the scalar code in vbim_ipu is the
// reference; vbim_ipu_simd (ipu/simd/) provides Highway versions chosen at run time that must give
// the same bytes (tests/ipu/simd_test.cpp).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "ipu/csc.hpp"
#include "ipu/mc_kernels.hpp"

namespace vbim::ipu {

// Which 8x8 inverse DCT the decoder computes (platform parameter ipu.idct, docs/timing/ipu.md#idct):
// - Pcsx2: the integer IDCT of PCSX2's IPU (libmpeg2 0.4's form, ipu/idct_libmpeg2.hpp), the default;
// - Libmpeg2: the C IDCT of libmpeg2 0.5.1 (`mpeg2dec -c`), which differs from Pcsx2's in the last bit;
// - Exact: the exact-rounded integer IDCT of ipu/idct.hpp, the default before issue #29.
enum class IdctKind : std::uint8_t { Pcsx2, Libmpeg2, Exact };
inline constexpr int kIdctKinds = 3;
inline constexpr IdctKind kAllIdctKinds[kIdctKinds] = {IdctKind::Pcsx2, IdctKind::Libmpeg2, IdctKind::Exact};
// The default of DecoderOptions, ipu.idct, `vbim decode --idct` and `vbim vectors --idct`.
inline constexpr IdctKind kDefaultIdct = IdctKind::Pcsx2;

// "pcsx2", "libmpeg2", "exact": the names of ipu.idct and `vbim decode --idct`.
const char* idctKindName(IdctKind k);
std::optional<IdctKind> idctKindByName(std::string_view name);

// block: 64 coefficients, raster order, each in [-2048, 2047]; rowMask / colMask: bit r / c set if
// row r / column c may hold a non-zero coefficient, except that rowMask bit 8 (kIdctToggleOnly)
// instead says: F[7][7] is +-1 and is the only coefficient of row 7 and column 7 (the usual result
// of mismatch control, ISO/IEC 13818-2 §7.4.4). The block is left unchanged.
inline constexpr unsigned kIdctToggleOnly = 0x100;
// IdctAddFn only, rowMask bit 9: the only coefficient coded was the first in scan order (F[0][0];
// F[7][7] may hold the mismatch toggle). Pcsx2 and Libmpeg2 then add the constant
// nonIntraDcResidual(F[0][0]) when nonIntraDcShortcut(F[0][0]) (ipu/idct_libmpeg2.hpp), as their
// decoders do; Exact adds its own transform's value when that is one constant
// (exactIdctIsConstant, ipu/idct.hpp), which gives the same bytes as the full transform.
inline constexpr unsigned kIdctFirstOnly = 0x200;
// Intra: writes the 8x8 result clamped to 0..255.
using IdctFn = void (*)(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst, int stride);
// Non-intra: adds the 8x8 result (the residual) to dst and clamps to 0..255.
using IdctAddFn = void (*)(const std::int16_t* block, unsigned rowMask, unsigned colMask, std::uint8_t* dst,
                           int stride);

struct IdctKernels {
  IdctFn copy;
  IdctAddFn add;
};

struct Kernels {
  IdctKernels idct[kIdctKinds];  // by IdctKind
  CscRowFn cscRow;
  const McKernels* mc;  // motion compensation (ipu/mc_kernels.hpp)
  const char* name;
  const IdctKernels& idctOf(IdctKind k) const { return idct[static_cast<int>(k)]; }
};

const Kernels& scalarKernels();

}  // namespace vbim::ipu
