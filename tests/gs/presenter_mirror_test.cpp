// A mirroring reference (Presenter::followTwin, issue #31) whose run does its GS work of every vsync
// some strips later: the run's sky shares its GS and draws first, so each lightmap strip the
// reference asks for is blended by the run only after the reference asked for the next ones. The
// reference must still mirror (its blends queued until the run makes them), give the same bytes and
// pops at every vsync as a reference that never mirrors, and, when a stall makes the run show
// another frame while several blends wait, make them all itself in order.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "gs/lag_meter.hpp"
#include "gs/presenter.hpp"
#include "gs/scripted_source.hpp"
#include "gs/simd/blend_simd.hpp"
#include "gs/twin_tiles.hpp"
#include "runtime/scheduler.hpp"
#include "runtime/serial_unit.hpp"
#include "tests/gs/presenter_fixture.hpp"

namespace vbim::gs {
namespace {

using test::kH;
using test::kW;
using test::stream;
using test::wave;

struct Seen {
  std::vector<std::vector<std::uint8_t>> refBytes;  // the reference's lightmap after each vsync
  std::vector<int> refPops;
  std::vector<std::vector<std::uint8_t>> runBytes;
  std::vector<int> lags;
  PresenterCounters ref;
  PresenterCounters run;
};

// The run (its sky first on its GS, frames held up by `stalls`) and its stall-free reference (its
// own GS, in the scheduler's first lane as the player puts it), 3 s of strips.
Seen play(bool mirror, std::vector<Stall> stalls) {
  GsParams p;
  p.upload_mode = "strips";  // two 32-row strips of the 128x64 lightmap at every vsync
  Scheduler s;
  SerialUnit runGs(s);
  // The sky is as large as the lightmap: its GS work takes as long as the lightmap's two strips.
  ScriptedFrameSource skySource(
      {stream("sky", 300)}, [](int v, std::int64_t k) { return test::waveSized(v, k + 7, kW, kH); }, SourceScript{});
  SourceScript runScript;
  runScript.stalls = std::move(stalls);
  runScript.decodeTime = fromMs(5);
  ScriptedFrameSource runSource({stream("clear", 300)}, wave, runScript);
  ScriptedFrameSource refSource({stream("clear", 300)}, wave, SourceScript{});
  PresenterOptions runOpt;
  runOpt.kernels = &simd::kernels();
  runOpt.gs = &runGs;
  runOpt.name = "gs";
  PresenterOptions skyOpt = runOpt;
  skyOpt.name = "gs.sky";
  PresenterOptions refOpt;
  refOpt.kernels = &simd::kernels();
  refOpt.name = "ref";
  Presenter sky(s, skySource, p, skyOpt);
  Presenter run(s, runSource, p, runOpt);
  Presenter ref(s, refSource, p, refOpt);
  TwinTiles tiles(run.blender().tileChanges().size());
  run.followTwin(ref, tiles, /*runSide=*/true);
  ref.followTwin(run, tiles, /*runSide=*/false, mirror);

  const Tick end = fromMs(3000);
  {
    const Scheduler::LaneScope first(s, Lane::First);
    s.spawn("ref", ref.run(end));
  }
  s.spawn("gs.sky", sky.run(end));  // asks for the GS before the run's lightmap at every vsync
  s.spawn("gs", run.run(end));
  // The lag, as the player keeps it: tiles it finds equal are the facts the twins start from.
  TiledDifference lag(run, ref, simd::kernels().compareRect, &tiles);
  Seen seen;
  // Once both presented vsync n (as the player records it): the reference's blends made, the lag,
  // the reference's bytes.
  auto record = [&]() -> Task<void> {
    for (std::int64_t n = 0; run.clock().time(n) < end; ++n) {
      for (Presenter* pr : {&run, &ref}) {
        while (pr->presented() <= n) co_await pr->presentedEvent().wait();
      }
      ref.settleTwin();
      seen.lags.push_back(lag.update().max);
      seen.refBytes.push_back(ref.lightmap().pixels);
      seen.refPops.push_back(ref.last().pop);
      seen.runBytes.push_back(run.lightmap().pixels);
    }
  };
  s.spawn("record", record());
  s.runUntil(end);
  seen.ref = ref.counters();
  seen.run = run.counters();
  return seen;
}

void expectSame(const Seen& mirrored, const Seen& own) {
  ASSERT_EQ(mirrored.refBytes.size(), own.refBytes.size());
  ASSERT_GT(own.refBytes.size(), 150u);
  for (std::size_t n = 0; n < own.refBytes.size(); ++n) {
    ASSERT_EQ(mirrored.refBytes[n], own.refBytes[n]) << "the reference's lightmap after vsync " << n;
    ASSERT_EQ(mirrored.refPops[n], own.refPops[n]) << "the reference's pop at vsync " << n;
    ASSERT_EQ(mirrored.runBytes[n], own.runBytes[n]) << "the run's lightmap after vsync " << n;
    ASSERT_EQ(mirrored.lags[n], own.lags[n]) << "the lag at vsync " << n;
  }
  EXPECT_EQ(own.ref.tilesMirrored, 0);
}

TEST(PresenterMirror, MirrorsARunWhoseStripsComeLater) {
  const Seen own = play(/*mirror=*/false, {});
  const Seen mirrored = play(/*mirror=*/true, {});
  expectSame(mirrored, own);
  // Every vsync but the first few blends both strips of a new or converging frame.
  EXPECT_GT(mirrored.ref.tilesMirrored, own.run.tilesCopied / 2) << "the reference should mirror the run";
  EXPECT_EQ(mirrored.ref.mirrorStops, 0);
}

TEST(PresenterMirror, StopsAndMakesEveryWaitingBlendWhenTheRunFallsBehind) {
  // A stall of the run's source after the two were in step: the run shows an older frame at the
  // next vsync, when both of the reference's strips of it wait, and the reference must make them
  // both. (The moving content keeps the two apart from then on.)
  const std::vector<Stall> stalls{{fromMs(900), fromMs(300)}};
  const Seen own = play(/*mirror=*/false, stalls);
  const Seen mirrored = play(/*mirror=*/true, stalls);
  expectSame(mirrored, own);
  EXPECT_GT(mirrored.ref.tilesMirrored, 0);
  EXPECT_EQ(mirrored.ref.mirrorStops, 1);
}

}  // namespace
}  // namespace vbim::gs
