#include "ipu/motion_compensation.hpp"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstring>

#include "ipu/clear_block.hpp"
#include "ipu/inter_vlc.hpp"
#include "ipu/kernels.hpp"

namespace vbim::ipu {
namespace {

// One plane of a reference: a frame, or one field of it.
struct SourcePlane {
  const std::uint8_t* base;
  std::ptrdiff_t stride;
  int width;
  int rows;
};

// Keeps a position (half samples) of a block of `size` samples inside [0, 2 * (extent - size)].
bool bound(int& pos, int extent, int size) {
  const int hi = 2 * (extent - size);
  if (pos >= 0 && pos <= hi) return false;
  pos = pos < 0 ? 0 : hi;
  return true;
}

SourcePlane planeOf(const std::vector<std::uint8_t>& plane, int stride, int rows, int width, int field) {
  if (field < 0) return {plane.data(), stride, width, rows};
  return {plane.data() + static_cast<std::ptrdiff_t>(field) * stride, 2 * static_cast<std::ptrdiff_t>(stride), width,
          rows / 2};
}

}  // namespace

PredictionResult predictMacroblock(const Macroblock& mb, const ReferenceSet& refs, const PictureParams& pp,
                                   const McKernels& mc) {
  PredictionResult result;
  for (int k = 0; k < mb.opCount; ++k) {
    const PredictionOp& op = mb.ops[k];
    const FrameStore* ref = op.ref == PredictionRef::kForward    ? refs.forward
                            : op.ref == PredictionRef::kBackward ? refs.backward
                                                                 : refs.current;
    // Destination: the rows of the macroblock (or of one of its fields) in the picture.
    const bool fieldRows = op.dstField >= 0;
    const std::ptrdiff_t yStride = pp.yStride;
    const std::ptrdiff_t cStride = pp.cStride;
    std::uint8_t* dy;
    std::uint8_t* dcb;
    std::uint8_t* dcr;
    std::ptrdiff_t dyStride = yStride;
    std::ptrdiff_t dcStride = cStride;
    const std::ptrdiff_t x = std::ptrdiff_t{16} * mb.mbX;
    if (fieldRows) {
      dy = pp.y + (std::ptrdiff_t{16} * mb.mbY + op.dstField) * yStride + x;
      dcb = pp.cb + (std::ptrdiff_t{8} * mb.mbY + op.dstField) * cStride + x / 2;
      dcr = pp.cr + (std::ptrdiff_t{8} * mb.mbY + op.dstField) * cStride + x / 2;
      dyStride *= 2;
      dcStride *= 2;
    } else {
      dy = pp.y + (std::ptrdiff_t{16} * mb.mbY + op.top) * yStride + x;
      dcb = pp.cb + (std::ptrdiff_t{8} * mb.mbY + op.top / 2) * cStride + x / 2;
      dcr = pp.cr + (std::ptrdiff_t{8} * mb.mbY + op.top / 2) * cStride + x / 2;
    }
    const int h = op.height;
    if (ref == nullptr) {
      // No reference frame: mid-grey (concealed, reported by the caller).
      result.missingReference = true;
      for (int r = 0; r < h; ++r) std::memset(dy + r * dyStride, 128, 16);
      for (int r = 0; r < h / 2; ++r) {
        std::memset(dcb + r * dcStride, 128, 8);
        std::memset(dcr + r * dcStride, 128, 8);
      }
      continue;
    }
    // Source position of the block in the reference's (frame or field) coordinates.
    const int y0 = (fieldRows ? 8 * mb.mbY : 16 * mb.mbY + op.top);
    const int x0 = 16 * mb.mbX;
    const SourcePlane ly = planeOf(ref->y, ref->lumaStride, ref->mbHeight * 16, ref->lumaStride, op.srcField);
    int px = 2 * x0 + op.mvx;
    int py = 2 * y0 + op.mvy;
    const bool cx = bound(px, ly.width, 16);
    const bool cy = bound(py, ly.rows, h);
    result.clamped = result.clamped || cx || cy;
    // Chroma: the (bounded) luma vector halved toward zero (§7.6.3.7), at half the position.
    const int mvx = px - 2 * x0;
    const int mvy = py - 2 * y0;
    const SourcePlane lc = planeOf(ref->cb, ref->chromaStride, ref->mbHeight * 8, ref->chromaStride, op.srcField);
    int qx = x0 + mvx / 2;
    int qy = y0 + mvy / 2;
    bound(qx, lc.width, 8);
    bound(qy, lc.rows, h / 2);
    // Cr has Cb's geometry: the same offsets into its plane.
    const std::ptrdiff_t lumaAt = static_cast<std::ptrdiff_t>(py >> 1) * ly.stride + (px >> 1);
    const std::ptrdiff_t chromaAt =
        (lc.base - ref->cb.data()) + static_cast<std::ptrdiff_t>(qy >> 1) * lc.stride + (qx >> 1);
    const McBlock b{dy,
                    dcb,
                    dcr,
                    dyStride,
                    dcStride,
                    ly.base + lumaAt,
                    ref->cb.data() + chromaAt,
                    ref->cr.data() + chromaAt,
                    ly.stride,
                    lc.stride,
                    h};
    mc.block[op.average ? 1 : 0][((py & 1) << 1) | (px & 1)][((qy & 1) << 1) | (qx & 1)](b);
  }
  return result;
}

void reconstructBlocks(Macroblock& mb, const PictureParams& pp) {
  const bool intra = (mb.type & kMbIntra) != 0;
  const std::ptrdiff_t stride = pp.yStride;
  std::uint8_t* y = pp.y + stride * 16 * mb.mbY + std::ptrdiff_t{16} * mb.mbX;
  const std::ptrdiff_t down = mb.fieldDct ? stride : 8 * stride;
  const std::ptrdiff_t lumaStride = mb.fieldDct ? 2 * stride : stride;
  const std::size_t c = static_cast<std::size_t>(mb.mbY) * 8 * pp.cStride + static_cast<std::size_t>(mb.mbX) * 8;
  // Each block's destination and stride from a table, not a branch on the block number.
  std::uint8_t* const dsts[6] = {y, y + 8, y + down, y + down + 8, pp.cb + c, pp.cr + c};
  const int strides[6] = {static_cast<int>(lumaStride),
                          static_cast<int>(lumaStride),
                          static_cast<int>(lumaStride),
                          static_cast<int>(lumaStride),
                          pp.cStride,
                          pp.cStride};
  // The intra kernel, or the kind's add kernel (kIdctFirstOnly lets Pcsx2 and Libmpeg2 take their
  // decoders' shortcut for a block whose only coded coefficient is the first, ipu/idct_libmpeg2.hpp).
  const IdctFn idct = intra ? pp.idct : pp.idctAdd;
  // The coded blocks by the pattern's set bits (bit 5 is block 0): a branch per bit would be a
  // coin toss on busy P and B pictures.
  for (unsigned pattern = intra ? 0x3Fu : mb.pattern & 0x3Fu; pattern != 0;) {
    const int b = std::countl_zero(pattern) - 26;
    pattern &= ~(32u >> b);
    std::int16_t* blk = mb.block[b];
    idct(blk, mb.rowMask[b], mb.colMask[b], dsts[b], strides[b]);
    clearBlock(blk);
  }
}

}  // namespace vbim::ipu
