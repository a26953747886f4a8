// Single-thread decode of a 720x480 I/P/B MPEG-2 stream (GOP 12, two B pictures between references,
// a panned texture so the vectors are non-trivial and half-sample; progressive, and interlaced with
// field prediction and field DCT), made at bench start with libavcodec's mpeg2video encoder, side by
// side in one process on the same bytes:
//   ours_yuv: our decoder (Highway kernels, the default IDCT) to YCbCr, every display frame touched;
//   ours_l2idct: the same with IdctKind::Libmpeg2 (bit-identical to libmpeg2's C decoder);
//   libmpeg2: libmpeg2 0.5.1 with its SIMD acceleration (mpeg2_accel(MPEG2_ACCEL_DETECT)) to YCbCr;
//   ours_rgba: our decoder to RGBA, each display frame converted with the decoder's kernels;
//   libavcodec: libavcodec (threads = 1) + swscale to RGBA.
// Interleaved rounds, thread CPU time; counters: frames/s (best round) and per-round ratios, medians:
//   x_libmpeg2_yuv = libmpeg2 / ours_yuv, x_libav_rgba = libavcodec / ours_rgba (> 1: we are faster),
//   l2idct_cost = ours_l2idct / ours_yuv (what libmpeg2 0.5.1's IDCT costs against the default).
// BM_GopDecodeTargets: our decode with the kernels of each Highway target this machine runs (is a
// wider target's code slower here than a narrower one's?).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "hwy/targets.h"
#include "runtime/simd/targets.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavutil/imgutils.h>
#include <libswscale/swscale.h>
}
#include <cinttypes>
extern "C" {
#include <mpeg2.h>
}

#include "bench/ipu/bench_timing.hpp"
#include "ipu/csc.hpp"
#include "ipu/elementary_stream.hpp"
#include "ipu/picture_decoder.hpp"
#include "ipu/simd/mc_kernels.hpp"
#include "ipu/simd/simd_kernels.hpp"
#include "tests/ipu/support/libav_mpeg.hpp"

namespace {

using vbim::ipu::testing::Content;

constexpr int kWidth = 720;
constexpr int kHeight = 480;
constexpr int kFrames = 24;  // two GOPs

struct Clip {
  std::vector<std::uint8_t> es;
  std::vector<vbim::ipu::AccessUnit> units;
};

const Clip& clip(bool interlaced, int q) {
  static std::map<std::pair<bool, int>, Clip> cache;
  auto& slot = cache[{interlaced, q}];
  if (slot.es.empty()) {
    vbim::ipu::testing::EncodeOptions o;
    o.width = kWidth;
    o.height = kHeight;
    o.frames = kFrames;
    o.gopSize = 12;
    o.bFrames = 2;
    o.quantiser = q;
    o.content = Content::kPan;
    o.interlacedDct = interlaced;
    o.interlacedMe = interlaced;
    slot.es = vbim::ipu::testing::encodeIntra(o);
    slot.units = vbim::ipu::splitAccessUnits(slot.es);
  }
  return slot;
}

// --- the decoders, each decoding the whole clip once ------------------------------------------

struct Ours {
  explicit Ours(vbim::ipu::IdctKind idct, bool toRgba, const vbim::ipu::Kernels* kernels = &vbim::ipu::simdKernels())
      : dec(options(idct, kernels)), rgba_(toRgba) {}
  static vbim::ipu::DecoderOptions options(vbim::ipu::IdctKind idct, const vbim::ipu::Kernels* kernels) {
    vbim::ipu::DecoderOptions o;
    o.kernels = kernels;
    o.idct = idct;
    return o;
  }
  std::uint64_t show(std::uint64_t& frames) {
    const vbim::ipu::FrameStore* f = dec.displayFrame();
    if (!f) return 0;
    ++frames;
    if (!rgba_) return f->y[f->y.size() / 2];
    const int w = dec.displayWidth();
    const int h = dec.displayHeight();
    if (image.width != w || image.height != h) image = vbim::Rgba8Image(w, h);
    vbim::ipu::convertLinesToRgba32(*f, 0, h, {}, image, dec.kernels().cscRow);
    return image.pixels[image.pixels.size() / 2];
  }
  std::uint64_t run(const Clip& c) {
    std::uint64_t sum = 0;
    frames = 0;
    for (const auto& au : c.units) {
      dec.decode(std::span(c.es).subspan(au.offset, au.size));
      sum += show(frames);
    }
    while (dec.flushDisplay()) sum += show(frames);
    return sum;
  }
  vbim::ipu::Decoder dec;
  vbim::Rgba8Image image;
  std::uint64_t frames = 0;

