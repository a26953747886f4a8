// Shared pieces of the presenter tests: small lightmap streams, content generators, and a rig that
// runs a presenter and a stall-free reference side by side in one scheduler with a lag meter.
#pragma once

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <optional>
#include <vector>

#include "gs/lag_meter.hpp"
#include "gs/presenter.hpp"
#include "gs/scripted_source.hpp"
#include "runtime/scheduler.hpp"

namespace vbim::gs::test {

inline constexpr int kW = 128;
inline constexpr int kH = 64;

// 30000/1001 frames per second: stream frame k is due exactly at NTSC vsync 2k.
inline StreamInfo stream(std::string name, std::int64_t frames = 300, int w = kW, int h = kH) {
  return StreamInfo{std::move(name), w, h, frames, 30000, 1001};
}

// A smooth, moving pattern: a triangle wave over position and time, 9 levels per frame at most.
inline int tri(int t) {
  t %= 512;
  return t < 256 ? t : 511 - t;
}
inline Rgba8Image waveSized(int variant, std::int64_t k, int w, int h) {
  Rgba8Image img(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = img.row(y) + 4 * x;
      for (int c = 0; c < 3; ++c) {
        const int v = tri(x * 2 + y * 3 + c * 40 + static_cast<int>(k) * 9);
        p[c] = static_cast<std::uint8_t>(variant == 0 ? v : v / 2 + 20);  // variant 1: overcast
      }
      p[3] = 0x80;
    }
  }
  return img;
}

inline Rgba8Image wave(int variant, std::int64_t k) {
  return waveSized(variant, k, kW, kH);
}

// Flat frames: stream frame k has every channel at 10 + 20k (a ramp the loop jumps back from).
inline Rgba8Image ramp(int, std::int64_t k) {
  Rgba8Image img(kW, kH);
  for (std::size_t i = 0; i < img.pixels.size(); ++i) {
    img.pixels[i] = static_cast<std::uint8_t>(i % 4 == 3 ? 0x80 : 10 + 20 * k);
  }
  return img;
}

inline int maxDiff(const Rgba8Image& a, const Rgba8Image& b) {
  int m = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) m = std::max(m, std::abs(a.pixels[i] - b.pixels[i]));
  return m;
}

// The largest contraction step of the lag: a texel pair at distance d, blended toward the same
// target with the same FIX, ends at most g(d) = d - floor(d * fix / 128) apart.
inline int contract(int d, int fix) {
  return d - (d * fix) / 128;
}

// One presenter under test plus a stall-free reference fed on time, in the same scheduler.
struct Rig {
  Scheduler sched;
  ScriptedFrameSource runSource;
  ScriptedFrameSource refSource;
  Presenter run;
  Presenter ref;
  LagMeter meter;
  std::vector<Rgba8Image> before;  // run's lightmap before each vsync
  Rgba8Image last;

  Rig(std::vector<StreamInfo> streams, ScriptedFrameSource::ImageFn img, SourceScript script, const GsParams& params,
      const GsParams& refParams, ScriptedFrameSource::ImageFn refImg = nullptr, PresenterOptions runOpt = {})
      : runSource(streams, img, script),
        refSource(streams, refImg ? refImg : img, SourceScript{script.t0, 0, 0, 0, {}, script.loop}),
        run(sched, runSource, params, withObserver(std::move(runOpt))),
        ref(sched, refSource, refParams, PresenterOptions{.t0 = script.t0, .name = "ref"}),
        meter(run, ref),
        last(streams[0].width, streams[0].height) {}

  PresenterOptions withObserver(PresenterOptions o) {
    o.onVsync = [this](const VsyncRecord& rec, const Rgba8Image& lm) {
      before.push_back(last);
      last = lm;
      (void)rec;
    };
    return o;
  }

  void runFor(Tick end) {
    sched.spawn("gs", run.run(end));
    sched.spawn("ref", ref.run(end));
    sched.spawn("lag", meter.measure(end));
    sched.runUntil(end);
  }
  const std::vector<LagSample>& lag() const { return meter.samples(); }
};

}  // namespace vbim::gs::test
