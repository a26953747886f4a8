// RGB32 written by the decode itself (RgbaOutput, decodeToRgba): after every picture the image
// equals the scalar conversion of the frame store, on the serial path and on the slice-parallel
// one (where each job converts its own rows), including rows no slice reached, rows revisited
// late, corrupt slices, sizes that are not whole macroblocks, interlaced frames, field pictures,
// the IPU's padded output and MPEG-1. Runs under ThreadSanitizer in CI.
#include <gtest/gtest.h>

#include <chrono>
#include <set>
#include <string>
#include <vector>

#include "ipu/csc.hpp"
#include "ipu/elementary_stream.hpp"
#include "ipu/picture_decoder.hpp"
#include "ipu/pool_runner.hpp"
#include "ipu/simd/simd_kernels.hpp"
#include "ipu/start_code.hpp"
#include "runtime/worker_pool.hpp"
#include "tests/ipu/support/libav_mpeg.hpp"

namespace vbim::ipu {
namespace {

constexpr CscThresholds kThresholds{40, 90};  // both SETTH paths show up in the bytes

std::vector<std::uint8_t> encode(int w, int h, int frames, bool mpeg1 = false, bool interlaced = false) {
  testing::EncodeOptions o;
  o.width = w;
  o.height = h;
  o.frames = frames;
  o.quantiser = 3;
  o.mpeg1 = mpeg1;
  o.interlacedDct = interlaced;
  o.content = testing::Content::kNoise;
  return testing::encodeIntra(o);
}

// The picture's bytes without the slices that start the given macroblock rows.
std::vector<std::uint8_t> withoutRows(std::span<const std::uint8_t> unit, const std::set<int>& rows) {
  std::vector<std::uint8_t> out;
  std::size_t pos = findStartCode(unit.data(), unit.size(), 0);
  out.insert(out.end(), unit.begin(), unit.begin() + static_cast<std::ptrdiff_t>(pos));
  while (pos < unit.size()) {
    const std::size_t next = findStartCode(unit.data(), unit.size(), pos + 3);
    const int code = pos + 3 < unit.size() ? unit[pos + 3] : 0;
    const bool slice = code >= 1 && code <= 0xAF;
    if (!slice || !rows.count(code - 1)) {
      out.insert(out.end(), unit.begin() + static_cast<std::ptrdiff_t>(pos),
                 unit.begin() + static_cast<std::ptrdiff_t>(next));
    }
    pos = next;
  }
  return out;
}

// Three decoders fed the same pictures: serial, one pool thread, three sleeping pool threads
// (more threads than some pictures have jobs). Each picture's image is checked against the scalar
// conversion of that decoder's frame store, and the three against each other.
class ThreeWays {
 public:
  explicit ThreeWays(bool wholeMacroblocks = false) : whole_(wholeMacroblocks) {
    DecoderOptions o;
    o.kernels = &simdKernels();
    for (Lane& l : lanes_) l.dec = Decoder(o);
  }

  void decode(std::span<const std::uint8_t> bytes, const std::string& what) {
    PictureReport reports[3];
    for (int i = 0; i < 3; ++i) {
      Lane& l = lanes_[i];
      WorkerPool* pool = i == 1 ? &one_ : (i == 2 ? &three_ : nullptr);
      // Poisoned, so a line the decode does not write shows even where the store kept its value.
      l.rgba.pixels.assign(l.rgba.pixels.size(), 0xA5);
      const RgbaOutput target{&l.rgba, kThresholds, whole_};
      if (pool) {
        reports[i] = decodeOnPool(l.dec, bytes, *pool, target);
      } else {
        reports[i] = l.dec.decode(bytes, nullptr, target);
      }
    }
    for (int i = 0; i < 3; ++i) {
      const Lane& l = lanes_[i];
      SCOPED_TRACE(what + ", decoder " + std::to_string(i));
      ASSERT_TRUE(reports[i].produced);
      const FrameStore& fs = l.dec.frame();
      Rgba8Image reference;
      if (whole_) {
        convertToRgba32(fs, fs.mbWidth * 16, fs.mbHeight * 16, kThresholds, reference);
      } else {
        convertToRgba32(fs, l.dec.width(), l.dec.height(), kThresholds, reference);
      }
      ASSERT_EQ(l.rgba.width, reference.width);
      ASSERT_EQ(l.rgba.height, reference.height);
      EXPECT_TRUE(l.rgba.pixels == reference.pixels);
      EXPECT_EQ(reports[i].macroblocksConcealed, reports[0].macroblocksConcealed);
      EXPECT_TRUE(l.rgba.pixels == lanes_[0].rgba.pixels);
    }
  }
  const Rgba8Image& image(int i) const { return lanes_[i].rgba; }
  const Decoder& decoder(int i) const { return lanes_[i].dec; }