 private:
  bool rgba_;
};

struct LibAv {
  AVCodecContext* ctx = nullptr;
  AVPacket* pkt = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  SwsContext* sws = nullptr;
  std::vector<std::uint8_t> rgba = std::vector<std::uint8_t>(std::size_t{kWidth} * kHeight * 4);
  std::uint64_t frames = 0;
  LibAv() {
    const AVCodec* codec = avcodec_find_decoder(AV_CODEC_ID_MPEG2VIDEO);
    ctx = avcodec_alloc_context3(codec);
    ctx->thread_count = 1;
    avcodec_open2(ctx, codec, nullptr);
  }
  LibAv(const LibAv&) = delete;
  LibAv& operator=(const LibAv&) = delete;
  ~LibAv() {
    sws_freeContext(sws);
    av_frame_free(&frame);
    av_packet_free(&pkt);
    avcodec_free_context(&ctx);
  }
  std::uint64_t receive() {
    std::uint64_t sum = 0;
    while (avcodec_receive_frame(ctx, frame) == 0) {
      if (!sws) {
        sws = sws_getContext(frame->width, frame->height, AV_PIX_FMT_YUV420P, frame->width, frame->height,
                             AV_PIX_FMT_RGBA, SWS_BILINEAR, nullptr, nullptr, nullptr);
      }
      std::uint8_t* dst[1] = {rgba.data()};
      const int stride[1] = {frame->width * 4};
      sws_scale(sws, frame->data, frame->linesize, 0, frame->height, dst, stride);
      sum += rgba[rgba.size() / 2];
      ++frames;
    }
    return sum;
  }
  std::uint64_t run(const Clip& c) {
    std::uint64_t sum = 0;
    frames = 0;
    for (const auto& au : c.units) {
      pkt->data = const_cast<std::uint8_t*>(c.es.data() + au.offset);
      pkt->size = static_cast<int>(au.size);
      avcodec_send_packet(ctx, pkt);
      sum += receive();
    }
    // End of stream: the last reference frame, then ready for the next round.
    avcodec_send_packet(ctx, nullptr);
    sum += receive();
    avcodec_flush_buffers(ctx);
    return sum;
  }
};

struct LibMpeg2 {
  std::uint64_t frames = 0;
  std::uint64_t run(const Clip& c) {
    mpeg2dec_t* dec = mpeg2_init();
    const mpeg2_info_t* info = mpeg2_info(dec);
    mpeg2_buffer(dec, const_cast<std::uint8_t*>(c.es.data()), const_cast<std::uint8_t*>(c.es.data() + c.es.size()));
    std::uint64_t sum = 0;
    frames = 0;
    bool fed = false;
    for (;;) {
      const mpeg2_state_t state = mpeg2_parse(dec);
      if (state == STATE_BUFFER) {
        if (fed) break;
        // A trailing sequence end code flushes the last picture.
        static std::uint8_t end[4] = {0, 0, 1, 0xB7};
        mpeg2_buffer(dec, end, end + 4);
        fed = true;
      } else if ((state == STATE_SLICE || state == STATE_END) && info->display_fbuf) {
        sum += info->display_fbuf->buf[0][std::ptrdiff_t{kWidth} * (kHeight / 2)];
        ++frames;
      }
    }
    mpeg2_close(dec);
    return sum;
  }
};

using vbim::bench::median;

template <class D>
double secondsOnce(D& d, const Clip& c) {
  return vbim::bench::secondsPerFrame(d, c, kFrames);
}

void BM_GopDecode(benchmark::State& state) {
  const bool interlaced = state.range(0) != 0;
  const int q = static_cast<int>(state.range(1));
  const Clip& c = clip(interlaced, q);
  // libmpeg2 picks its accelerated IDCT and motion compensation once per process.
  const std::uint32_t accel = mpeg2_accel(MPEG2_ACCEL_DETECT);
  Ours yuv(vbim::ipu::kDefaultIdct, false);
  Ours l2idct(vbim::ipu::IdctKind::Libmpeg2, false);
  Ours rgba(vbim::ipu::kDefaultIdct, true);
  LibMpeg2 m2;
  LibAv av;
  for (auto _ : state) benchmark::DoNotOptimize(yuv.run(c));
  // Every decoder must show every frame (a check that the loops above decode what they should).
  benchmark::DoNotOptimize(l2idct.run(c) + rgba.run(c) + m2.run(c) + av.run(c));
  const bool allFrames = yuv.frames == kFrames && l2idct.frames == kFrames && rgba.frames == kFrames &&
                         m2.frames == kFrames && av.frames == kFrames;
  // Interleaved rounds: neighbours' load on the shared machine hits all alike within a round, so
  // the ratios are taken per round and their median reported; fps are the best of the rounds.
  constexpr int kRounds = 15;
  double best[5] = {1e9, 1e9, 1e9, 1e9, 1e9};
  std::vector<double> xM2, xAv, xIdct;
  for (int r = 0; r < kRounds; ++r) {
    const double t[5] = {secondsOnce(yuv, c), secondsOnce(m2, c), secondsOnce(rgba, c), secondsOnce(av, c),
                         secondsOnce(l2idct, c)};
    for (int k = 0; k < 5; ++k) best[k] = std::min(best[k], t[k]);
    xM2.push_back(t[1] / t[0]);
    xAv.push_back(t[3] / t[2]);
    xIdct.push_back(t[4] / t[0]);
  }
  state.counters["bytes/frame"] = static_cast<double>(c.es.size()) / kFrames;
  state.counters["ours_yuv_fps"] = 1.0 / best[0];
  state.counters["libmpeg2_fps"] = 1.0 / best[1];
  state.counters["ours_rgba_fps"] = 1.0 / best[2];
  state.counters["libavcodec_fps"] = 1.0 / best[3];
  state.counters["ours_l2idct_fps"] = 1.0 / best[4];
  state.counters["x_libmpeg2_yuv"] = median(xM2);
  state.counters["x_libav_rgba"] = median(xAv);
  state.counters["l2idct_cost"] = median(xIdct);
  state.counters["libmpeg2_accel"] = static_cast<double>(accel);
  state.counters["all_frames"] = allFrames ? 1 : 0;
  state.SetItemsProcessed(state.iterations() * kFrames);
}
BENCHMARK(BM_GopDecode)
    ->ArgNames({"interlaced", "q"})
    ->Args({0, 4})
    ->Args({0, 2})
    ->Args({1, 4})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(0.5);

// One decode of the clip, never inlined, so that a profiler can count it alone (without the clip's
// encode at bench start): valgrind --tool=callgrind --toggle-collect='*countedDecode*' ...
template <class D>
[[gnu::noinline]] std::uint64_t countedDecode(D& d, const Clip& c) {
  return d.run(c);
}

// Ours alone to YCbCr (with the default IDCT, or IdctKind::Libmpeg2) or to RGBA, for profiling:
// perf record -g build/bench/ipu/bench_ipu_gop_decode --benchmark_filter=BM_GopDecodeOurs/...
// One decode ahead of the loop, so that every counted decode finds its frames allocated.
void BM_GopDecodeOurs(benchmark::State& state) {
  const Clip& c = clip(state.range(0) != 0, static_cast<int>(state.range(1)));
  Ours ours(state.range(2) != 0 ? vbim::ipu::IdctKind::Libmpeg2 : vbim::ipu::kDefaultIdct, state.range(3) != 0);
  benchmark::DoNotOptimize(ours.run(c));
  for (auto _ : state) benchmark::DoNotOptimize(countedDecode(ours, c));
  state.SetItemsProcessed(state.iterations() * kFrames);
}
BENCHMARK(BM_GopDecodeOurs)
    ->ArgNames({"interlaced", "q", "l2idct", "rgba"})
    ->Args({0, 4, 0, 0})
    ->Args({0, 2, 0, 0})
    ->Args({0, 4, 1, 0})
    ->Args({1, 4, 0, 0})
    ->Args({0, 4, 0, 1})
    ->Args({0, 2, 0, 1})
    ->Unit(benchmark::kMillisecond);

// libmpeg2 alone to YCbCr, the same clips, to compare whole-decode counts with BM_GopDecodeOurs
// (its symbols are stripped, so a profile of it gives totals, not functions):
// valgrind --tool=callgrind --toggle-collect='*countedDecode*' --branch-sim=yes --cache-sim=yes
//   build/bench/ipu/bench_ipu_gop_decode --benchmark_filter=BM_GopDecodeLibmpeg2/... --benchmark_min_time=0.001
void BM_GopDecodeLibmpeg2(benchmark::State& state) {
  const Clip& c = clip(state.range(0) != 0, static_cast<int>(state.range(1)));
  mpeg2_accel(MPEG2_ACCEL_DETECT);
  LibMpeg2 m2;
  benchmark::DoNotOptimize(m2.run(c));
  for (auto _ : state) benchmark::DoNotOptimize(countedDecode(m2, c));
  state.SetItemsProcessed(state.iterations() * kFrames);
}
BENCHMARK(BM_GopDecodeLibmpeg2)
    ->ArgNames({"interlaced", "q"})
    ->Args({0, 4})
    ->Args({0, 2})
    ->Args({1, 4})
    ->Unit(benchmark::kMillisecond);

// Our decode with each Highway target's kernels (IDCT, motion compensation, CSC) on the same bytes, in
// interleaved rounds: x_<TARGET> = that target's time / the best target's (the one simdKernels()
// picks), median of the per-round ratios (> 1: the dispatch's pick is faster). A wider target that
// is slower on the machine than a narrower one would show here as x < 1.
void BM_GopDecodeTargets(benchmark::State& state) {
  const Clip& c = clip(state.range(0) != 0, static_cast<int>(state.range(1)));
  const bool toRgba = state.range(2) != 0;
  struct Target {
    std::string name;
    vbim::ipu::McKernels mc;
    vbim::ipu::Kernels kernels;
    std::unique_ptr<Ours> dec;
  };
  std::deque<Target> targets;  // stable addresses: each Kernels points at its McKernels
  vbim::simd::forEachTarget(HWY_TARGETS & ~(HWY_SCALAR | HWY_EMU128), [&](std::int64_t t) {
    Target& x = targets.emplace_back();
    x.name = hwy::TargetName(t);
    x.mc = vbim::ipu::simdMcKernelsOfCurrentTarget();
    x.kernels = vbim::ipu::simdKernelsOfCurrentTarget();
    x.kernels.mc = &x.mc;
  });
  // To RGBA, also the best target's decode with each narrower target's colour conversion
  // (csc_<TARGET>), to tell the conversion's share of a difference from the decode's.
  const std::size_t wholeTargets = targets.size();
  if (toRgba) {
    for (std::size_t k = 1; k < wholeTargets; ++k) {
      Target& x = targets.emplace_back();
      x.name = "csc_" + targets[k].name;
      x.mc = targets.front().mc;
      x.kernels = targets.front().kernels;
      x.kernels.mc = &x.mc;
      x.kernels.cscRow = targets[k].kernels.cscRow;
    }
  }
  for (Target& x : targets) x.dec = std::make_unique<Ours>(vbim::ipu::kDefaultIdct, toRgba, &x.kernels);
  if (targets.empty()) {
    state.SkipWithError("no SIMD target");
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(targets.front().dec->run(c));
  // Every target's decode shows the same samples (a check, not a proof: tests/ipu/simd_test.cpp
  // and mc_kernels_test.cpp compare the kernels on every target).
  const std::uint64_t reference = targets.front().dec->run(c);
  bool same = true;
  for (Target& x : targets) same = same && x.dec->run(c) == reference;
  state.counters["same_samples"] = same ? 1 : 0;
  constexpr int kRounds = 15;
  std::vector<std::vector<double>> ratios(targets.size());
  for (int r = 0; r < kRounds; ++r) {
    std::vector<double> t(targets.size());
    for (std::size_t k = 0; k < targets.size(); ++k) t[k] = secondsOnce(*targets[k].dec, c);
    for (std::size_t k = 1; k < targets.size(); ++k) ratios[k].push_back(t[k] / t[0]);
  }
  for (std::size_t k = 1; k < targets.size(); ++k) state.counters["x_" + targets[k].name] = median(ratios[k]);
  state.SetLabel(targets.front().name);
}
BENCHMARK(BM_GopDecodeTargets)
    ->ArgNames({"interlaced", "q", "rgba"})
    ->Args({0, 2, 0})
    ->Args({0, 4, 0})
    ->Args({1, 4, 0})
    ->Args({0, 2, 1})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
