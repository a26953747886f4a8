#include "player/pipeline.hpp"

#include <array>
#include <utility>

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
                   const iop::FaultPlan* faults, std::uint64_t seed, Kernels kernels, Tracer* tracer, std::string name,
                   bool hashChain)
    : s_(s),
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
      ipu_(s, config.ipu, tracer_, decoderOptions(kernels), config.ee.mc),
      gs_(s) {
  ipu_.setSliceRunner(kernels.sliceRunner);
  // The 16-bit path: the IPU writes dithered RGB16 (IDEC OFM = 1, DTE = 1; docs/porting.md), half
  // the fromIPU qwords of RGB32.
  if (config.gs.texture_format == "ct16") ipu_.setRgb16Output(true);
  const auto depth = static_cast<std::size_t>(config.ee.decoded_frames);
  lmFrames_ = std::make_unique<ee::DecodedFrames>(s, streamInfos(stream, stream.lightmapIndex), depth, *this);
  const auto recorder = [this](bool sky) {
    return [this, sky](int variant, std::int64_t seq, Tick readyAt) {
      if (arrivalHook_) arrivalHook_(sky, variant, seq, readyAt);
    };
  };
  lmSource_ = std::make_unique<gs::RecordingSource>(*lmFrames_, recorder(false));
  gs::PresenterOptions lightmapOptions = presenterOptions(t0_, kernels, tracer_, "gs", gs_);
  lightmapOptions.hashChain = hashChain;
  if (stream.skyIndex >= 0) {
    // One VRAM budget for the console: the lightmap presenter's plan holds the sky's staging too.
    const streams::StreamEntry& sky = stream.descriptor.streams[static_cast<std::size_t>(stream.skyIndex)];
    lightmapOptions.sky = gs::SkyTexture{sky.width, sky.height};
  }
  lightmap_ = std::make_unique<gs::Presenter>(s, *lmSource_, config.gs, std::move(lightmapOptions));
  if (stream.skyIndex >= 0) {
    skyFrames_ = std::make_unique<ee::DecodedFrames>(s, streamInfos(stream, stream.skyIndex), depth, *this);
    skySource_ = std::make_unique<gs::RecordingSource>(*skyFrames_, recorder(true));
    // The sky is blended in the same VRAM: into the plan's sky texture, from the sky's staging area.
    gs::PresenterOptions skyOptions = presenterOptions(t0_, kernels, tracer_, "gs.sky", gs_);
    skyOptions.console = &lightmap_->vram();
    sky_ = std::make_unique<gs::Presenter>(s, *skySource_, config.gs, std::move(skyOptions));
  }
  // An intra-only stream goes through IDEC, on the one decoder both such streams share (as before
  // issue #29: its bytes and timing unchanged); a stream with P or B pictures through the BDEC flow,
  // with its own reference frames.
  std::array<ipu::StreamId, 2> ipuStreams{ipu::kSharedIdecStream, ipu::kSharedIdecStream};
  for (const int s : {ee::kLightmap, ee::kSky}) {
    if (demux_.order(s).intraOnly()) continue;
    ipuStreams[static_cast<std::size_t>(s)] = ipu_.openStream(ipu::DecodePath::kBdec);
  }
  feeder_ = std::make_unique<ee::IpuFeeder>(
      s, std::array<ee::CompressedBuffer*, 2>{&lmCompressed_, &skyCompressed_},
      std::array<ee::DecodedFrames*, 2>{lmFrames_.get(), skyFrames_.get()}, demux_, timeline_, ipu_, config_.ee,
      config_.gs.upload_strategy == "ee-reorder", work_, tracer_, feederTrack_, ipuStreams);
  if (faults != nullptr) iop::applyFaults(s, drive_, *faults, Rng(seed).fork("faults"));
}

void Pipeline::start(Tick end) {
  s_.spawn(name_ + "ee.demux", demux_.run());
  s_.spawn(name_ + "ee.ipu", feeder_->run());
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
  feeder_->branch(fromSeq);
  timeline_.branch(fromSeq, variant);
  lmFrames_->dropFrom(fromSeq);
  if (skyFrames_) skyFrames_->dropFrom(fromSeq);
  demux_.branch(fromSeq);
}

}  // namespace vbim::player
