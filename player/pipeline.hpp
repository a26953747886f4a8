// One complete playback pipeline on a shared Scheduler, as cooperating threads:
//
//   drive ("drive") -> stream ring ("ring" producer) -> SIF0 -> EE demux ("ee.demux")
//     -> compressed frame buffers (lightmap, sky) -> IPU feeder ("ee.ipu", one IPU, serialised)
//     -> decoded frame buffers -> GS presenters ("gs" lightmap, "gs.sky" sky) at every vsync
//
// The IPU feeder (ee/ipu_feeder.hpp) decodes in timeline order: for each sequence number the
// lightmap picture, then the sky picture, so the sky stays in step with the lightmap. A branch
// (scheduled on both presenters at the same time) drops what was loaded for the old variant and
// repositions the demux.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "ee/ee_demux.hpp"
#include "ee/frame_buffers.hpp"
#include "ee/ipu_feeder.hpp"
#include "ee/stream_probe.hpp"
#include "ee/timeline.hpp"
#include "gs/arrival_source.hpp"
#include "gs/blend.hpp"
#include "gs/presenter.hpp"
#include "iop/drive.hpp"
#include "iop/fault_plan.hpp"
#include "iop/sif.hpp"
#include "iop/stream_ring.hpp"
#include "ipu/ipu_unit.hpp"
#include "player/platform_config.hpp"
#include "runtime/rng.hpp"
#include "runtime/scheduler.hpp"
#include "runtime/serial_unit.hpp"
#include "runtime/trace.hpp"

namespace vbim::player {

// SIMD kernels are injected by the caller (the model links only the portable scalar references).
struct Kernels {
  const gs::BlendKernels* blend = nullptr;  // null: gs scalar reference
  const ipu::Kernels* ipu = nullptr;        // null: ipu scalar reference
  ipu::SliceRunner* sliceRunner = nullptr;  // null: the IPU decodes on the simulation thread
};

class Pipeline : public ee::DecodedFrames::BranchSink {
 public:
  Pipeline(Scheduler& s, iop::SectorSource& disc, const ee::ProbedStream& stream, const PlatformConfig& config,
           const iop::FaultPlan* faults, std::uint64_t seed, Kernels kernels, Tracer* tracer, std::string name,
           bool hashChain = false);
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;

  // Spawns every process; presenters present vsyncs before `end`.
  void start(Tick end);
  // At the first vsync at or after `at`, both presenters switch to `variant` (same time of day).
  void scheduleBranch(Tick at, int variant);
  // Called the first time a presenter receives each frame (the arrivals a port would log).
  using ArrivalHook = std::function<void(bool sky, int variant, std::int64_t seq, Tick readyAt)>;
  void setArrivalHook(ArrivalHook hook) { arrivalHook_ = std::move(hook); }
  // The IPU records every command it issues, and `hook` gets each picture's (ipu_commands.csv).
  void setIpuCommandHook(ee::IpuFeeder::CommandHook hook) {
    ipu_.recordCommands();
    feeder_->setCommandHook(std::move(hook));
  }

  // hashChain: the lightmap presenter keeps the frame hash's chain (gs::PresenterOptions::hashChain).
  gs::Presenter& lightmap() { return *lightmap_; }
  const gs::Presenter& lightmap() const { return *lightmap_; }
  gs::Presenter* sky() { return sky_.get(); }
  const SerialUnit& gsUnit() const { return gs_; }
  ipu::IpuUnit& ipu() { return ipu_; }
  const iop::Drive& drive() const { return drive_; }
  const iop::StreamRing& ring() const { return ring_; }
  const iop::SifChannel& sif() const { return sif_; }
  const ee::EeDemux& demux() const { return demux_; }
  const ee::DecodeCounters& decode() const { return feeder_->counters(); }
  Tick t0() const { return t0_; }
  // The drive's busy-span track in the tracer (the drive creates it right after the feeder's).
  Tracer::TrackId driveTrack() const { return feederTrack_ + 1; }

 private:
  void onBranch(int variant, std::int64_t fromSeq, Tick now) override;

  Scheduler& s_;
  PlatformConfig config_;
  Tracer* tracer_;
  std::string name_;
  Tick t0_;
  Tracer::TrackId feederTrack_ = 0;  // created first: the drive's track is the next one (driveTrack())
  iop::Drive drive_;
  iop::SifChannel sif_;
  iop::StreamRing ring_;
  ee::Timeline timeline_;
  Event work_;
  ee::CompressedBuffer lmCompressed_;
  ee::CompressedBuffer skyCompressed_;
  ee::EeDemux demux_;
  ipu::IpuUnit ipu_;
  std::unique_ptr<ee::DecodedFrames> lmFrames_;
  std::unique_ptr<ee::DecodedFrames> skyFrames_;
  // Built after the frame buffers it fills, from the track created first (feederTrack_).
  std::unique_ptr<ee::IpuFeeder> feeder_;
  // The presenters read the decoded frames through these, which report each frame's arrival.
  std::unique_ptr<gs::RecordingSource> lmSource_;
  std::unique_ptr<gs::RecordingSource> skySource_;
  ArrivalHook arrivalHook_;
  SerialUnit gs_;  // the one GS both presenters draw on
  std::unique_ptr<gs::Presenter> lightmap_;
  std::unique_ptr<gs::Presenter> sky_;
  Tick lastBranchAt_ = -1;
  int lastBranchVariant_ = 0;
};

}  // namespace vbim::player
