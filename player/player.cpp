#include "player/player.hpp"

#include <algorithm>

#include "gs/lag_meter.hpp"
#include "player/frame_hash.hpp"

namespace vbim::player {

namespace {

// The run's presenter and the reference's follow each other (gs::Presenter::followTwin): whichever
// blends a tile second copies the other's; returns the tile facts they share with the lag.
std::unique_ptr<gs::TwinTiles> twins(gs::Presenter& run, gs::Presenter& reference, bool mirror) {
  auto tiles = std::make_unique<gs::TwinTiles>(run.blender().tileChanges().size());
  run.followTwin(reference, *tiles, /*runSide=*/true);
  reference.followTwin(run, *tiles, /*runSide=*/false, mirror);
  return tiles;
}

}  // namespace

Player::Player(iop::SectorSource& disc, const iop::DiscFile& file, PlayerOptions options)
    : options_(std::move(options)), stream_(ee::probeStream(disc, file)), tracer_(options_.trace) {
  validate(options_.config);
  for (const Branch& b : options_.branches) {
    if (b.variant < 0 || b.variant >= static_cast<int>(stream_.descriptor.variants.size())) {
      throw ConfigError("branch at " + std::to_string(toSeconds(b.at)) + " s to variant " + std::to_string(b.variant) +
                        ", but the stream has " + std::to_string(stream_.descriptor.variants.size()) + " variant(s)");
    }
  }
  main_ = std::make_unique<Pipeline>(sched_, disc, stream_, options_.config, &options_.faults, options_.seed,
                                     options_.kernels, &tracer_, "", /*hashChain=*/true);
  if (options_.reference && !options_.faults.faults.empty()) {
    // The reference's processes go first at any tick both pipelines share (runTo), from the start.
    const Scheduler::LaneScope first(sched_, Lane::First);
    ref_ = std::make_unique<Pipeline>(sched_, disc, stream_, options_.config, nullptr, options_.seed, options_.kernels,
                                      nullptr, "ref.");
    if (options_.shareDecodes) {
      decodes_ = std::make_unique<ipu::SharedDecodes>();
      main_->ipu().shareDecodes(*decodes_, 0);
      ref_->ipu().shareDecodes(*decodes_, 1);
      // Each BDEC stream (the two pipelines open the same streams in the same order) its own log.
      for (ipu::StreamId id = 0; id < main_->ipu().streamCount(); ++id) {
        if (main_->ipu().decodePath(id) != ipu::DecodePath::kBdec) continue;
        flowDecodes_.push_back(std::make_unique<ipu::SharedDecodes>(
            ipu::SharedDecodes::kDefaultMaxAhead, ipu::SharedDecodes::kDefaultMaxImageBytes, ipu::DecoderState::Kept));
        main_->ipu().shareFlowDecodes(id, *flowDecodes_.back(), 0);
        ref_->ipu().shareFlowDecodes(id, *flowDecodes_.back(), 1);
      }
    }
    const gs::BlendKernels& k = options_.kernels.blend != nullptr ? *options_.kernels.blend : gs::scalarKernels();
    if (options_.shareReference) {
      const bool mirror = options_.mirrorReference;
      lagTiles_ = twins(main_->lightmap(), ref_->lightmap(), mirror);
      if (main_->sky() != nullptr) skyLagTiles_ = twins(*main_->sky(), *ref_->sky(), mirror);
    }
    lagDiff_ =
        std::make_unique<gs::TiledDifference>(main_->lightmap(), ref_->lightmap(), k.compareRect, lagTiles_.get());
    if (main_->sky() != nullptr) {
      skyLagDiff_ =
          std::make_unique<gs::TiledDifference>(*main_->sky(), *ref_->sky(), k.compareRect, skyLagTiles_.get());
    }
  }
  for (const Branch& b : options_.branches) {
    main_->scheduleBranch(b.at, b.variant);
    if (ref_) ref_->scheduleBranch(b.at, b.variant);
  }
  if (tracer_.enabled()) lagCounter_ = tracer_.counter("player.lag");
  totals_.ringHistogram.assign(static_cast<std::size_t>(options_.config.iop.ring.bankmax) + 1, 0);
}

void Player::runTo(Tick t) {
  if (!started_) {
    started_ = true;
    // The reference's processes in the first lane: at every tick where both presenters blend, the
    // reference's blend comes first and can wait for the run's (gs::Presenter::followTwin,
    // mirroring). Spawn order alone kept that only until the two drifted apart within a tick: a run
    // with no frame yet (a stall at spin-up) finished its vsyncs first, and from then on its strips
    // were blended first at every tick, so a strip-mode reference never mirrored. The two pipelines
    // share no simulated state, and within a lane the order is as if the other did not exist
    // (runtime/scheduler.hpp), so the lanes change nothing in either.
    if (ref_) {
      const Scheduler::LaneScope first(sched_, Lane::First);
      ref_->start(options_.duration);
    }
    main_->start(options_.duration);
    sched_.spawn("player.record", record(*this));
  }
  sched_.runUntil(std::min(t, options_.duration));
  settleReference();  // the reference's lightmaps as they are, for whoever reads them now
}

// A reference blend still waiting for the run's is made (gs::Presenter::followTwin, mirroring).
void Player::settleReference() {
  if (!ref_) return;
  ref_->lightmap().settleTwin();
  if (ref_->sky() != nullptr) ref_->sky()->settleTwin();
}

void Player::onVsync(std::int64_t n) {
  gs::Presenter& lm = main_->lightmap();
  gs::Presenter* sky = main_->sky();
  VsyncRow row;
  row.vsync = n;
  row.lightmap = lm.last();
  row.at = row.lightmap.at;
  if (sky != nullptr) row.sky = sky->last();
  // An unchanged lightmap and sky (no byte moved: pop 0) keep the previous hash.
  const bool changed = !last_ || row.lightmap.pop != 0 || (row.sky && row.sky->pop != 0);
  if (changed) {
    // The lightmap's chain is folded as it is blended (gs::TiledBlender, hash mode); the sky follows.
    FrameHasher h(lm.hashChain());
    if (sky != nullptr) h.add(sky->lightmap());
    row.hash = h.digest();
  } else {
    row.hash = last_->hash;
  }
  if (ref_) {
    settleReference();  // every presenter presented vsync n: a blend still waiting will not be the run's
    // Only the tiles that either lightmap changed since the last vsync are compared again.
    row.lag = lagDiff_->update().max;
    if (skyLagDiff_) row.skyLag = skyLagDiff_->update().max;
  }
  row.ringBanks = main_->ring().visibleBanks();

  ++totals_.vsyncs;
  if (n > 0 && !row.lightmap.snapped) totals_.pop.offer(row.lightmap.pop, n, row.at);
  if (row.sky && n > 0 && !row.sky->snapped) totals_.skyPop.offer(row.sky->pop, n, row.at);
  totals_.lag.offer(row.lag, n, row.at);
  totals_.skyLag.offer(row.skyLag, n, row.at);
  totals_.ringMin = totals_.ringMin < 0 ? row.ringBanks : std::min(totals_.ringMin, row.ringBanks);
  totals_.ringMax = std::max(totals_.ringMax, row.ringBanks);
  totals_.ringSum += row.ringBanks;
  const auto bucket = static_cast<std::size_t>(
      std::clamp<std::int64_t>(row.ringBanks, 0, static_cast<std::int64_t>(totals_.ringHistogram.size()) - 1));
  ++totals_.ringHistogram[bucket];
  if (row.lightmap.behind) ++totals_.behindVsyncs;
  const bool newFrame = row.lightmap.targetSeq >= 0 && (!last_ || row.lightmap.targetSeq != last_->lightmap.targetSeq ||
                                                        row.lightmap.variant != last_->lightmap.variant);
  if (!row.lightmap.behind || newFrame) totals_.lastProgressAt = row.at;
  totals_.lastVsyncAt = row.at;
  totals_.endsBehind = row.lightmap.behind;
  if (tracer_.enabled() && ref_) tracer_.value(lagCounter_, row.at, row.lag);
  if (sink_) sink_(row, lm.lightmap(), sky ? &sky->lightmap() : nullptr);
  tracer_.advance(row.at);  // a streamed trace writes what is now final
  last_ = row;
}

// Waits until every presenter (run and reference) has presented vsync n, then records it.
Task<void> Player::record(Player& p) {
  const VsyncClock clock = p.main_->lightmap().clock();
  std::vector<gs::Presenter*> all{&p.main_->lightmap()};
  if (p.main_->sky()) all.push_back(p.main_->sky());
  if (p.ref_) {
    all.push_back(&p.ref_->lightmap());
    if (p.ref_->sky()) all.push_back(p.ref_->sky());
  }
  for (std::int64_t n = 0; clock.time(n) < p.options_.duration; ++n) {
    for (gs::Presenter* pr : all) {
      while (pr->presented() <= n) co_await pr->presentedEvent().wait();
    }
    p.onVsync(n);
  }
}

}  // namespace vbim::player
