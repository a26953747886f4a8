#include "ee/ipu_feeder.hpp"

#include <algorithm>
#include <limits>
#include <memory>
#include <utility>

#include "runtime/clock.hpp"

namespace vbim::ee {

IpuFeeder::IpuFeeder(Scheduler& s, std::array<CompressedBuffer*, 2> in, std::array<DecodedFrames*, 2> out,
                     const EeDemux& demux, const Timeline& timeline, ipu::IpuUnit& ipu, const EeParams& p, bool reorder,
                     Event& work, Tracer* tracer, Tracer::TrackId track)
    : s_(s),
      in_(in),
      out_(out),
      demux_(demux),
      timeline_(timeline),
      ipu_(ipu),
      p_(p),
      reorder_(reorder),
      work_(work),
      tracer_(tracer),
      track_(track) {}

void IpuFeeder::branch(std::int64_t fromSeq) {
  ++generation_;
  lastBranchFrom_ = fromSeq;
}

Task<void> IpuFeeder::decodeOne(int stream) {
  CompressedBuffer& in = *in_[static_cast<std::size_t>(stream)];
  DecodedFrames& out = *out_[static_cast<std::size_t>(stream)];
  CompressedPicture pic = in.pop();
  work_.notify();
  const std::uint64_t gen = generation_;
  const Tick t0 = s_.now();
  co_await s_.delay(fromEeCycles(p_.decode_setup_cycles));
  // A recycled buffer of this stream's size: the IPU writes every byte of it.
  std::shared_ptr<Rgba8Image> image = images_[static_cast<std::size_t>(stream)].take();
  const ipu::TimedPicture tp = co_await ipu_.decode(pic.data, *image);
  const Tick took = s_.now() - t0;
  if (tracer_ != nullptr) tracer_->span(track_, t0, s_.now(), stream == kLightmap ? "lightmap" : "sky");
  ++dc_.pictures;
  ++dc_.picturesPerStream[static_cast<std::size_t>(stream)];
  dc_.busy += took;
  dc_.perStream[static_cast<std::size_t>(stream)] += took;
  dc_.maxPerPicture = std::max(dc_.maxPerPicture, took);
  dc_.idecCommands += tp.idecCommands;
  dc_.commands += tp.commands;
  dc_.eeBusy += tp.eeBusy;
  dc_.concealedMacroblocks += tp.report.macroblocksConcealed;
  if (!tp.report.clean()) ++dc_.picturesWithIssues;
  const gs::StreamInfo& info = out.streams()[0];
  if (!tp.report.produced || image->width != info.width || image->height != info.height) {
    ++dc_.undecodable;
    co_return;
  }
  if (reorder_) {
    // Every quadword the IPU wrote, in macroblock order (partial macroblocks at the edges included).
    const std::int64_t qwords = tp.outputQwords;
    const Tick r0 = s_.now();
    co_await s_.delay(fromEeCycles(qwords * p_.reorder_cycles_per_qword));
    if (tracer_ != nullptr) tracer_->span(track_, r0, s_.now(), "reorder");
    dc_.reorderedQwords += qwords;
    dc_.reorderBusy += s_.now() - r0;
  }
  if (gen != generation_ && pic.seq >= lastBranchFrom_) {
    ++dc_.staleDropped;
    co_return;
  }
  out.push(gs::ReadyFrame{timeline_.variantOf(pic.seq), pic.seq, s_.now(), std::move(image)});
}

// The EE thread that feeds the one IPU: in timeline order, for each seq the lightmap then the sky.
// A stream whose buffer is empty holds the order back only while the demux may still load a picture
// at that seq (its next wanted seq is not past it); otherwise that picture was lost and is skipped.
Task<void> IpuFeeder::run() {
  constexpr std::int64_t kNone = std::numeric_limits<std::int64_t>::max();
  for (;;) {
    std::int64_t k = kNone;
    for (int s = 0; s < 2; ++s) {
      if (!active(s)) continue;
      const CompressedBuffer& b = *in_[static_cast<std::size_t>(s)];
      k = std::min(k, b.empty() ? demux_.nextSeq(s) : b.front().seq);
    }
    int ready = -1;
    for (int s = 0; s < 2 && ready < 0; ++s) {
      if (!active(s)) continue;
      const CompressedBuffer& b = *in_[static_cast<std::size_t>(s)];
      if (!b.empty() && b.front().seq == k) ready = s;
    }
    if (ready < 0) {
      co_await work_.wait();
      continue;
    }
    DecodedFrames& out = *out_[static_cast<std::size_t>(ready)];
    if (out.full()) {
      co_await out.room().wait();
      continue;  // re-evaluate: a branch may have changed the buffers
    }
    co_await decodeOne(ready);
  }
}

}  // namespace vbim::ee