 private:
  // decode(bytes, pool) with an image: through decodeToRgba for the display size.
  PictureReport decodeOnPool(Decoder& dec, std::span<const std::uint8_t> bytes, WorkerPool& pool,
                             const RgbaOutput& target) {
    if (!target.wholeMacroblocks) return decodeToRgba(dec, bytes, *target.image, pool, target.thresholds);
    PoolSliceRunner runner(pool);
    return dec.decode(bytes, &runner, target);
  }
  struct Lane {
    Decoder dec;
    Rgba8Image rgba;
  };
  bool whole_;
  Lane lanes_[3];
  WorkerPool one_{1};
  WorkerPool three_{3, std::chrono::microseconds(0)};
};

TEST(IpuRgbaOutput, EveryPictureEqualsTheConversionOfTheStore) {
  for (const auto& [w, h] : {std::pair{160, 144}, std::pair{100, 76}, std::pair{17, 9}}) {
    const auto es = encode(w, h, 3);
    ThreeWays t;
    for (const AccessUnit& au : splitAccessUnits(es))
      t.decode(std::span(es).subspan(au.offset, au.size), std::to_string(w) + "x" + std::to_string(h));
    EXPECT_EQ(t.image(0).width, w);
    EXPECT_EQ(t.image(0).height, h);
  }
}

// Rows with no slice keep the previous picture: first, inner (between two jobs' rows) and last.
TEST(IpuRgbaOutput, RowsNoSliceReachedAreConvertedToo) {
  const auto es = encode(160, 144, 2);
  const auto units = splitAccessUnits(es);
  ThreeWays t;
  t.decode(std::span(es).subspan(units[0].offset, units[0].size), "picture 1");
  const auto second = withoutRows(std::span(es).subspan(units[1].offset, units[1].size), {0, 3, 4, 6, 8});
  t.decode(second, "picture 2 without rows 0, 3, 4, 6, 8");
  EXPECT_EQ(t.decoder(0).frame().mbHeight, 9);
}

TEST(IpuRgbaOutput, ARowRevisitedLateAndCorruptSlicesGiveTheSameImage) {
  auto es = encode(160, 144, 3);
  const auto units = splitAccessUnits(es);
  std::vector<std::uint8_t> revisited(es.begin() + static_cast<std::ptrdiff_t>(units[0].offset),
                                      es.begin() + static_cast<std::ptrdiff_t>(units[0].offset + units[0].size));
  const auto second = std::span(es).subspan(units[1].offset, units[1].size);
  const auto rowZero = withoutRows(second, {1, 2, 3, 4, 5, 6, 7, 8});
  const std::size_t firstSlice = findStartCode(rowZero.data(), rowZero.size(), 0);
  std::size_t s = firstSlice;
  while (s < rowZero.size() && rowZero[s + 3] != 0x01) s = findStartCode(rowZero.data(), rowZero.size(), s + 3);
  ASSERT_LT(s, rowZero.size());
  revisited.insert(revisited.end(), rowZero.begin() + static_cast<std::ptrdiff_t>(s), rowZero.end());
  ThreeWays t;
  t.decode(revisited, "picture 1 with picture 2's row 0 appended");
  const auto third = std::span(es).subspan(units[2].offset, units[2].size);
  std::size_t slice = findStartCode(third.data(), third.size(), 0);
  while (slice < third.size() && (third[slice + 3] < 1 || third[slice + 3] > 0xAF))
    slice = findStartCode(third.data(), third.size(), slice + 3);
  ASSERT_LT(slice, third.size());
  for (std::size_t i = units[2].offset + slice + 8; i < units[2].offset + units[2].size; i += 211) es[i] ^= 0x24;
  t.decode(std::span(es).subspan(units[2].offset, units[2].size), "corrupt picture 3");
}

// progressive_sequence = 0: the frame has 2 * ceil(h / 32) macroblock rows, more than the image's.
TEST(IpuRgbaOutput, InterlacedFrameWithRowsBelowThePicture) {
  const auto es = encode(96, 72, 2, false, true);
  ThreeWays t;
  for (const AccessUnit& au : splitAccessUnits(es)) t.decode(std::span(es).subspan(au.offset, au.size), "interlaced");
  EXPECT_EQ(t.decoder(0).frame().mbHeight, 6);
}

TEST(IpuRgbaOutput, WholeMacroblocksAsTheIpuWritesThem) {
  const auto es = encode(100, 76, 2);
  ThreeWays t(true);
  for (const AccessUnit& au : splitAccessUnits(es)) t.decode(std::span(es).subspan(au.offset, au.size), "padded");
  EXPECT_EQ(t.image(0).width, 112);
  EXPECT_EQ(t.image(0).height, 80);
}

TEST(IpuRgbaOutput, Mpeg1IsConvertedAfterTheSerialDecode) {
  const auto es = encode(100, 76, 2, true);
  ThreeWays t;
  for (const AccessUnit& au : splitAccessUnits(es)) t.decode(std::span(es).subspan(au.offset, au.size), "MPEG-1");
}

// A top field picture changes the even lines only; the whole frame is converted after it.
TEST(IpuRgbaOutput, FieldPictureConvertsTheWholeFrame) {
  auto es = encode(32, 32, 1);
  bool patched = false;
  for (std::size_t i = 0; i + 7 < es.size() && !patched; ++i) {
    if (es[i] == 0 && es[i + 1] == 0 && es[i + 2] == 1 && es[i + 3] == 0xB5 && (es[i + 4] >> 4) == 8) {
      es[i + 6] = static_cast<std::uint8_t>((es[i + 6] & ~0x03) | 0x01);  // picture_structure = 1
      patched = true;
    }
  }
  ASSERT_TRUE(patched);
  ThreeWays t;
  t.decode(es, "top field");
  EXPECT_EQ(t.decoder(0).picture().pictureStructure, 1);
}

TEST(IpuRgbaOutput, AnUndecodablePictureLeavesTheImageAlone) {
  const auto es = encode(64, 48, 1);
  const std::size_t seq = findStartCode(es.data(), es.size(), 0);
  ASSERT_EQ(es[seq + 3], 0xB3);
  const std::size_t afterSeq = findStartCode(es.data(), es.size(), seq + 3);
  Decoder dec;
  Rgba8Image image(3, 2);
  image.pixels.assign(image.pixels.size(), 7);
  const PictureReport r = decodeToRgba(dec, std::span(es).subspan(afterSeq), image);  // no sequence header
  EXPECT_FALSE(r.produced);
  EXPECT_EQ(image.width, 3);
  EXPECT_EQ(image.pixels, std::vector<std::uint8_t>(std::size_t{24}, 7));
}

}  // namespace
}  // namespace vbim::ipu
