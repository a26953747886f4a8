// Bad input gives a GsError (or, from inside the running process, the scheduler's error that wraps
// it) whose message says what was given and what was expected.
#include <gtest/gtest.h>

#include "gs/error.hpp"
#include "presenter_fixture.hpp"

namespace vbim::gs {
namespace {

using namespace test;

template <class Fn>
std::string errorOf(Fn&& fn) {
  try {
    fn();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no error)";
}

ScriptedFrameSource source(std::vector<StreamInfo> s = {stream("clear"), stream("rain")}) {
  return ScriptedFrameSource(std::move(s), wave, SourceScript{});
}

TEST(BadInput, FixOutsideTheRegister) {
  Scheduler s;
  auto src = source();
  for (std::int64_t fix : {-1LL, 256LL}) {
    GsParams p;
    p.fix = fix;
    EXPECT_NE(errorOf([&] { Presenter pr(s, src, p); }).find("outside 0..255"), std::string::npos);
    GsParams q;
    q.catchup_fix = fix;
    EXPECT_NE(errorOf([&] { Presenter pr(s, src, q); }).find("outside 0..255"), std::string::npos);
  }
}

TEST(BadInput, FrameOfTheWrongSize) {
  Scheduler s;
  // The stream says 128x64; its frames are 64x64.
  ScriptedFrameSource src(
      {stream("clear")}, [](int v, std::int64_t k) { return waveSized(v, k, 64, 64); }, SourceScript{});
  Presenter pr(s, src, GsParams{});
  s.spawn("gs", pr.run(fromMs(100)));
  const std::string msg = errorOf([&] { s.run(); });
  EXPECT_NE(msg.find("frame seq 0 of stream 0 'clear' is 64x64 but the lightmap is 128x64"), std::string::npos) << msg;
}

TEST(BadInput, BranchToAStreamThatDoesNotExist) {
  Scheduler s;
  auto src = source();
  Presenter pr(s, src, GsParams{});
  const std::string msg = errorOf([&] { pr.scheduleBranch(fromMs(10), 2); });
  EXPECT_NE(msg.find("branch to stream 2, which does not exist"), std::string::npos) << msg;
  EXPECT_NE(msg.find("0 'clear', 1 'rain'"), std::string::npos) << msg;
  EXPECT_NE(errorOf([&] { pr.scheduleBranch(fromMs(10), -1); }).find("does not exist"), std::string::npos);
  EXPECT_NE(errorOf([&] { src.branch(5, 0, 0); }).find("branch to stream 5"), std::string::npos);
}

TEST(BadInput, VariantsThatCannotBranchAtTheSameTimeOfDay) {
  Scheduler s;
  auto src = source({stream("clear"), stream("rain", 300, 64, 64)});
  const std::string msg = errorOf([&] { Presenter pr(s, src, GsParams{}); });
  EXPECT_NE(msg.find("stream 1 'rain' (64x64"), std::string::npos) << msg;
}

TEST(BadInput, SettingsOutsideTheirChoices) {
  Scheduler s;
  auto src = source();
  GsParams a;
  a.strip_rows = 48;
  a.upload_mode = "strips";
  EXPECT_NE(errorOf([&] { Presenter pr(s, src, a); }).find("multiple of 32"), std::string::npos);
  GsParams b;
  b.catchup = "rewind";
  EXPECT_NE(errorOf([&] { Presenter pr(s, src, b); }).find("unknown catch-up policy 'rewind'"), std::string::npos);
  GsParams c;
  c.video = "secam";
  EXPECT_NE(errorOf([&] { Presenter pr(s, src, c); }).find("unknown video mode 'secam'"), std::string::npos);
}

// The sky presenter draws in the console's plan (the lightmap presenter's): planned with room for
// its stream.
TEST(BadInput, SkyPresenterWithoutARoomForItsStream) {
  Scheduler s;
  auto src = source({stream("sky")});  // 128x64
  PresenterOptions o;
  const VramLayout noSky = planVram(GsParams{}, 256, 256);
  o.console = &noSky;
  EXPECT_NE(errorOf([&] { Presenter pr(s, src, GsParams{}, o); }).find("no sky staging area"), std::string::npos);
  const VramLayout smallerSky = planVram(GsParams{}, 256, 256, SkyTexture{64, 64});
  o.console = &smallerSky;
  const std::string msg = errorOf([&] { Presenter pr(s, src, GsParams{}, o); });
  EXPECT_NE(msg.find("128x64 sky picture does not fit the layout's sky (256x256) and sky staging (64x64)"),
            std::string::npos)
      << msg;
  const VramLayout console = planVram(GsParams{}, 256, 256, SkyTexture{128, 64});
  o.console = &console;
  Presenter pr(s, src, GsParams{}, o);
  EXPECT_EQ(pr.vram().region("sky staging").firstPage, console.region("sky staging").firstPage);
  GsParams small;
  small.sky_width = 64;  // the stream no longer fits the sky texture gs.sky_width x gs.sky_height names
  EXPECT_NE(errorOf([&] { Presenter p2(s, src, small, o); }).find("gs.sky_width"), std::string::npos);
}

TEST(BadInput, LightmapThatDoesNotFitVram) {
  Scheduler s;
  auto src = source({stream("huge", 10, 1024, 1024)});
  const std::string msg = errorOf([&] { Presenter pr(s, src, GsParams{}); });
  EXPECT_NE(msg.find("VRAM layout does not fit"), std::string::npos) << msg;
}

}  // namespace
}  // namespace vbim::gs
