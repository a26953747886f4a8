// The IPU timing's shortcuts against its own qword-by-qword steps (issue #29, item 6: the 512x512
// GOP play's CPU): a CSC command from EE memory whose macroblocks repeat once the FIFOs reach a
// steady state (IpuTimeline::plan), and BDEC output that fromIPU drains as fast as it comes
// (planFlow). Every time, count and FIFO state must be what stepping gives, with DMA stall windows
// before, inside and after the command and with parameters that disable each shortcut.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "ipu/bdec_flow.hpp"
#include "ipu/bdec_flow_timing.hpp"
#include "ipu/ipu_unit_timing.hpp"
#include "ipu/picture_decoder.hpp"
#include "tests/ipu/support/libav_mpeg.hpp"

namespace vbim::ipu {
namespace {

// A CSC command of `mbs` macroblocks from EE memory, as IpuUnit stages the BDEC flow's display frame.
CommandTiming cscCommand(std::size_t mbs, Tick arrival, int qwordsPerRow) {
  CommandTiming c;
  c.arrival = arrival;
  c.csc = true;
  c.qwordsPerRow = qwordsPerRow;
  c.bits.assign(mbs, 0);
  c.restart.assign(mbs, 0);
  c.needQwords.resize(mbs);
  for (std::size_t i = 0; i < mbs; ++i) c.needQwords[i] = static_cast<std::uint32_t>(i + 1) * 24;
  c.inQwords = static_cast<std::uint32_t>(mbs) * 24;
  return c;
}

void expectSamePlan(const CommandTiming& a, const CommandTiming& b) {
  EXPECT_EQ(a.mbBegin, b.mbBegin);
  EXPECT_EQ(a.mbDecoded, b.mbDecoded);
  EXPECT_EQ(a.mbEnd, b.mbEnd);
  ASSERT_EQ(a.rowStalls.size(), b.rowStalls.size());
  for (std::size_t i = 0; i < a.rowStalls.size(); ++i) {
    EXPECT_EQ(a.rowStalls[i].mb, b.rowStalls[i].mb);
    EXPECT_EQ(a.rowStalls[i].ready, b.rowStalls[i].ready);
    EXPECT_EQ(a.rowStalls[i].end, b.rowStalls[i].end);
  }
  EXPECT_EQ(a.stalls, b.stalls);
  EXPECT_EQ(a.lastResume, b.lastResume);
  EXPECT_EQ(a.finished, b.finished);
  EXPECT_EQ(a.quietAfter, b.quietAfter);
}

void expectSameState(const IpuTimeline::State& a, const IpuTimeline::State& b) {
  EXPECT_EQ(a.toIpuFree, b.toIpuFree);
  EXPECT_EQ(a.coreFree, b.coreFree);
  EXPECT_EQ(a.fromIpuFree, b.fromIpuFree);
  EXPECT_EQ(a.inCount, b.inCount);
  EXPECT_EQ(a.outCount, b.outCount);
  EXPECT_EQ(a.inPops, b.inPops);
  EXPECT_EQ(a.outTakes, b.outTakes);
}

struct StallAt {
  bool output;
  Tick from;
  Tick duration;
};

// Plans two CSC commands (the second right after the first, so it starts from the first's FIFO
// state) with the shortcut (no qword log) and stepped (qword log), and compares everything.
void expectCscShortcutExact(const IpuParams& p, std::size_t mbs, int qwordsPerRow, const std::vector<StallAt>& stalls,
                            const std::string& what) {
  SCOPED_TRACE(what);
  DmaStalls in;
  DmaStalls out;
  for (const StallAt& s : stalls) (s.output ? out : in).add(s.from, s.duration);
  IpuTimeline fast(p);
  IpuTimeline stepped(p);
  Tick arrival = 1'000;
  for (int command = 0; command < 2; ++command) {
    CommandTiming a = cscCommand(mbs, arrival, qwordsPerRow);
    CommandTiming b = a;
    fast.plan(a, in, out, false);
    stepped.plan(b, in, out, true);
    expectSamePlan(a, b);
    expectSameState(fast.state(), stepped.state());
    arrival = a.finished / 2;  // arrives while the first is still in the FIFOs
  }
}

TEST(IpuTimingShortcuts, CscCommandsRepeatTheirSteadyStateExactly) {
  const IpuParams defaults;
  // Without stalls: the 512x512 lightmap's and the 256x128 sky's frames, and small ones.
  for (const std::size_t mbs :
       {std::size_t{1}, std::size_t{2}, std::size_t{3}, std::size_t{24}, std::size_t{128}, std::size_t{1024}}) {
    expectCscShortcutExact(defaults, mbs, kQwordsPerRow, {}, "no stall, " + std::to_string(mbs) + " macroblocks");
    expectCscShortcutExact(defaults, mbs, kQwordsPerRow16, {}, "RGB16, " + std::to_string(mbs) + " macroblocks");
  }
  // A 1,024-macroblock command takes about 1024 * 270 ticks from t = 1,000: stalls before it,
  // inside it (early, middle, at its end) and after it, on either channel, short and long.
  for (const bool output : {false, true}) {
    for (const Tick from :
         {Tick{10}, Tick{900}, Tick{5'000}, Tick{140'000}, Tick{275'000}, Tick{400'000}, Tick{2'000'000}}) {
      for (const Tick duration : {Tick{3}, Tick{700}, Tick{60'000}}) {
        expectCscShortcutExact(defaults, 1024, kQwordsPerRow, {{output, from, duration}},
                               std::string(output ? "fromIPU" : "toIPU") + " stall at " + std::to_string(from) +
                                   " for " + std::to_string(duration));
      }
    }
  }
  expectCscShortcutExact(defaults, 1024, kQwordsPerRow, {{false, 50'000, 100}, {true, 50'050, 5'000}}, "both channels");
  // Parameters where the FIFOs settle differently or where the drain stretch does not apply.
  IpuParams shallow = defaults;
  shallow.in_fifo_qwords = 1;
  shallow.in_buffer_qwords = 0;
  expectCscShortcutExact(shallow, 300, kQwordsPerRow, {}, "one-qword input FIFO");
  IpuParams slowIn = defaults;
  slowIn.toipu_cycles_per_qword = 20;  // input slower than CSC: the input sets the pace
  expectCscShortcutExact(slowIn, 300, kQwordsPerRow, {}, "slow toIPU");
  expectCscShortcutExact(slowIn, 300, kQwordsPerRow, {{false, 30'000, 500}}, "slow toIPU, stalled");
  IpuParams slowOut = defaults;
  slowOut.fromipu_cycles_per_qword = 5;  // no drain stretch: every qword stepped either way
  expectCscShortcutExact(slowOut, 300, kQwordsPerRow, {}, "slow fromIPU");
  IpuParams fastCsc = defaults;
  fastCsc.csc_cycles_per_mb = 16;
  expectCscShortcutExact(fastCsc, 300, kQwordsPerRow, {}, "fast CSC");
}

// planFlow with and without the output shortcut, on real P and B pictures.
void expectFlowShortcutExact(const FlowPicture& f, const IpuParams& p, const DmaStalls& in, const DmaStalls& out,
                             Tick arrival) {
  FlowTiming a;
  a.arrival = arrival;
  a.recordCommands = true;
  FlowTiming b = a;
  b.stepEveryQword = true;
  planFlow(f, p, EeFlowCosts{}, in, out, a);
  planFlow(f, p, EeFlowCosts{}, in, out, b);
  EXPECT_EQ(a.decodeEnd, b.decodeEnd);
  EXPECT_EQ(a.inFree, b.inFree);
  EXPECT_EQ(a.ipuFree, b.ipuFree);
  EXPECT_EQ(a.fromFree, b.fromFree);
  EXPECT_EQ(a.eeBusy, b.eeBusy);
  EXPECT_EQ(a.eeWait, b.eeWait);
  EXPECT_EQ(a.ipuBusy, b.ipuBusy);
  EXPECT_EQ(a.outputStalls, b.outputStalls);
  ASSERT_EQ(a.spans.size(), b.spans.size());
  for (std::size_t i = 0; i < a.spans.size(); ++i) {
    EXPECT_EQ(a.spans[i].begin, b.spans[i].begin);
    EXPECT_EQ(a.spans[i].end, b.spans[i].end);
    EXPECT_EQ(a.spans[i].track, b.spans[i].track);
  }
  ASSERT_EQ(a.commands.size(), b.commands.size());
  for (std::size_t i = 0; i < a.commands.size(); ++i) {
    EXPECT_EQ(a.commands[i].word, b.commands[i].word);
    EXPECT_EQ(a.commands[i].begin, b.commands[i].begin);
    EXPECT_EQ(a.commands[i].end, b.commands[i].end);
  }
}

TEST(IpuTimingShortcuts, BdecOutputDrainedAsItComesIsExact) {
  testing::EncodeOptions o;
  o.width = 96;
  o.height = 64;
  o.frames = 7;
  o.gopSize = 6;
  o.bFrames = 2;
  o.quantiser = 4;
  o.content = testing::Content::kNoise;
  const std::vector<std::vector<std::uint8_t>> pics = testing::encodePictures(o);
  Decoder dec(DecoderOptions{.recordMacroblocks = true});
  std::vector<FlowPicture> flows;
  for (const auto& b : pics) {
    const PictureReport r = dec.decode(b);
    flows.push_back(buildFlow(b, dec.macroblockTrace(), r.pictureCodingType == 1, false));
  }
  const IpuParams defaults;
  IpuParams quickBdec = defaults;  // BDEC far quicker than the EE: its output waits on fromIPU more often
  quickBdec.mb_base_cycles = 0;
  quickBdec.mb_cycles_per_bit = 0;
  quickBdec.idec_start_cycles = 0;
  IpuParams zeroPeriod = defaults;
  zeroPeriod.fromipu_cycles_per_qword = 0;
  IpuParams slowOut = defaults;
  slowOut.fromipu_cycles_per_qword = 2;  // no shortcut: both step
  IpuParams deepOut = defaults;
  deepOut.out_fifo_qwords = 60;  // a ring deeper than BDEC's 48 qwords
  IpuParams shallowOut = defaults;
  shallowOut.out_fifo_qwords = 1;
  for (std::size_t k = 0; k < flows.size(); ++k) {
    SCOPED_TRACE("picture " + std::to_string(k));
    for (const IpuParams& p : {defaults, quickBdec, zeroPeriod, slowOut, deepOut, shallowOut}) {
      expectFlowShortcutExact(flows[k], p, DmaStalls{}, DmaStalls{}, 1'000);
      // fromIPU stalls at a few points of the picture, short and long.
      FlowTiming calm;
      calm.arrival = 1'000;
      planFlow(flows[k], p, EeFlowCosts{}, DmaStalls{}, DmaStalls{}, calm);
      for (const Tick at : {calm.arrival + 10, (calm.arrival + calm.decodeEnd) / 2, calm.decodeEnd - 50}) {
        for (const Tick duration : {Tick{2}, Tick{40}, Tick{5'000}}) {
          DmaStalls out;
          out.add(at, duration);
          expectFlowShortcutExact(flows[k], p, DmaStalls{}, out, 1'000);
          DmaStalls in;
          in.add(at, duration);
          expectFlowShortcutExact(flows[k], p, in, DmaStalls{}, 1'000);
        }
      }
    }
  }
}

}  // namespace
}  // namespace vbim::ipu
