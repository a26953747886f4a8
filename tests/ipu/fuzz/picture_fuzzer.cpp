// libFuzzer target for the picture decoder: any bytes, as one access unit and split into access
// units (I, P and B pictures; seeds with GOPs, field pictures and dual prime). The decoder must not crash, read out of
// bounds (ASan) or hang; the Highway kernels must give the same frame as the scalar reference; the slice-parallel path
// the same frame, and an RGBA image of the decoded picture's size equal to the conversion of that frame. Built with
// -DVBIM_FUZZ=ON and clang; scripts/fuzz.sh runs it for a bounded time from the seed corpus
// next to this file.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <span>

#include "ipu/csc.hpp"
#include "ipu/elementary_stream.hpp"
#include "ipu/picture_decoder.hpp"
#include "ipu/simd/simd_kernels.hpp"

namespace {

// Runs the jobs of the slice-parallel path on the calling thread, last job first: exercises the
// split into jobs and the merge, and shows the result does not depend on the order jobs run in.
class ReverseRunner final : public vbim::ipu::SliceRunner {
 public:
  unsigned threads() const override { return 1; }
  void run(std::size_t count, const std::function<void(std::size_t)>& fn) override {
    for (std::size_t k = count; k-- > 0;) fn(k);
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  vbim::ipu::DecoderOptions small;
  small.maxWidth = 720;  // keeps each input's frame store and time bounded
  small.maxHeight = 576;
  small.recordMacroblocks = true;
  vbim::ipu::DecoderOptions simd = small;
  simd.kernels = &vbim::ipu::simdKernels();
  vbim::ipu::Decoder scalar(small), fast(simd), split(simd);
  const vbim::ipu::PictureReport a = scalar.decode(bytes);
  const vbim::ipu::PictureReport b = fast.decode(bytes);
  if (a.issueCount != b.issueCount || scalar.frame().y != fast.frame().y || scalar.frame().cb != fast.frame().cb ||
      scalar.frame().cr != fast.frame().cr)
    std::abort();
  // The split decode also writes RGB32 itself (each job converts its rows, the rest after them):
  // it must equal the conversion of the store it left.
  ReverseRunner reverse;
  vbim::Rgba8Image splitRgba;
  const vbim::ipu::PictureReport c = vbim::ipu::decodeToRgba(split, bytes, splitRgba, {40, 90}, &reverse);
  if (c.issueCount != a.issueCount || c.macroblocksDecoded != a.macroblocksDecoded ||
      split.frame().y != fast.frame().y || split.frame().cb != fast.frame().cb || split.frame().cr != fast.frame().cr)
    std::abort();
  if (c.produced) {
    if (splitRgba.width != split.width() || splitRgba.height != split.height()) std::abort();
    vbim::Rgba8Image expected;
    vbim::ipu::convertToRgba32(split.frame(), splitRgba.width, splitRgba.height, {40, 90}, expected);
    if (expected.pixels != splitRgba.pixels) std::abort();
  }
  if (a.produced && a.macroblocksDecoded + a.macroblocksConcealed != a.macroblocks) std::abort();
  // Picture by picture (P and B pictures predict from the frames before), with libmpeg2's IDCT
  // on a second decoder, and every frame leaving in display order read whole.
  vbim::ipu::DecoderOptions m2 = small;
  m2.idct = vbim::ipu::IdctKind::Libmpeg2;
  vbim::ipu::Decoder ordered(m2);
  vbim::Yuv420Image shown;
  auto show = [&]() {
    if (ordered.displayFrame())
      vbim::ipu::copyToYuv420(*ordered.displayFrame(), ordered.displayWidth(), ordered.displayHeight(), shown);
  };
  for (const vbim::ipu::AccessUnit& au : vbim::ipu::splitAccessUnits(bytes)) {
    if (au.offset + au.size > size) std::abort();
    scalar.decode(bytes.subspan(au.offset, au.size));
    const vbim::ipu::PictureReport r = ordered.decode(bytes.subspan(au.offset, au.size));
    if (r.produced && r.macroblocksDecoded + r.macroblocksConcealed != r.macroblocks) std::abort();
    show();
  }
  while (ordered.flushDisplay()) show();
  if (scalar.hasSequence() && !scalar.frame().empty()) {
    vbim::Rgba8Image img;
    vbim::ipu::convertToRgba32(scalar.frame(), scalar.frame().mbWidth * 16, scalar.frame().mbHeight * 16, {40, 90}, img,
                               vbim::ipu::cscRowsRgba32Simd);
  }
  return 0;
}
