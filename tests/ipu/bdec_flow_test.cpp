// P and B pictures on the simulated clock (issue #29, item 3): the BDEC flow of ps2sdk's libmpeg
// (ipu/bdec_flow*.hpp) through IpuUnit's per-stream decoders.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "ipu/bdec_flow.hpp"
#include "ipu/bdec_flow_timing.hpp"
#include "ipu/elementary_stream.hpp"
#include "ipu/ipu_unit.hpp"
#include "tests/ipu/support/libav_mpeg.hpp"

namespace vbim::ipu {
namespace {

using Bytes = std::vector<std::uint8_t>;

// A GOP stream split into pictures (stream order).
std::vector<Bytes> gopPictures(testing::Content content, int gopSize, int bFrames, int frames = 7,
                               std::uint32_t seed = 1) {
  testing::EncodeOptions o;
  o.width = 96;
  o.height = 64;
  o.frames = frames;
  o.gopSize = gopSize;
  o.bFrames = bFrames;
  o.quantiser = 4;
  o.content = content;
  o.seed = seed;
  return testing::encodePictures(o);
}

struct Shown {
  std::vector<Rgba8Image> frames;
  std::vector<TimedPicture> results;
};

// Decodes the pictures of each stream, taking one picture from each stream in turn, then flushes.
Task<void> decodeInterleaved(IpuUnit& unit, std::vector<StreamId> ids, const std::vector<std::vector<Bytes>>* streams,
                             std::vector<Shown>* shown) {
  std::size_t most = 0;
  for (const auto& s : *streams) most = std::max(most, s.size());
  for (std::size_t i = 0; i <= most; ++i) {
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const std::vector<Bytes>& pics = (*streams)[k];
      if (i > pics.size()) continue;
      Rgba8Image img;
      const TimedPicture tp =
          i < pics.size() ? co_await unit.decode(ids[k], pics[i], img) : co_await unit.flush(ids[k], img);
      (*shown)[k].results.push_back(tp);
      if (tp.displayed) (*shown)[k].frames.push_back(std::move(img));
    }
  }
}

std::vector<Shown> run(const IpuParams& p, const EeFlowCosts& ee, const std::vector<std::vector<Bytes>>& streams,
                       Tracer* tracer = nullptr) {
  Scheduler s;
  IpuUnit unit(s, p, tracer, {}, ee);
  std::vector<StreamId> ids;
  for (std::size_t k = 0; k < streams.size(); ++k) ids.push_back(unit.openStream(DecodePath::kBdec));
  std::vector<Shown> shown(streams.size());
  s.spawn("ee", decodeInterleaved(unit, ids, &streams, &shown));
  s.run();
  return shown;
}

// The frames libmpeg would show: the functional decoder's display order, through CSC.
std::vector<Rgba8Image> expectedFrames(const std::vector<Bytes>& pics) {
  Decoder dec;
  std::vector<Rgba8Image> out;
  auto take = [&] {
    if (const FrameStore* f = dec.displayFrame()) {
      out.emplace_back();
      convertToRgba32(*f, dec.displayWidth(), dec.displayHeight(), {}, out.back());
    }
  };
  for (const Bytes& b : pics) {
    dec.decode(b);
    take();
  }
  while (dec.flushDisplay()) take();
  return out;
}

TEST(BdecFlow, TwoStreamsInterleavedKeepTheirReferences) {
  const std::vector<Bytes> lightmap = gopPictures(testing::Content::kPan, 6, 2);
  const std::vector<Bytes> sky = gopPictures(testing::Content::kNoise, 4, 1, 7, 9);
  const std::vector<Shown> together = run({}, {}, {lightmap, sky});
  const std::vector<Shown> lightmapAlone = run({}, {}, {lightmap});
  const std::vector<Shown> skyAlone = run({}, {}, {sky});
  const std::vector<Rgba8Image> expectLightmap = expectedFrames(lightmap);
  ASSERT_EQ(together[0].frames.size(), lightmap.size());
  ASSERT_EQ(together[1].frames.size(), sky.size());
  for (std::size_t i = 0; i < lightmap.size(); ++i) {
    EXPECT_EQ(together[0].frames[i].pixels, lightmapAlone[0].frames[i].pixels) << i;
    EXPECT_EQ(together[0].frames[i].pixels, expectLightmap[i].pixels) << i;
    EXPECT_EQ(together[0].frames[i].width, 96);
  }
  for (std::size_t i = 0; i < sky.size(); ++i) EXPECT_EQ(together[1].frames[i].pixels, skyAlone[0].frames[i].pixels);
  // And the pictures really were P and B pictures, with no concealment.
  int predicted = 0;
  for (const TimedPicture& tp : together[0].results) {
    predicted += tp.report.pictureCodingType >= 2 ? 1 : 0;
    EXPECT_EQ(tp.report.macroblocksConcealed, 0);
  }
  EXPECT_GE(predicted, 4);
}

// IDEC cannot decode a P or B picture: the IDEC path refuses it (before, the shared decoder
// predicted it from whichever stream's frame it had decoded last) and the stream goes on.
Task<void> decodeAll(IpuUnit& unit, const std::vector<Bytes>* pics, std::vector<TimedPicture>* out) {
  for (const Bytes& b : *pics) {
    Rgba8Image img;
    out->push_back(co_await unit.decode(b, img));
  }
}

TEST(BdecFlow, ThePredictedPictureOfAnIdecStreamIsRefused) {
  const std::vector<Bytes> pics = gopPictures(testing::Content::kPan, 3, 0, 4);
  Scheduler s;
  IpuUnit unit(s, {});
  std::vector<TimedPicture> results;
  s.spawn("ee", decodeAll(unit, &pics, &results));
  s.run();
  ASSERT_EQ(results.size(), 4u);
  EXPECT_TRUE(results[0].report.produced);
  for (int i : {1, 2}) {
    EXPECT_FALSE(results[i].report.produced);
    EXPECT_TRUE(results[i].report.undecodable);
    ASSERT_EQ(results[i].report.issues.size(), 1u);
    EXPECT_EQ(results[i].report.issues[0].kind, IssueKind::kPredictedPictureOnIdec);
    EXPECT_EQ(results[i].finished, results[i].started);  // no IPU time
  }
  EXPECT_TRUE(results[3].report.produced);  // the next I picture
  EXPECT_EQ(results[3].commands.idec, results[3].idecCommands);
}

// Closed form with DMA never limiting (default rates, the input FIFO refilled far faster than
// commands read it): per pass of the loop the EE waits for the previous BDEC, parses, issues BDEC,
// predicts the macroblock before; BDEC takes idec_start + base + per bit x its bits, then 48 qwords
// out at one a cycle. The CSC of the display frame follows the EE's set-up.
Tick expectedDecodeEnd(const FlowPicture& f, const IpuParams& p, const EeFlowCosts& ee, Tick start) {
  const Tick vdec = fromEeCycles(ee.vdec_cycles) + p.vdec_cycles;
  const Tick fdec = fromEeCycles(ee.fdec_cycles) + p.fdec_cycles;
  Tick e = start + fromEeCycles(ee.fdec_cycles) * (1 + f.header.bclr + f.header.setiq) + fdec * f.header.fdec +
           p.bclr_cycles * (1 + f.header.bclr) + p.setiq_cycles * f.header.setiq;
  Tick bdecDone = e;
  const FlowMacroblock* prev = nullptr;
  for (const FlowMacroblock& m : f.macroblocks) {
    e = std::max(e, bdecDone);
    if (!m.skipped) {
      e += vdec * m.vdec + fdec * m.fdec + fromEeCycles(ee.mb_cycles) +
           (m.bdec ? fromEeCycles(ee.bdec_issue_cycles) : 0);
      if (m.bdec) bdecDone = e + p.idec_start_cycles + p.mb_base_cycles + p.mb_cycles_per_bit * m.blockBits + 48;
    }
    if (prev) e += mcCost(*prev, ee);
    prev = &m;
  }
  e = std::max(e, bdecDone);
  return prev ? e + mcCost(*prev, ee) : e;
}

TEST(BdecFlow, TicksFollowTheClosedForm) {
  const std::vector<Bytes> pics = gopPictures(testing::Content::kPan, 6, 2);
  const IpuParams p;
  const EeFlowCosts ee;
  const std::vector<Shown> shown = run(p, ee, {pics});
  Decoder dec(DecoderOptions{.recordMacroblocks = true});
  for (std::size_t i = 0; i < pics.size(); ++i) {
    const TimedPicture& tp = shown[0].results[i];
    dec.decode(pics[i]);
    const PictureHeader& ph = dec.picture();
    const FlowPicture f = buildFlow(pics[i], dec.macroblockTrace(), tp.report.pictureCodingType == 1,
                                    dec.sequence().mpeg2 && ph.pictureStructure == 3 && !ph.framePredFrameDct);
    EXPECT_EQ(tp.decodeEnd, expectedDecodeEnd(f, p, ee, tp.started)) << "picture " << i;
    std::int64_t bdec = 0;
    for (const FlowMacroblock& m : f.macroblocks) bdec += m.bdec ? 1 : 0;
    EXPECT_EQ(tp.commands.bdec, bdec);
    EXPECT_GT(tp.commands.vdec, 0);
    EXPECT_GT(tp.commands.fdec, 0);
    EXPECT_EQ(tp.commands.idec, 0);
    if (tp.displayed) {
      // CSC of 6 x 4 macroblocks from EE memory: 256 cycles each, then the last row's drain. Each
      // macroblock's 24 input qwords are read before it is converted: the first come in one a cycle;
      // for each later one 10 wait in the FIFO (in_fifo_qwords + in_buffer_qwords) and 13 more
      // arrive one a cycle after the first pop frees a slot (the one that frees it enters at once).
      const Tick input = 24 + 23 * (24 - (p.in_fifo_qwords + p.in_buffer_qwords) - 1);
      EXPECT_EQ(tp.finished, tp.decodeEnd + fromEeCycles(ee.csc_setup_cycles) + input + 24 * p.csc_cycles_per_mb + 4);
      EXPECT_EQ(tp.commands.csc, 1);
    } else {
      EXPECT_EQ(tp.finished, tp.decodeEnd);
      EXPECT_EQ(tp.commands.csc, 0);
    }
    EXPECT_GT(tp.eeBusy, 0);
  }
  // The first picture's sequence header loads the default matrices (SetDefQM twice: 4 SETIQ).
  EXPECT_EQ(shown[0].results[0].commands.setiq, 4);
  EXPECT_EQ(shown[0].results[0].commands.setvq, 0);
  EXPECT_FALSE(shown[0].results[0].displayed);  // the I frame waits for the next I or P frame
}

Tick totalDecodeEnd(const std::vector<Shown>& shown) {
  return shown[0].results.back().finished;
}

// Doubling the EE's prediction cost moves completion by exactly the added cycles when the EE is
// the bottleneck, and by almost nothing when BDEC is (the MC hides behind the next BDEC).
TEST(BdecFlow, EeCostMattersOnlyWhenTheEeIsTheBottleneck) {
  const std::vector<Bytes> pics = gopPictures(testing::Content::kNoise, 6, 2);
  EeFlowCosts ee;
  EeFlowCosts ee2 = ee;
  ee2.mc_cycles_per_prediction *= 2;
  // Predictions in the stream (coded and skipped macroblocks), from one run's flows.
  std::int64_t predictions = 0;
  std::int64_t skipped = 0;
  Decoder dec(DecoderOptions{.recordMacroblocks = true});
  for (const Bytes& b : pics) {
    const PictureReport r = dec.decode(b);
    for (const FlowMacroblock& m : buildFlow(b, dec.macroblockTrace(), r.pictureCodingType == 1, false).macroblocks) {
      predictions += m.predictions;
      skipped += m.skipped ? 1 : 0;
    }
  }
  ASSERT_GT(predictions, 100);
  const Tick perPrediction = fromEeCycles(ee2.mc_cycles_per_prediction) - fromEeCycles(ee.mc_cycles_per_prediction);

  IpuParams fast;  // BDEC far quicker than the EE's work
  fast.mb_base_cycles = 0;
  fast.mb_cycles_per_bit = 0;
  fast.idec_start_cycles = 0;
  const Tick eeBound = totalDecodeEnd(run(fast, ee2, {pics})) - totalDecodeEnd(run(fast, ee, {pics}));
  EXPECT_EQ(eeBound, predictions * perPrediction);

  IpuParams slow;  // BDEC far slower
  slow.mb_base_cycles = 20'000;
  const Tick ipuBound = totalDecodeEnd(run(slow, ee2, {pics})) - totalDecodeEnd(run(slow, ee, {pics}));
  EXPECT_GE(ipuBound, 0);
  // Only MC that no BDEC hides: each picture's last macroblock and skipped macroblocks.
  EXPECT_LE(ipuBound, (static_cast<std::int64_t>(pics.size()) + skipped) * 2 * perPrediction);
  EXPECT_LT(ipuBound * 10, eeBound);
}

// The EE predicts macroblock n while the IPU decodes n + 1: their spans overlap; the EE's track
// "ee" holds its busy time.
TEST(BdecFlow, TheEePredictsWhileTheIpuDecodesTheNextMacroblock) {
  const std::vector<Bytes> pics = gopPictures(testing::Content::kPan, 6, 2);
  Decoder dec(DecoderOptions{.recordMacroblocks = true});
  dec.decode(pics[0]);
  dec.decode(pics[1]);  // a P picture
  const FlowPicture f = buildFlow(pics[1], dec.macroblockTrace(), false, false);
  FlowTiming t;
  t.arrival = 1000;
  planFlow(f, {}, {}, DmaStalls{}, DmaStalls{}, t);
  Tick overlap = 0;
  for (const FlowSpan& mc : t.spans) {
    if (mc.track != 0 || std::string(mc.label) != "mc") continue;
    for (const FlowSpan& b : t.spans)
      if (b.track == 1) overlap += std::max<Tick>(0, std::min(mc.end, b.end) - std::max(mc.begin, b.begin));
  }
  EXPECT_GT(overlap, 0);
  Tick sum = 0;
  for (const FlowSpan& s : t.spans) sum += s.track == 0 ? s.end - s.begin : 0;
  EXPECT_EQ(sum, t.eeBusy);

  Tracer tracer;
  const std::vector<Shown> shown = run({}, {}, {pics}, &tracer);
  Tick eeBusy = 0;
  for (const TimedPicture& tp : shown[0].results) eeBusy += tp.eeBusy;
  // Tracks: "ipu" then "ee".
  EXPECT_EQ(tracer.busyTime(1, 0, shown[0].results.back().finished + 1), eeBusy);
}

// DMA stalls in the middle of P/B decode: completion moves later by at most the stall, the frames
// do not change.
Task<void> stallLater(Scheduler& s, IpuUnit& unit, Tick at, Tick duration, bool output) {
  co_await s.until(at);
  if (output) {
    unit.stallOutputDma(duration);
  } else {
    unit.stallInputDma(duration);
  }
}

TEST(BdecFlow, DmaStallsDuringPredictedPictures) {
  // Noise: pictures of many qwords, so the input FIFO is still being refilled mid-picture.
  const std::vector<Bytes> pics = gopPictures(testing::Content::kNoise, 6, 2);
  const std::vector<Shown> calm = run({}, {}, {pics});
  const Tick mid = (calm[0].results[2].started + calm[0].results[2].decodeEnd) / 2;  // inside a P or B picture
  ASSERT_GE(calm[0].results[2].report.pictureCodingType, 2);
  for (const bool output : {true, false}) {
    Scheduler s;
    IpuUnit unit(s, {});
    const std::vector<StreamId> ids{unit.openStream(DecodePath::kBdec)};
    std::vector<Shown> shown(1);
    const std::vector<std::vector<Bytes>> streams{pics};
    s.spawn("ee", decodeInterleaved(unit, ids, &streams, &shown));
    constexpr Tick kStall = 50'000;  // longer than the 10 qwords in the FIFO last
    s.spawn("fault", stallLater(s, unit, mid, kStall, output));
    s.run();
    const Tick moved = totalDecodeEnd(shown) - totalDecodeEnd(calm);
    EXPECT_GT(moved, 0) << (output ? "fromIPU" : "toIPU");
    EXPECT_LE(moved, kStall);
    ASSERT_EQ(shown[0].frames.size(), calm[0].frames.size());
    for (std::size_t i = 0; i < shown[0].frames.size(); ++i)
      EXPECT_EQ(shown[0].frames[i].pixels, calm[0].frames[i].pixels);
    if (output) {
      EXPECT_GT(shown[0].results[2].outputStalls, 0);
    }
  }
}

}  // namespace
}  // namespace vbim::ipu
