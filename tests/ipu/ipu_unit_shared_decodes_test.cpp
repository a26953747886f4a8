// Two IPUs sharing their decodes (ipu/ipu_unit_shared_decodes.hpp, issue #31) give each caller
// the same pictures, reports and ticks as two IPUs that decode everything themselves: when one
// side is late, drops pictures, is given damaged bytes or pictures without a sequence header of
// their own (so the decoder's past matters), and when the log's limit makes the side ahead keep
// its decodes, and when the side that went its own way is first at every tick. The sharing must take
// place where it can.
#include "ipu/ipu_unit_shared_decodes.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ipu/ipu_unit.hpp"
#include "ipu/start_code.hpp"
#include "tests/ipu/support/libav_mpeg.hpp"

namespace vbim::ipu {
namespace {

using Bytes = std::vector<std::uint8_t>;

struct Step {
  Bytes bytes;
  Tick at = 0;  // decoded at this tick or as soon as the IPU is free after it
};

struct Decoded {
  TimedPicture timed;
  Rgba8Image image;
};

struct Outcome {
  std::vector<Decoded> a, b;
  SharedDecodes::Counters counters;
  std::size_t held = 0;  // entries the log still holds at the end
};

// A picture's image is kept when it was displayed (always, on the IDEC path, when it was decoded).
Task<void> feed(Scheduler& s, IpuUnit& unit, StreamId stream, const std::vector<Step>& steps,
                std::vector<Decoded>& out) {
  for (const Step& step : steps) {
    if (s.now() < step.at) co_await s.until(step.at);
    auto image = std::make_shared<Rgba8Image>();
    Decoded d;
    d.timed = co_await unit.decode(stream, step.bytes, image);
    if (d.timed.displayed) d.image = *image;
    out.push_back(std::move(d));
  }
}

struct PlayOptions {
  std::size_t maxAhead = 64;
  // Side a's IPU and feeder in the scheduler's first lane, so that at any tick both share a is
  // first (the player's reference and run); else in spawn order as their work leaves them.
  bool aFirst = false;
  // The BDEC flow: each IPU's own kBdec stream, shared through a log of its own (DecoderState::Kept).
  bool flow = false;
  bool aRecordsCommands = false;  // side a's IPU logs its commands (recordCommands)
};

Outcome play(const std::vector<Step>& a, const std::vector<Step>& b, bool share, const PlayOptions& opt = {}) {
  Scheduler s;
  std::optional<Scheduler::LaneScope> lane;
  if (opt.aFirst) lane.emplace(s, Lane::First);
  IpuUnit ua(s, IpuParams{});
  lane.reset();
  IpuUnit ub(s, IpuParams{});
  const StreamId sa = opt.flow ? ua.openStream(DecodePath::kBdec) : kSharedIdecStream;
  const StreamId sb = opt.flow ? ub.openStream(DecodePath::kBdec) : kSharedIdecStream;
  SharedDecodes shared(opt.maxAhead, SharedDecodes::kDefaultMaxImageBytes,
                       opt.flow ? DecoderState::Kept : DecoderState::FreshPerPicture);
  if (share && opt.flow) {
    ua.shareFlowDecodes(sa, shared, 0);
    ub.shareFlowDecodes(sb, shared, 1);
  } else if (share) {
    ua.shareDecodes(shared, 0);
    ub.shareDecodes(shared, 1);
  }
  if (opt.aRecordsCommands) ua.recordCommands();
  Outcome o;
  if (opt.aFirst) lane.emplace(s, Lane::First);
  s.spawn("a", feed(s, ua, sa, a, o.a));
  lane.reset();
  s.spawn("b", feed(s, ub, sb, b, o.b));
  s.run();
  o.counters = shared.counters();
  o.held = shared.held();
  return o;
}

void expectSame(const std::vector<Decoded>& got, const std::vector<Decoded>& want, const char* side) {
  ASSERT_EQ(got.size(), want.size()) << side;
  for (std::size_t i = 0; i < want.size(); ++i) {
    const TimedPicture& g = got[i].timed;
    const TimedPicture& w = want[i].timed;
    SCOPED_TRACE(std::string(side) + " picture " + std::to_string(i));
    EXPECT_EQ(g.report.produced, w.report.produced);
    EXPECT_EQ(g.report.undecodable, w.report.undecodable);
    EXPECT_EQ(g.report.macroblocksDecoded, w.report.macroblocksDecoded);
    EXPECT_EQ(g.report.macroblocksConcealed, w.report.macroblocksConcealed);
    EXPECT_EQ(g.report.issueCount, w.report.issueCount);
    EXPECT_EQ(g.report.describe(), w.report.describe());
    EXPECT_EQ(g.started, w.started);
    EXPECT_EQ(g.finished, w.finished);
    EXPECT_EQ(g.idecCommands, w.idecCommands);
    EXPECT_EQ(g.outputQwords, w.outputQwords);
    EXPECT_EQ(g.displayed, w.displayed);
    EXPECT_EQ(got[i].image.width, want[i].image.width);
    EXPECT_EQ(got[i].image.height, want[i].image.height);
    EXPECT_TRUE(got[i].image.pixels == want[i].image.pixels);
  }
}

// Plays both ways and compares; returns the shared play's counters.
SharedDecodes::Counters expectSameAsUnshared(const std::vector<Step>& a, const std::vector<Step>& b,
                                             std::size_t maxAhead = 64, bool aFirst = false) {
  const PlayOptions opt{.maxAhead = maxAhead, .aFirst = aFirst};
  const Outcome own = play(a, b, false, opt);
  const Outcome shared = play(a, b, true, opt);
  expectSame(shared.a, own.a, "side 0");
  expectSame(shared.b, own.b, "side 1");
  EXPECT_EQ(own.counters.decoded + own.counters.taken, 0);
  EXPECT_EQ(shared.counters.decoded + shared.counters.taken, static_cast<std::int64_t>(a.size() + b.size()));
  return shared.counters;
}

std::vector<Bytes> pictures(int width, int height, int frames, testing::Content content) {
  testing::EncodeOptions o;
  o.width = width;
  o.height = height;
  o.frames = frames;
  o.quantiser = 4;
  o.content = content;
  return testing::encodePictures(o);
}

// The picture without its sequence header (and extension): the decoder keeps the one it read last.
Bytes withoutSequenceHeader(const Bytes& b) {
  std::size_t pos = findStartCode(b.data(), b.size(), 0);
  while (pos + 3 < b.size() && (b[pos + 3] == 0xB3 || b[pos + 3] == 0xB5)) {
    pos = findStartCode(b.data(), b.size(), pos + 4);
  }
  return Bytes(b.begin() + static_cast<std::ptrdiff_t>(pos), b.end());
}

// Flips bits in the middle of the picture's slice data.
Bytes damaged(Bytes b) {
  for (std::size_t i = b.size() / 2; i < b.size() / 2 + 24 && i < b.size(); i += 3) b[i] ^= 0x5A;
  return b;
}

std::vector<Step> steps(const std::vector<Bytes>& pics, Tick start, Tick every) {
  std::vector<Step> out;
  for (std::size_t i = 0; i < pics.size(); ++i) out.push_back(Step{pics[i], start + static_cast<Tick>(i) * every});
  return out;
}

constexpr Tick kEvery = fromMs(5);

TEST(SharedDecodes, StartsWithSequenceHeader) {
  const std::vector<Bytes> pics = pictures(64, 48, 1, testing::Content::kBusy);
  EXPECT_TRUE(startsWithSequenceHeader(pics[0]));
  EXPECT_FALSE(startsWithSequenceHeader(withoutSequenceHeader(pics[0])));
  Bytes broken = pics[0];
  broken.resize(6);  // the header cut short does not parse
  EXPECT_FALSE(startsWithSequenceHeader(broken));
  EXPECT_FALSE(startsWithSequenceHeader({}));
}

TEST(SharedDecodes, ALateSideTakesEveryPictureOfTheOther) {
  const std::vector<Bytes> pics = pictures(64, 48, 10, testing::Content::kBusy);
  const SharedDecodes::Counters c = expectSameAsUnshared(steps(pics, 0, kEvery), steps(pics, fromMs(23), kEvery));
  EXPECT_EQ(c.decoded, 10);
  EXPECT_EQ(c.taken, 10);
  EXPECT_EQ(c.divergences, 0);
}

TEST(SharedDecodes, SidesThatOvertakeEachOtherTakeTurns) {
  const std::vector<Bytes> pics = pictures(72, 40, 12, testing::Content::kLightmap);  // cropped macroblocks
  std::vector<Step> a = steps(pics, 0, kEvery);
  std::vector<Step> b = steps(pics, fromMs(12), kEvery);
  for (std::size_t i = 6; i < a.size(); ++i) a[i].at += fromMs(40);  // a stalls: b leads from picture 6
  const SharedDecodes::Counters c = expectSameAsUnshared(a, b);
  EXPECT_EQ(c.decoded, 12);
  EXPECT_EQ(c.taken, 12);
}

TEST(SharedDecodes, ASideThatDropsOrIsGivenDamagedPicturesPicksUpAgain) {
  const std::vector<Bytes> pics = pictures(64, 48, 12, testing::Content::kNoise);
  std::vector<Bytes> late = pics;
  late[3] = damaged(late[3]);
  late.erase(late.begin() + 7);  // dropped, as a hard-skip run drops a late picture
  const SharedDecodes::Counters c = expectSameAsUnshared(steps(pics, 0, kEvery), steps(late, fromMs(31), kEvery));
  // The damaged picture is its own; the next one and the one after the gap are found further on.
  EXPECT_EQ(c.divergences, 1);
  EXPECT_EQ(c.rejoined, 2);
  EXPECT_EQ(c.taken, 10);
}

TEST(SharedDecodes, PicturesWithoutTheirOwnSequenceHeaderAreDecodedAgainBeforeADivergence) {
  std::vector<Bytes> pics = pictures(64, 48, 10, testing::Content::kBusy);
  for (std::size_t i = 1; i < pics.size(); ++i) pics[i] = withoutSequenceHeader(pics[i]);
  std::vector<Bytes> late = pics;
  late[6] = damaged(late[6]);
  const SharedDecodes::Counters c = expectSameAsUnshared(steps(pics, 0, kEvery), steps(late, fromMs(17), kEvery));
  EXPECT_EQ(c.divergences, 1);
  EXPECT_EQ(c.taken, 6);
  EXPECT_EQ(c.replayed, 6) << "the late side's decoder must read pictures 0-5 before it decodes picture 6";
}

TEST(SharedDecodes, AStaleDecoderNeverHasMoreThanTheLimitToReadAgain) {
  std::vector<Bytes> pics = pictures(64, 48, 12, testing::Content::kBusy);
  for (std::size_t i = 1; i < pics.size(); ++i) pics[i] = withoutSequenceHeader(pics[i]);
  const SharedDecodes::Counters c =
      expectSameAsUnshared(steps(pics, 0, kEvery), steps(pics, fromMs(7), kEvery), /*maxAhead=*/4);
  EXPECT_EQ(c.taken, 4);
  EXPECT_EQ(c.replayed, 4) << "the late side reads pictures 0-3 again, then decodes the rest itself";
}

// Side 0 is first at every tick it shares with side 1 (as the player's reference, in the scheduler's
// first lane, is with the run). Side 1 once decodes two pictures in the other order, the second of
// them ahead of side 0: side 0 does not find its next picture where the log has side 1's and goes its
// own way, and from then on, level with side 1 but always first, it looks for each picture before
// side 1 has decoded it. It picks up again only by offering its own fresh starts, which side 1 takes.
TEST(SharedDecodes, ASideFirstAtEveryTickThatWentItsOwnWayOffersItsFreshStartsAgain) {
  const std::vector<Bytes> pics = pictures(64, 48, 12, testing::Content::kBusy);
  const std::vector<Step> first = steps(pics, 0, kEvery);
  std::vector<Step> second = steps(pics, 0, kEvery);
  std::swap(second[2], second[3]);
  second[2].at = fromMs(7);   // picture 3, ahead of side 0's picture 2
  second[3].at = fromMs(12);  // picture 2
  const SharedDecodes::Counters c = expectSameAsUnshared(first, second, 64, /*aFirst=*/true);
  EXPECT_GE(c.offeredAgain, 1);
  // Side 1 takes pictures 0-1 and 5-11, side 0 takes picture 3 (found ahead); 2 and 4 are decoded
  // by both. Without the offers side 0 would take nothing after picture 3, nor side 1 after 1.
  EXPECT_EQ(c.taken, 10) << "decoded " << c.decoded << ", divergences " << c.divergences << ", rejoined " << c.rejoined
                         << ", offered again " << c.offeredAgain;
}

TEST(SharedDecodes, TheSideAheadKeepsItsDecodesPastTheLimit) {
  const std::vector<Bytes> pics = pictures(64, 48, 12, testing::Content::kSmooth);
  const SharedDecodes::Counters c =
      expectSameAsUnshared(steps(pics, 0, kEvery), steps(pics, fromMs(200), kEvery), /*maxAhead=*/4);
  EXPECT_GT(c.heldBack, 0);
  EXPECT_EQ(c.taken, 4);
}

// The BDEC flow (P and B pictures): the same harness on each IPU's own kBdec stream.
// The shared play's counters and the entries its log holds at the end.
std::pair<SharedDecodes::Counters, std::size_t> expectFlowSameAsUnsharedHeld(const std::vector<Step>& a,
                                                                             const std::vector<Step>& b,
                                                                             std::size_t maxAhead = 64,
                                                                             bool aRecordsCommands = false) {
  const PlayOptions opt{.maxAhead = maxAhead, .flow = true, .aRecordsCommands = aRecordsCommands};
  const Outcome own = play(a, b, false, opt);
  const Outcome shared = play(a, b, true, opt);
  expectSame(shared.a, own.a, "side 0");
  expectSame(shared.b, own.b, "side 1");
  EXPECT_EQ(own.counters.decoded + own.counters.taken, 0);
  int displayed = 0;
  for (const Decoded& d : own.a) displayed += d.timed.displayed ? 1 : 0;
  EXPECT_GT(displayed, static_cast<int>(a.size()) / 2) << "most pictures should show a frame";
  return {shared.counters, shared.held};
}

SharedDecodes::Counters expectFlowSameAsUnshared(const std::vector<Step>& a, const std::vector<Step>& b,
                                                 std::size_t maxAhead = 64, bool aRecordsCommands = false) {
  return expectFlowSameAsUnsharedHeld(a, b, maxAhead, aRecordsCommands).first;
}

// GOPs of 6 with 2 B pictures, in stream (decode) order.
std::vector<Bytes> gopPictures(int frames, testing::Content content = testing::Content::kBusy) {
  testing::EncodeOptions o;
  o.width = 64;
  o.height = 48;
  o.frames = frames;
  o.gopSize = 6;
  o.bFrames = 2;
  o.quantiser = 4;
  o.content = content;
  return testing::encodePictures(o);
}

TEST(SharedFlowDecodes, ALateSideTakesEveryPictureOfTheOther) {
  const std::vector<Bytes> pics = gopPictures(14);
  const SharedDecodes::Counters c = expectFlowSameAsUnshared(steps(pics, 0, kEvery), steps(pics, fromMs(23), kEvery));
  EXPECT_EQ(c.decoded, 14);
  EXPECT_EQ(c.taken, 14);
  EXPECT_EQ(c.replayed, 0);
}

// The side that took a's decodes leads after a stalls: its decoder takes a's state (the two are
// level), never decoding a picture twice.
TEST(SharedFlowDecodes, SidesThatOvertakeEachOtherTakeTurnsByTakingTheOthersState) {
  const std::vector<Bytes> pics = gopPictures(16, testing::Content::kLightmap);
  std::vector<Step> a = steps(pics, 0, kEvery);
  std::vector<Step> b = steps(pics, fromMs(12), kEvery);
  for (std::size_t i = 7; i < a.size(); ++i) a[i].at += fromMs(40);  // a stalls: b leads from picture 7
  const SharedDecodes::Counters c = expectFlowSameAsUnshared(a, b);
  EXPECT_EQ(c.decoded, 16);
  EXPECT_EQ(c.taken, 16);
  EXPECT_GE(c.statesCopied, 1);
  EXPECT_EQ(c.replayed, 0);
}

// A late side given a damaged P picture goes its own way: its decoder, stale since the start, reads
// the pictures before it again first (the other's state is further on).
TEST(SharedFlowDecodes, ALateSideGivenADamagedPictureDecodesThePastAgainAndGoesItsOwnWay) {
  const std::vector<Bytes> pics = gopPictures(14, testing::Content::kNoise);
  std::vector<Bytes> late = pics;
  late[6] = damaged(late[6]);
  const auto [c, held] = expectFlowSameAsUnsharedHeld(steps(pics, 0, kEvery), steps(late, fromMs(31), kEvery));
  EXPECT_EQ(c.divergences, 1);
  EXPECT_EQ(c.taken, 6);
  EXPECT_EQ(c.replayed, 6) << "the late side's decoder must read pictures 0-5 before it decodes picture 6";
  EXPECT_EQ(c.decoded, 14 + 8) << "no rejoining in the BDEC flow: its references carry the past";
  EXPECT_EQ(held, 0u) << "no one can take what the log would hold: it must not keep it (nor its images)";
}

// With a short log the late side takes at most the limit while its decoder is stale; level with the
// other at the limit's half, it takes the other's state instead of growing the replay.
TEST(SharedFlowDecodes, AStaleDecoderTakesTheOthersStateBeforeTheLimit) {
  const std::vector<Bytes> pics = gopPictures(14);
  std::vector<Step> a = steps(pics, 0, kEvery);
  std::vector<Step> b = steps(pics, 0, kEvery);
  for (Step& st : b) st.at += 1;  // one tick behind: level after each take
  const SharedDecodes::Counters c = expectFlowSameAsUnshared(a, b, /*maxAhead=*/4);
  EXPECT_EQ(c.taken, 14);
  EXPECT_GE(c.statesCopied, 3);
  EXPECT_EQ(c.replayed, 0);
}

// A side three pictures behind is never level with the other, so its decoder, stale, must not take
// the other's state (three pictures further on): when it meets a damaged picture it reads the past
// again from its own.
TEST(SharedFlowDecodes, ALaggingSideNeverTakesTheStateOfASideAheadOfIt) {
  const std::vector<Bytes> pics = gopPictures(14, testing::Content::kNoise);
  std::vector<Bytes> late = pics;
  late[9] = damaged(late[9]);
  const SharedDecodes::Counters c =
      expectFlowSameAsUnshared(steps(pics, 0, kEvery), steps(late, 3 * kEvery + 1, kEvery), /*maxAhead=*/8);
  EXPECT_EQ(c.statesCopied, 0);
  EXPECT_EQ(c.taken, 8) << "taken until its decoder is the limit behind";
  EXPECT_GE(c.replayed, 1);
}

TEST(SharedFlowDecodes, AnIpuThatLogsItsCommandsSharesNothing) {
  const std::vector<Bytes> pics = gopPictures(8);
  const SharedDecodes::Counters c =
      expectFlowSameAsUnshared(steps(pics, 0, kEvery), steps(pics, fromMs(9), kEvery), 64, /*aRecordsCommands=*/true);
  EXPECT_EQ(c.taken, 0);
  EXPECT_EQ(c.decoded, 8) << "side 1 decodes all 8 itself; side 0 left the log before its first";
}

}  // namespace
}  // namespace vbim::ipu
