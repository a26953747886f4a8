#include "player/pipeline.hpp"

#include <algorithm>
#include <limits>

namespace vbim::player {

namespace {

Tracer* enabled(Tracer* t) {
  return t != nullptr && t->enabled() ? t : nullptr;
}

std::vector<gs::StreamInfo> streamInfos(const ee::ProbedStream& p, int descriptorIndex) {
  const streams::Descriptor& d = p.descriptor;
  const streams::StreamEntry& e = d.streams[static_cast<std::size_t>(descriptorIndex)];
  std::vector<gs::StreamInfo> out;
  for (const streams::Variant& v : d.variants) {
    out.push_back(gs::StreamInfo{v.name, e.width, e.height, d.framesPerVariant, d.gameFps.num, d.gameFps.den});
  }
  return out;
}

ipu::DecoderOptions decoderOptions(const Kernels& k) {
  ipu::DecoderOptions o;
  o.kernels = k.ipu;
  return o;
}

gs::PresenterOptions presenterOptions(Tick t0, const Kernels& k, Tracer* tracer, std::string name, SerialUnit& gs) {
  gs::PresenterOptions o;
  o.t0 = t0;
  o.gs = &gs;
  o.kernels = k.blend;
  o.tracer = tracer;
  o.name = std::move(name);
  o.keepHistory = false;  // the player streams its own per-vsync rows: memory independent of run length
  return o;
}

}  // namespace

Pipeline::Pipeline(Scheduler& s, iop::SectorSource& disc, const ee::ProbedStream& stream, const PlatformConfig& config,
                   const iop::FaultPlan* faults, std::uint64_t seed, Kernels kernels, Tracer* tracer, std::string name)
    : s_(s),
      stream_(stream),
      config_(config),
      tracer_(enabled(tracer)),
      name_(std::move(name)),
      t0_(fromMs(config.ee.start_lead_ms)),
      feederTrack_(tracer_ != nullptr ? tracer_->track("ee.ipu") : 0),
      drive_(s, disc, config.iop.drive, Rng(seed).fork("iop"), tracer_),
      sif_(s, config.iop.sif, tracer_),
      ring_(s, drive_, sif_, config.iop.ring, tracer_),
      timeline_(stream.descriptor),
      work_(s),
      lmCompressed_(s, static_cast<std::size_t>(config.ee.compressed_frames)),
      skyCompressed_(s, static_cast<std::size_t>(config.ee.compressed_frames)),
      demux_(s, ring_, stream, timeline_, config.ee, {&lmCompressed_, &skyCompressed_}, work_, tracer_),
      ipu_(s, config.ipu, tracer_, decoderOptions(kernels)),
      gs_(s) {
  const auto depth = static_cast<std::size_t>(config.ee.decoded_frames);
  lmFrames_ = std::make_unique<ee::DecodedFrames>(s, streamInfos(stream, stream.lightmapIndex), depth, *this);
  lightmap_ =
      std::make_unique<gs::Presenter>(s, *lmFrames_, config.gs, presenterOptions(t0_, kernels, tracer_, "gs", gs_));
  if (stream.skyIndex >= 0) {
    skyFrames_ = std::make_unique<ee::DecodedFrames>(s, streamInfos(stream, stream.skyIndex), depth, *this);
    sky_ = std::make_unique<gs::Presenter>(s, *skyFrames_, config.gs,
                                           presenterOptions(t0_, kernels, tracer_, "gs.sky", gs_));
  }
  if (faults != nullptr) iop::applyFaults(s, drive_, *faults, Rng(seed).fork("faults"));
}

void Pipeline::start(Tick end) {
  s_.spawn(name_ + "ee.demux", demux_.run());
  s_.spawn(name_ + "ee.ipu", feedIpu(*this));
  s_.spawn(name_ + "gs", lightmap_->run(end));
  if (sky_) s_.spawn(name_ + "gs.sky", sky_->run(end));
}

void Pipeline::scheduleBranch(Tick at, int variant) {
  lightmap_->scheduleBranch(at, variant);
  if (sky_) sky_->scheduleBranch(at, variant);
}

// Both presenters report the same branch at the same vsync; the first call does the work.
void Pipeline::onBranch(int variant, std::int64_t fromSeq, Tick now) {
  if (now == lastBranchAt_ && variant == lastBranchVariant_) return;
  lastBranchAt_ = now;
  lastBranchVariant_ = variant;
  if (timeline_.variantOf(fromSeq) == variant && timeline_.variantOf(fromSeq - 1) == variant) return;
  ++generation_;
  lastBranchFrom_ = fromSeq;
  timeline_.branch(fromSeq, variant);
  lmFrames_->dropFrom(fromSeq);
  if (skyFrames_) skyFrames_->dropFrom(fromSeq);
  demux_.branch(fromSeq);
}

Task<void> Pipeline::decodeOne(int stream) {
  ee::CompressedBuffer& in = stream == ee::kLightmap ? lmCompressed_ : skyCompressed_;
  ee::DecodedFrames& out = stream == ee::kLightmap ? *lmFrames_ : *skyFrames_;
  ee::CompressedPicture pic = in.pop();
  work_.notify();
  const std::uint64_t gen = generation_;
  const Tick t0 = s_.now();
  co_await s_.delay(fromEeCycles(config_.ee.decode_setup_cycles));
  auto image = std::make_shared<Rgba8Image>();
  const ipu::TimedPicture tp = co_await ipu_.decode(pic.data, *image);
  const Tick took = s_.now() - t0;
  if (tracer_ != nullptr) tracer_->span(feederTrack_, t0, s_.now(), stream == ee::kLightmap ? "lightmap" : "sky");
  ++dc_.pictures;
  ++dc_.picturesPerStream[static_cast<std::size_t>(stream)];
  dc_.busy += took;
  dc_.perStream[static_cast<std::size_t>(stream)] += took;
  dc_.maxPerPicture = std::max(dc_.maxPerPicture, took);
  dc_.concealedMacroblocks += tp.report.macroblocksConcealed;
  if (!tp.report.clean()) ++dc_.picturesWithIssues;
  const gs::StreamInfo& info = out.streams()[0];
  if (!tp.report.produced || image->width != info.width || image->height != info.height) {
    ++dc_.undecodable;
    co_return;
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
Task<void> Pipeline::feedIpu(Pipeline& p) {
  constexpr std::int64_t kNone = std::numeric_limits<std::int64_t>::max();
  for (;;) {
    std::int64_t k = kNone;
    for (int s = 0; s < 2; ++s) {
      if (!p.active(s)) continue;
      const ee::CompressedBuffer& b = s == ee::kLightmap ? p.lmCompressed_ : p.skyCompressed_;
      k = std::min(k, b.empty() ? p.demux_.nextSeq(s) : b.front().seq);
    }
    int ready = -1;
    for (int s = 0; s < 2 && ready < 0; ++s) {
      if (!p.active(s)) continue;
      const ee::CompressedBuffer& b = s == ee::kLightmap ? p.lmCompressed_ : p.skyCompressed_;
      if (!b.empty() && b.front().seq == k) ready = s;
    }
    if (ready < 0) {
      co_await p.work_.wait();
      continue;
    }
    ee::DecodedFrames& out = ready == ee::kLightmap ? *p.lmFrames_ : *p.skyFrames_;
    if (out.full()) {
      co_await out.room().wait();
      continue;  // re-evaluate: a branch may have changed the buffers
    }
    co_await p.decodeOne(ready);
  }
}

}  // namespace vbim::player
