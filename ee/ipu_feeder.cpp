#include "ee/ipu_feeder.hpp"

#include <algorithm>
#include <limits>
#include <memory>
#include <utility>

#include "runtime/clock.hpp"

namespace vbim::ee {

IpuFeeder::IpuFeeder(Scheduler& s, std::array<CompressedBuffer*, 2> in, std::array<DecodedFrames*, 2> out,
                     const EeDemux& demux, const Timeline& timeline, ipu::IpuUnit& ipu, const EeParams& p, bool reorder,
                     Event& work, Tracer* tracer, Tracer::TrackId track, std::array<ipu::StreamId, 2> ipuStreams)
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
      track_(track),
      ipuStreams_(ipuStreams) {
  for (std::size_t i = 0; i < 2; ++i) bdec_[i] = ipu_.decodePath(ipuStreams_[i]) == ipu::DecodePath::kBdec;
}

void IpuFeeder::branch(std::int64_t fromSeq) {
  ++generation_;
  lastBranchFrom_ = fromSeq;
}

// The BDEC flow shows a B picture as soon as it is decoded and an I or P picture when the next one
// is (ISO/IEC 13818-2 §6.1.1.11): then the reference decoded before it is the frame out.
std::optional<IpuFeeder::Held> IpuFeeder::displayed(int stream, const CompressedPicture& pic, std::uint64_t gen,
                                                    bool produced) {
  const auto si = static_cast<std::size_t>(stream);
  const Held now{pic.seq, pic.shown, gen};
  if (!bdec_[si]) return now;
  if (!produced) return std::nullopt;
  if (pic.type == streams::PictureType::B) return now;
  return std::exchange(held_[si], now);
}

// A P or B picture decoded while a reference before it in the GOP was lost or damaged predicts from
// the wrong picture (or mid-grey): counted until the next clean I picture.
void IpuFeeder::countReferences(int stream, const CompressedPicture& pic, const ipu::PictureReport& report) {
  bool& broken = brokenChain_[static_cast<std::size_t>(stream)];
  const bool missing = std::any_of(report.issues.begin(), report.issues.end(), [](const ipu::DecodeIssue& i) {
    return i.kind == ipu::IssueKind::kMissingReference;
  });
  // A picture that disagrees with the index (pic.damaged) may decode without an issue and still be
  // wrong: as a reference it breaks the chain too.
  const bool bad = pic.damaged || !report.clean();
  if (pic.type == streams::PictureType::I) {
    broken = bad;
    return;
  }
  if (pic.afterLoss) broken = true;
  if (broken || missing) ++dc_.brokenReferencePictures;
  if (pic.type == streams::PictureType::P && bad) broken = true;
}

Task<void> IpuFeeder::decodeOne(int stream) {
  const auto si = static_cast<std::size_t>(stream);
  CompressedBuffer& in = *in_[si];
  DecodedFrames& out = *out_[si];
  CompressedPicture pic = in.pop();
  work_.notify();
  const std::uint64_t gen = generation_;
  const Tick t0 = s_.now();
  co_await s_.delay(fromEeCycles(p_.decode_setup_cycles));
  // A recycled buffer of this stream's size: the IPU writes every byte of it (or hands back the
  // image of the same picture another IPU decoded: ipu/ipu_unit_shared_decodes.hpp).
  std::shared_ptr<Rgba8Image> image = images_[si].take();
  const ipu::TimedPicture tp = co_await ipu_.decode(ipuStreams_[si], pic.data, image);
  // The variant the picture belongs to (its number in the stream), not the one a branch may have
  // switched to meanwhile.
  if (commandHook_) commandHook_(stream, static_cast<int>(pic.globalFrame / timeline_.framesPerVariant()), pic, tp);
  const Tick took = s_.now() - t0;
  if (tracer_ != nullptr) tracer_->span(track_, t0, s_.now(), stream == kLightmap ? "lightmap" : "sky");
  ++dc_.pictures;
  ++dc_.picturesPerStream[si];
  dc_.busy += took;
  dc_.perStream[si] += took;
  dc_.maxPerPicture = std::max(dc_.maxPerPicture, took);
  dc_.idecCommands += tp.idecCommands;
  dc_.commands += tp.commands;
  dc_.eeBusy += tp.eeBusy;
  dc_.concealedMacroblocks += tp.report.macroblocksConcealed;
  if (!tp.report.clean()) ++dc_.picturesWithIssues;
  if (bdec_[si]) {
    ++dc_.bdecPictures;
    if (!pic.shown) ++dc_.picturesForReference;
    countReferences(stream, pic, tp.report);
  }
  const std::optional<Held> frame = displayed(stream, pic, gen, tp.report.produced);
  const gs::StreamInfo& info = out.streams()[0];
  if (!tp.report.produced) {
    ++dc_.undecodable;
    co_return;
  }
  if (!tp.displayed) co_return;  // BDEC flow: the picture waits for the next reference
  if (image->width != info.width || image->height != info.height) {
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
  if (!frame || !frame->shown) co_return;  // a reference decoded only for the frames after it
  if (frame->generation != generation_ && frame->seq >= lastBranchFrom_) {
    ++dc_.staleDropped;
    co_return;
  }
  out.push(gs::ReadyFrame{timeline_.variantOf(frame->seq), frame->seq, s_.now(), std::move(image)});
}

// The EE thread that feeds the one IPU: in decode order (ee/decode_order.hpp; the timeline's order
// in an intra-only stream), for each key the lightmap then the sky. A stream whose buffer is empty
// holds the order back only while the demux may still load a picture at that key (its next wanted
// key is not past it); otherwise that picture was lost and is skipped.
Task<void> IpuFeeder::run() {
  constexpr std::int64_t kNone = std::numeric_limits<std::int64_t>::max();
  for (;;) {
    std::int64_t k = kNone;
    for (int s = 0; s < 2; ++s) {
      if (!active(s)) continue;
      const CompressedBuffer& b = *in_[static_cast<std::size_t>(s)];
      k = std::min(k, b.empty() ? demux_.nextKey(s) : b.front().key);
    }
    int ready = -1;
    for (int s = 0; s < 2 && ready < 0; ++s) {
      if (!active(s)) continue;
      const CompressedBuffer& b = *in_[static_cast<std::size_t>(s)];
      if (!b.empty() && b.front().key == k) ready = s;
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
