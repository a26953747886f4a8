// The player: a whole run on one Scheduler. It probes the stream, builds the pipeline (and, when the
// fault plan is not empty, a fault-free reference pipeline with the same seed beside it, so the lag
// of every vsync is exact), and records every vsync: a 64-bit hash of the lightmap and sky, the
// presenters' records, pop, lag and ring occupancy. Rows stream to a sink as they happen, so memory
// does not grow with the run's length (nor does the trace when it is streamed to files).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "ee/stream_probe.hpp"
#include "gs/lag_meter.hpp"
#include "gs/twin_tiles.hpp"
#include "iop/fault_plan.hpp"
#include "iop/sector_source.hpp"
#include "ipu/ipu_unit_shared_decodes.hpp"
#include "player/frame_hash.hpp"
#include "player/pipeline.hpp"
#include "player/platform_config.hpp"
#include "runtime/scheduler.hpp"
#include "runtime/trace.hpp"

namespace vbim::player {

struct Branch {
  Tick at = 0;
  int variant = 0;
};

struct PlayerOptions {
  PlatformConfig config;
  iop::FaultPlan faults;  // empty: no faults (and no reference pipeline: the lag is zero by definition)
  std::uint64_t seed = 1;
  Tick duration = fromMs(10'000);  // vsyncs before this time are presented
  std::vector<Branch> branches;    // scheduled variant switches
  Kernels kernels;                 // SIMD kernels (null: scalar references; same bytes either way)
  bool trace = true;               // keep busy spans and counters for trace.json / signals.vcd
  bool reference = true;           // measure lag against a fault-free reference (only if faults exist)
  // The reference takes the run's host work where it is the same (issue #31): a tile the run blended
  // from the same bytes toward the same source with the same spec is copied, and tiles known equal
  // are not compared (gs/twin_tiles.hpp). false: the reference does all its own work. Same bytes.
  bool shareReference = true;
  // With shareReference: while every tile of the reference's lightmap (and sky) is known equal to
  // the run's, the reference writes none of its own and takes the run's blends as its own when they
  // are the same (gs::Presenter::followTwin, mirroring): no copy, no second blend. false: the
  // reference blends or copies each tile itself. Same bytes.
  bool mirrorReference = true;
  // The run's IPU and the reference's share the decode of each picture both are given after the
  // same history (ipu/ipu_unit_shared_decodes.hpp; intra pictures, and P and B pictures of a BDEC
  // stream while the two are in step): one decodes, the other takes its picture, and both
  // pipelines hold the same image. false: each IPU decodes every picture. Same bytes.
  bool shareDecodes = true;
};

// What happened at one vsync, over the whole output (lightmap + sky).
struct VsyncRow {
  std::int64_t vsync = 0;
  Tick at = 0;
  std::uint64_t hash = 0;
  gs::VsyncRecord lightmap;
  std::optional<gs::VsyncRecord> sky;
  int lag = 0;                 // largest per-byte difference from the reference lightmap (0 without faults)
  int skyLag = 0;              // the same for the sky
  std::int64_t ringBanks = 0;  // banks readable in the stream ring at the vsync
};

struct Extreme {
  int value = 0;
  std::int64_t vsync = -1;
  Tick at = 0;
  void offer(int v, std::int64_t n, Tick t) {
    if (v > value) {
      value = v;
      vsync = n;
      at = t;
    }
  }
};

// Aggregates over the rows recorded so far.
struct RunTotals {
  std::int64_t vsyncs = 0;
  Extreme pop;  // lightmap pop (excluding the first frame copied into the empty lightmap)
  Extreme skyPop;
  Extreme lag;
  Extreme skyLag;
  std::int64_t ringMin = -1, ringMax = 0, ringSum = 0;
  std::vector<std::int64_t> ringHistogram;  // vsyncs per number of readable banks
  std::int64_t behindVsyncs = 0;
  // For the run's health (player/report.hpp, runHealth): the last vsync, whether the lightmap was
  // behind schedule there, and the last vsync at which it was on schedule or took a new frame.
  Tick lastVsyncAt = 0;
  bool endsBehind = false;
  Tick lastProgressAt = 0;
};

class Player {
 public:
  using Sink = std::function<void(const VsyncRow&, const Rgba8Image& lightmap, const Rgba8Image* sky)>;

  // Probes the stream (throws streams::StreamProbeError), validates the options (ConfigError, GsError).
  Player(iop::SectorSource& disc, const iop::DiscFile& file, PlayerOptions options);
  Player(const Player&) = delete;
  Player& operator=(const Player&) = delete;

  void setSink(Sink sink) { sink_ = std::move(sink); }
  const Sink& sink() const { return sink_; }
  // Runs the simulation up to time t (at most to the duration). May be called repeatedly.
  void runTo(Tick t);
  void runToEnd() { runTo(options_.duration); }

  Tick now() const { return sched_.now(); }
  Tick duration() const { return options_.duration; }
  const ee::ProbedStream& stream() const { return stream_; }
  const PlayerOptions& options() const { return options_; }
  Pipeline& pipeline() { return *main_; }
  const Pipeline& pipeline() const { return *main_; }
  bool hasReference() const { return ref_ != nullptr; }
  Pipeline* reference() { return ref_.get(); }
  // With a reference and shareDecodes: what the two IPUs shared (tests), else null.
  const ipu::SharedDecodes* sharedDecodes() const { return decodes_.get(); }
  // The same for each BDEC stream (P and B pictures), empty without them.
  std::vector<const ipu::SharedDecodes*> sharedFlowDecodes() const {
    std::vector<const ipu::SharedDecodes*> all;
    for (const auto& d : flowDecodes_) all.push_back(d.get());
    return all;
  }
  const Tracer& tracer() const { return tracer_; }
  Tracer& tracer() { return tracer_; }  // e.g. to stream it to files (Tracer::streamTo) before the run
  const Scheduler& scheduler() const { return sched_; }
  const RunTotals& totals() const { return totals_; }
  const std::optional<VsyncRow>& lastRow() const { return last_; }
  const Rgba8Image& lightmap() const { return main_->lightmap().lightmap(); }
  const Rgba8Image* sky() const { return main_->sky() ? &main_->sky()->lightmap() : nullptr; }

 private:
  static Task<void> record(Player& p);
  void onVsync(std::int64_t n);
  void settleReference();

  PlayerOptions options_;
  ee::ProbedStream stream_;
  Scheduler sched_;
  Tracer tracer_;
  std::unique_ptr<ipu::SharedDecodes> decodes_;                   // outlives both pipelines' IPUs
  std::vector<std::unique_ptr<ipu::SharedDecodes>> flowDecodes_;  // so do these
  std::unique_ptr<Pipeline> main_;
  std::unique_ptr<Pipeline> ref_;
  // The lag of the lightmap and of the sky against the reference (with ref_ only), and the tiles of
  // each known equal in the two (with shareReference).
  std::unique_ptr<gs::TwinTiles> lagTiles_;
  std::unique_ptr<gs::TwinTiles> skyLagTiles_;
  std::unique_ptr<gs::TiledDifference> lagDiff_;
  std::unique_ptr<gs::TiledDifference> skyLagDiff_;
  Tracer::CounterId lagCounter_ = 0;
  Sink sink_;
  RunTotals totals_;
  std::optional<VsyncRow> last_;
  bool started_ = false;
};

}  // namespace vbim::player
