// The IPU on the simulated clock: cost per macroblock, FIFOs and DMA back-pressure.
#include "ipu/ipu_unit.hpp"
#include "config/params_toml.hpp"

#include <gtest/gtest.h>

#include "ipu/elementary_stream.hpp"
#include "tests/ipu/support/libav_mpeg.hpp"

namespace vbim::ipu {
namespace {

std::vector<std::uint8_t> firstPicture(testing::Content content = testing::Content::kBusy) {
  testing::EncodeOptions o;
  o.width = 128;
  o.height = 64;
  o.frames = 1;
  o.quantiser = 3;
  o.content = content;
  return testing::encodePictures(o).at(0);
}

struct TimedRun {
  TimedPicture result;
  Rgba8Image image;
  std::vector<MacroblockBits> trace;
};

Task<void> decodeOnce(IpuUnit& unit, const std::vector<std::uint8_t>& bytes, TimedRun& run) {
  run.result = co_await unit.decode(bytes, run.image);
  run.trace = unit.decoder().macroblockTrace();
}

Task<void> stallOutputLater(Scheduler& s, IpuUnit& unit, Tick at, Tick duration) {
  co_await s.until(at);
  unit.stallOutputDma(duration);
}

TimedRun runWith(const IpuParams& p, const std::vector<std::uint8_t>& bytes, Tick stallAt = -1, Tick stallFor = 0,
                 Rgba8Image initial = {}) {
  Scheduler s;
  Tracer tracer;
  IpuUnit unit(s, p, &tracer);
  TimedRun run;
  run.image = std::move(initial);
  s.spawn("player", decodeOnce(unit, bytes, run));
  if (stallAt >= 0) s.spawn("fault", stallOutputLater(s, unit, stallAt, stallFor));
  s.run();
  return run;
}

TEST(IpuUnit, OutputEqualsTheFunctionalDecode) {
  const std::vector<std::uint8_t> bytes = firstPicture();
  const TimedRun run = runWith(IpuParams{}, bytes);
  ASSERT_TRUE(run.result.report.produced);
  Decoder dec;
  dec.decode(bytes);
  Rgba8Image expected;
  convertToRgba32(dec.frame(), dec.width(), dec.height(), {}, expected);
  EXPECT_EQ(run.image.pixels, expected.pixels);
  EXPECT_EQ(run.image.width, 128);
  EXPECT_EQ(run.image.row(0)[3], 0x80);  // RGB32 alpha = 1.0
}

// The player hands the IPU recycled buffers (runtime/image_pool.hpp) holding an older picture: the
// decode must write every byte, also where a damaged picture's macroblocks are concealed.
TEST(IpuUnit, DecodesIntoAStaleBufferAsIntoAFreshOne) {
  const std::vector<std::uint8_t> whole = firstPicture();
  const std::vector<std::uint8_t> cut(whole.begin(), whole.begin() + static_cast<std::ptrdiff_t>(whole.size() / 2));
  for (const auto* bytes : {&whole, &cut}) {
    const TimedRun fresh = runWith(IpuParams{}, *bytes);
    ASSERT_TRUE(fresh.result.report.produced);
    Rgba8Image stale(128, 64);
    std::fill(stale.pixels.begin(), stale.pixels.end(), std::uint8_t{0xAB});
    const TimedRun reused = runWith(IpuParams{}, *bytes, -1, 0, std::move(stale));
    EXPECT_EQ(reused.image.pixels, fresh.image.pixels) << (bytes == &cut ? "damaged picture" : "whole picture");
    EXPECT_EQ(reused.result.finished, fresh.result.finished);
  }
  EXPECT_GT(runWith(IpuParams{}, cut).result.report.macroblocksConcealed, 0);
}

// Doubling base, per-bit and CSC cost moves the completion time by exactly one more sum of
// per-macroblock costs: the DMA never limits at the default rates.
Task<void> decodeInTurn(IpuUnit& unit, std::vector<const std::vector<std::uint8_t>*> pictures,
                        std::vector<TimedRun>& runs) {
  for (const auto* bytes : pictures) {
    runs.emplace_back();
    runs.back().result = co_await unit.decode(*bytes, runs.back().image);
  }
}

// The one IPU decodes the lightmap's and the sky's pictures in turn. A macroblock it conceals in one
// picture is mid-grey: it never shows the picture decoded before, which may be the other stream's
// (of the same size here), and it is the same whatever came before (so replay, which decodes each
// picture on its own, shows the same bytes).
TEST(IpuUnit, AConcealedMacroblockDoesNotShowThePictureDecodedBefore) {
  const std::vector<std::uint8_t> other = firstPicture(testing::Content::kSmooth);
  const std::vector<std::uint8_t> whole = firstPicture();
  const std::vector<std::uint8_t> cut(whole.begin(), whole.begin() + static_cast<std::ptrdiff_t>(whole.size() / 2));
  Scheduler s;
  IpuUnit unit(s, IpuParams{});
  std::vector<TimedRun> runs;
  s.spawn("ee", decodeInTurn(unit, {&other, &cut}, runs));
  s.run();
  ASSERT_EQ(runs.size(), 2u);
  ASSERT_GT(runs[1].result.report.macroblocksConcealed, 0);
  const TimedRun alone = runWith(IpuParams{}, cut);
  EXPECT_EQ(runs[1].image.pixels, alone.image.pixels);
  // The last macroblock was cut off: mid-grey (Y = Cb = Cr = 128), not the other picture's.
  const Rgba8Image& img = runs[1].image;
  const std::uint8_t* last = img.row(img.height - 1) + 4 * (img.width - 1);
  // ipu/csc.hpp: lum = ((0x95 * (128 - 16)) >> 6) + 1 = 261, no chroma term, (261 + 0) >> 1 = 130.
  EXPECT_EQ(std::vector<std::uint8_t>(last, last + 4), (std::vector<std::uint8_t>{130, 130, 130, 0x80}));
  const std::uint8_t* before = runs[0].image.row(img.height - 1) + 4 * (img.width - 1);
  EXPECT_NE(std::vector<std::uint8_t>(last, last + 4), std::vector<std::uint8_t>(before, before + 4));
}

TEST(IpuUnit, DoublingMacroblockCostMovesCompletionByItsSum) {
  const std::vector<std::uint8_t> bytes = firstPicture();
  IpuParams p;
  const TimedRun a = runWith(p, bytes);
  IpuParams p2 = p;
  p2.mb_base_cycles *= 2;
  p2.mb_cycles_per_bit *= 2;
  p2.csc_cycles_per_mb *= 2;
  const TimedRun b = runWith(p2, bytes);
  ASSERT_EQ(a.trace.size(), 32u);
  Tick sum = 0;
  for (const MacroblockBits& m : a.trace) sum += p.mb_base_cycles + p.mb_cycles_per_bit * m.bits + p.csc_cycles_per_mb;
  const Tick da = a.result.finished - a.result.started;
  const Tick db = b.result.finished - b.result.started;
  EXPECT_EQ(db - da, sum);
  // And the whole time is command start + the sum + the EE's IDEC restart at each of the 3 later
  // slices (one per macroblock row) + draining the last CSC row's 4 qwords.
  EXPECT_EQ(da, p.idec_start_cycles + sum + 3 * (p.slice_restart_cycles + p.idec_start_cycles) +
                    4 * p.fromipu_cycles_per_qword);
  EXPECT_EQ(a.result.outputStalls, 0);
  EXPECT_EQ(a.image.pixels, b.image.pixels);
}

// IDEC stops at every slice start code and the EE issues it again: one command per slice (4 rows
// of 8 macroblocks, one slice each), each later one costing the restart and the IDEC start.
TEST(IpuUnit, IdecIsIssuedOncePerSlice) {
  const std::vector<std::uint8_t> bytes = firstPicture();
  IpuParams p;
  const TimedRun a = runWith(p, bytes);
  EXPECT_EQ(a.result.idecCommands, 4);
  std::int64_t starts = 0;
  for (const MacroblockBits& m : a.trace) starts += m.sliceStart ? 1 : 0;
  EXPECT_EQ(starts, 4);
  IpuParams q = p;
  q.slice_restart_cycles += 1000;
  const TimedRun b = runWith(q, bytes);
  EXPECT_EQ((b.result.finished - b.result.started) - (a.result.finished - a.result.started), 3 * 1000);
  EXPECT_EQ(a.image.pixels, b.image.pixels);
}

// The output FIFO is not drained for a while: decode stalls, and completion moves by the length
// of the stall less the work the decoder can still do before it must push (at most one
// macroblock's VLD/IDCT plus the rows that fit in the FIFO).
TEST(IpuUnit, DecodeStallsWhenOutputIsNotDrained) {
  const std::vector<std::uint8_t> bytes = firstPicture();
  const TimedRun a = runWith(IpuParams{}, bytes);
  const Tick stall = 20'000;
  const TimedRun b = runWith(IpuParams{}, bytes, 5'000, stall);
  const Tick delay = (b.result.finished - b.result.started) - (a.result.finished - a.result.started);
  EXPECT_GT(b.result.outputStalls, 0);
  EXPECT_LE(delay, stall);
  Tick maxMb = 0;
  const IpuParams p;
  for (const MacroblockBits& m : a.trace)
    maxMb = std::max<Tick>(maxMb, p.mb_base_cycles + p.mb_cycles_per_bit * m.bits + p.csc_cycles_per_mb);
  EXPECT_GE(delay, stall - maxMb);
  EXPECT_EQ(a.image.pixels, b.image.pixels);
}

// A slow toIPU DMA starves the decoder: it cannot finish before the last input qword arrives.
TEST(IpuUnit, SlowInputDmaBoundsDecode) {
  const std::vector<std::uint8_t> bytes = firstPicture();
  IpuParams p;
  p.toipu_cycles_per_qword = 400;
  const TimedRun r = runWith(p, bytes);
  const Tick qwords = static_cast<Tick>((bytes.size() + 15) / 16);
  EXPECT_GE(r.result.finished - r.result.started, qwords * 400);
  const TimedRun fast = runWith(IpuParams{}, bytes);
  EXPECT_GT(r.result.finished, fast.result.finished);
}

// Input left after the last macroblock (stuffing, or what follows a picture whose last
// macroblocks were concealed) is still being moved by the toIPU DMA and dropped by the core when
// the output is complete and decode() returns. The two loops must not read the finished command
// after that (under ASan this read of the released coroutine frame was a use after free), and the
// next command must start on its own input.
Task<void> decodeTwice(IpuUnit& unit, const std::vector<std::uint8_t>& first, const std::vector<std::uint8_t>& second,
                       TimedRun& a, TimedRun& b) {
  a.result = co_await unit.decode(first, a.image);
  b.result = co_await unit.decode(second, b.image);
}

TEST(IpuUnit, TrailingInputOutlivesTheCommandSafely) {
  const std::vector<std::uint8_t> bytes = firstPicture();
  std::vector<std::uint8_t> padded = bytes;
  constexpr Tick kTrailingQwords = 4096;
  padded.resize(bytes.size() + kTrailingQwords * 16, 0);  // zero stuffing after the picture
  Scheduler s;
  IpuUnit unit(s, IpuParams{});
  TimedRun a;
  TimedRun b;
  s.spawn("player", decodeTwice(unit, padded, bytes, a, b));
  s.run();
  ASSERT_TRUE(a.result.report.produced);
  ASSERT_TRUE(b.result.report.produced);
  EXPECT_EQ(a.image.pixels, b.image.pixels);
  // The first command returned with its trailing qwords still queued (the input FIFO holds only
  // a few): the second command's decode waited while the core dropped them, one per DMA cycle.
  const TimedRun alone = runWith(IpuParams{}, bytes);
  const Tick waited = (b.result.finished - b.result.started) - (alone.result.finished - alone.result.started);
  EXPECT_GT(waited, kTrailingQwords / 2 * IpuParams{}.toipu_cycles_per_qword);
  EXPECT_LE(waited, kTrailingQwords * IpuParams{}.toipu_cycles_per_qword);
}

TEST(IpuUnit, ParamsAreRegisteredWithSources) {
  ParamTable t;
  IpuParams p;
  describeParams(t, p);
  ASSERT_NE(t.find("ipu.mb_base_cycles"), nullptr);
  for (const auto& param : t.params()) {
    EXPECT_EQ(param.key.rfind("ipu.", 0), 0u) << param.key;
    EXPECT_FALSE(param.source.empty()) << param.key;
  }
  config::applyToml(t, "[ipu]\nmb_base_cycles = 800\n", "<test>");
  EXPECT_EQ(p.mb_base_cycles, 800);
}

}  // namespace
}  // namespace vbim::ipu
