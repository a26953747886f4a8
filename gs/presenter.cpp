#include "gs/presenter.hpp"

#include <algorithm>
#include <cstring>

#include "gs/blend16.hpp"
#include "gs/error.hpp"

namespace vbim::gs {

namespace {

const StreamInfo& checkedStreams(const FrameSource& source) {
  const auto& s = source.streams();
  if (s.empty()) throw GsError("the frame source has no streams");
  for (std::size_t i = 1; i < s.size(); ++i) {
    if (s[i].width != s[0].width || s[i].height != s[0].height || s[i].frameCount != s[0].frameCount ||
        s[i].fpsNum * s[0].fpsDen != s[0].fpsNum * s[i].fpsDen) {
      throw GsError("stream " + std::to_string(i) + " '" + s[i].name + "' (" + std::to_string(s[i].width) + "x" +
                    std::to_string(s[i].height) + ", " + std::to_string(s[i].frameCount) +
                    " frames) does not match stream 0 '" + s[0].name + "' (" + std::to_string(s[0].width) + "x" +
                    std::to_string(s[0].height) + ", " + std::to_string(s[0].frameCount) +
                    " frames): variants must share size, length and rate to branch at the same time of day");
    }
  }
  if (s[0].frameCount <= 0 || s[0].fpsNum <= 0 || s[0].fpsDen <= 0) {
    throw GsError("stream 0 '" + s[0].name + "' needs a positive frame count and frame rate");
  }
  return s[0];
}

// The console's VRAM as this presenter sees it, checked for a stream of s's size: checkParams for
// the lightmap presenter, which plans it; checkSkyParams for the sky presenter, which is given it.
VramLayout checkedVram(const GsParams& p, const StreamInfo& s, const PresenterOptions& o) {
  return o.console == nullptr ? checkParams(p, s.width, s.height, o.sky)
                              : checkSkyParams(p, *o.console, s.width, s.height);
}

// The streams of `source` checked, and the parameters checked for their size before any member
// that needs them is built (so every error names its key).
const StreamInfo& checkedSource(const FrameSource& source, const GsParams& p, const PresenterOptions& o) {
  const StreamInfo& s = checkedStreams(source);
  checkedVram(p, s, o);
  return s;
}

// The spec as the 16-bit path draws it (gs/blend16.hpp): dithered unless a copy (FIX = 0x80).
BlendSpec withTexels(BlendSpec spec, bool sixteen) {
  spec.psmct16 = sixteen;
  spec.dither = sixteen && spec.fix != 0x80;
  return spec;
}

}  // namespace

Presenter::Presenter(Scheduler& sched, FrameSource& source, const GsParams& params, PresenterOptions options)
    : sched_(sched),
      source_(source),
      params_(params),
      opt_(std::move(options)),
      stream_(checkedSource(source, params, opt_)),
      timing_(params),
      clock_(clockFor(params)),
      spec_(withTexels(makeBlendSpec(params.fix, colclampFor(params), alphaFor(params)),
                       texturePsm(params) == Psm::Ct16)),
      catchupSpec_(withTexels(
          makeBlendSpec(params.catchup_fix == 0 ? params.fix : params.catchup_fix, spec_.colclamp, spec_.alpha),
          spec_.psmct16)),
      policy_(catchUpByName(params.catchup)),
      strips_(checkedStrips(params)),
      macroblockUploads_(checkedMacroblockUploads(params)),
      sixteen_(spec_.psmct16),
      vram_(checkedVram(params, stream_, opt_)),
      lightmap_(stream_.width, stream_.height),
      blender_(stream_.width, stream_.height, opt_.kernels != nullptr ? *opt_.kernels : scalarKernels(),
               params.convergence_aware, opt_.hashChain),
      presentedEvent_(sched) {
  if (opt_.tracer != nullptr && opt_.tracer->enabled()) {
    track_ = opt_.tracer->track(opt_.name);
    popCounter_ = opt_.tracer->counter(opt_.name + ".pop");
    targetCounter_ = opt_.tracer->counter(opt_.name + ".target_seq");
    lateCounter_ = opt_.tracer->counter(opt_.name + ".frames_late");
    droppedCounter_ = opt_.tracer->counter(opt_.name + ".frames_dropped");
    catchUpCounter_ = opt_.tracer->counter(opt_.name + ".catchup_vsyncs");
  }
}

BlendDraw Presenter::blendDraw(int y0, int y1) const {
  const BlendSurface surface = opt_.console != nullptr ? BlendSurface::Sky : BlendSurface::Lightmap;
  return blendDrawFor(vram_, params_, surface, lightmap_.width, lightmap_.height, y0, y1);
}

void Presenter::followTwin(Presenter& twin, TwinTiles& equal, bool runSide, bool mirror) {
  if (!twin.lightmap_.sameSize(lightmap_) || equal.size() != blender_.tileChanges().size()) {
    throw GsError("a presenter can follow only a twin of its own size (" + std::to_string(lightmap_.width) + "x" +
                  std::to_string(lightmap_.height) + "), not " + std::to_string(twin.lightmap_.width) + "x" +
                  std::to_string(twin.lightmap_.height));
  }
  twin_ = &twin;
  twinTiles_ = &equal;
  twinRunSide_ = runSide;
  mayMirror_ = mirror && !runSide;
  blender_.recordBlends();
}

void Presenter::settleTwin() {
  if (mirror_ && !waitingEmpty()) stopMirroring();
}

// The reference, asked to blend rows [y0, y1) of `source`: whether the blend waits for the run's
// (mirroring: every tile known equal to the run's, so the run's same blend gives this one's result).
bool Presenter::waitForTwin(const Rgba8Image& source, const BlendSpec& spec, std::uint64_t id, int y0, int y1) {
  if (!mayMirror_ || sixteen_ || twin_->sixteen_ || !params_.convergence_aware || !twin_->params_.convergence_aware ||
      !filled_ || !target_.image || &source != target_.image.get() || opt_.onVsync ||
      (opt_.tracer != nullptr && opt_.tracer->enabled())) {
    return false;
  }
  if (!mirror_) {
    // Not while the run shows another frame (a run behind after a stall): its next blend would stop
    // the mirror again at once, at every vsync until the two show the same frame. By number only:
    // a mirror that starts in vain costs nothing, and the run's blend is checked when it is taken.
    const Target& shown = twin_->target_;
    if (!shown.image || shown.seq != target_.seq || shown.variant != target_.variant) return false;
    // Nor while the run's GS work is not where this one's was before this blend: its last blend
    // must be this presenter's last (same vsync, same rows), so that its next is this one. A run
    // some strips behind (its EE had more to upload) or ahead would make every mirror stop at its
    // next blend. Only the place, not the tick: a run whose GS work of every vsync comes a fixed
    // time after the reference's (its sky drawn first) mirrors, its blends queued (waiting_). A run
    // that already made this blend in this tick is ahead too (the player puts the reference's
    // processes in the scheduler's first lane, so at a tick both blend, the reference asks first).
    if (twin_->lastBlend_ != prevBlend_) return false;
    const std::vector<std::uint64_t>& mine = blender_.tileChanges();
    const std::vector<std::uint64_t>& theirs = twin_->blender_.tileChanges();
    for (std::size_t i = 0; i < mine.size(); ++i) {
      if (!twinTiles_->equalAt(i, theirs[i], mine[i])) return false;
    }
    mirror_ = true;
    mirrorRow0_ = lightmap_.height;
    mirrorRow1_ = 0;
    blender_.forgetAllRecords();  // the run must not copy from bytes this presenter stops writing
  }
  waiting_.push_back(
      Waiting{target_.image, spec, id, y0, y1, open_ != nullptr ? open_->vsync : last_.vsync, targetGeneration_});
  return true;
}

// The run, about to blend rows [y0, y1) of `source`: whether the mirroring reference's oldest
// waiting blend is this very one (same rows, spec and source bytes). Otherwise the reference takes
// its own bytes back first, while the run's lightmap still holds the bytes it mirrors.
bool Presenter::twinTakes(const Rgba8Image& source, const BlendSpec& spec, std::uint64_t id, int y0, int y1) {
  if (twin_ == nullptr || !twin_->mirror_) return false;
  Presenter& ref = *twin_;
  if (!ref.waitingEmpty()) {
    const Waiting& w = ref.waitingFront();
    if (w.y0 == y0 && w.y1 == y1 && w.sourceId == id && w.spec == spec) {
      if (targetGeneration_ != takeSeenOwn_ || w.generation != takeSeenTwin_) {
        takeSeenOwn_ = targetGeneration_;
        takeSeenTwin_ = w.generation;
        takeSame_ = w.source.get() == &source || (w.source->sameSize(source) && w.source->pixels == source.pixels);
      }
      if (takeSame_) return true;
    }
  }
  ref.stopMirroring();
  return false;
}

// The reference, after the run made the oldest blend it waited for.
void Presenter::takeFromTwin() {
  const Waiting& w = waitingFront();
  const int pop = blender_.takeTwinBlend(twin_->blender_, *twinTiles_, twinRunSide_, w.sourceId, w.spec, w.y0, w.y1);
  const int ty0 = w.y0 / kTileHeight;
  const int ty1 = (std::min(w.y1, lightmap_.height) + kTileHeight - 1) / kTileHeight;
  counters_.tilesMirrored += static_cast<std::int64_t>(ty1 - ty0) * blender_.tilesX();
  mirrorRow0_ = std::min(mirrorRow0_, ty0 * kTileHeight);
  mirrorRow1_ = std::max(mirrorRow1_, std::min(ty1 * kTileHeight, lightmap_.height));
  const std::int64_t vsync = w.vsync;
  popWaiting();
  addPop(vsync, pop);
}

void Presenter::popWaiting() {
  waiting_[waitingHead_].source.reset();
  if (++waitingHead_ == waiting_.size()) {
    waiting_.clear();
    waitingHead_ = 0;
  }
}

// The reference takes its own bytes back: the run's as they are (the same), then the waiting blends
// in the order it was asked for them.
void Presenter::stopMirroring() {
  if (!mirror_) return;
  mirror_ = false;
  ++counters_.mirrorStops;
  // Every tile was equal to the run's when the mirror began, and the run changed only rows it
  // blended for this presenter (a blend it did not make for it stops the mirror first): those rows
  // are the bytes to take back, and only then are the settled marks stale (they were not kept
  // while mirroring). A mirror that took no blend left this presenter's bytes and marks as they
  // were. In a strip-mode fault play the mirror began and stopped at nearly every strip while the
  // run lagged (40,000 times in 60 s of a 512x512 play): a whole-lightmap copy and a full re-blend
  // each time were most of its CPU.
  if (mirrorRow1_ > mirrorRow0_) {
    const std::size_t rowBytes = static_cast<std::size_t>(lightmap_.width) * 4;
    std::memcpy(lightmap_.row(mirrorRow0_), twin_->lightmap_.row(mirrorRow0_),
                rowBytes * static_cast<std::size_t>(mirrorRow1_ - mirrorRow0_));
    counters_.mirrorRowsCopied += mirrorRow1_ - mirrorRow0_;
    blender_.invalidate();
  }
  for (; !waitingEmpty(); popWaiting()) {
    const Waiting& w = waitingFront();
    const TiledBlender::Result r = blender_.blend(lightmap_, *w.source, w.spec, w.sourceId, w.y0, w.y1);
    counters_.tilesBlended += r.tilesBlended;
    counters_.tilesSkipped += r.tilesSkipped;
    addPop(w.vsync, r.pop);
  }
}

// A blend that waited for the run adds its pop to the vsync it was asked at.
void Presenter::addPop(std::int64_t vsync, int pop) {
  if (open_ != nullptr && open_->vsync == vsync) {
    open_->pop = std::max(open_->pop, pop);  // present() takes it into the counters
    return;
  }
  if (last_.vsync == vsync) last_.pop = std::max(last_.pop, pop);
  if (opt_.keepHistory && !history_.empty() && history_.back().vsync == vsync) {
    history_.back().pop = std::max(history_.back().pop, pop);
  }
  counters_.maxPop = std::max(counters_.maxPop, pop);  // mirroring starts after the initial fill
}

// The twin's last blend was from its current target, and that target holds the bytes of this
// presenter's (compared once per pair of targets: a frame's image does not change once decoded).
bool Presenter::sameSourceAsTwin() {
  if (twin_ == nullptr || sixteen_ || !target_.image) return false;
  const Target& t = twin_->target_;
  if (!t.image || twin_->blender_.lastSourceId() != sourceIdOf(t)) return false;
  if (twin_->targetGeneration_ != sameSeenTwin_ || targetGeneration_ != sameSeenOwn_) {
    sameSeenTwin_ = twin_->targetGeneration_;
    sameSeenOwn_ = targetGeneration_;
    // Other frames are taken to differ without looking (a frame repeated under another number is
    // only not shared): half the comparisons, since the two take each new frame one after the other.
    sameSeen_ =
        t.seq == target_.seq && t.variant == target_.variant &&
        (t.image == target_.image || (t.image->sameSize(*target_.image) && t.image->pixels == target_.image->pixels));
  }
  return sameSeen_;
}

void Presenter::scheduleBranch(Tick at, int variant) {
  const auto& s = source_.streams();
  if (variant < 0 || variant >= static_cast<int>(s.size())) {
    std::string names;
    for (std::size_t i = 0; i < s.size(); ++i) names += (i ? ", " : "") + std::to_string(i) + " '" + s[i].name + "'";
    throw GsError("branch to stream " + std::to_string(variant) + ", which does not exist: the source has " +
                  std::to_string(s.size()) + " stream(s): " + names);
  }
  branches_.push_back(Branch{at, variant});
  std::stable_sort(branches_.begin(), branches_.end(), [](const Branch& a, const Branch& b) { return a.at < b.at; });
}

Task<void> Presenter::run(Tick end) {
  for (std::int64_t n = 0; clock_.time(n) < end;) {
    co_await sched_.until(clock_.time(n));
    co_await present(n);
    // The next vsync not already past: GS work that overruns a vsync period loses vsyncs.
    std::int64_t next = clock_.countAt(sched_.now());
    if (clock_.time(next) < sched_.now()) ++next;
    next = std::max(next, n + 1);
    counters_.missedVsyncs += next - n - 1;
    n = next;
  }
}

void Presenter::checkFrame(const ReadyFrame& f) const {
  if (!f.image || f.image->width != lightmap_.width || f.image->height != lightmap_.height ||
      f.image->pixels.size() != static_cast<std::size_t>(lightmap_.width) * lightmap_.height * 4) {
    const auto& s = source_.streams();
    const std::string name = f.variant >= 0 && f.variant < static_cast<int>(s.size()) ? s[f.variant].name : "?";
    throw GsError("frame seq " + std::to_string(f.seq) + " of stream " + std::to_string(f.variant) + " '" + name +
                  "' is " +
                  (f.image ? std::to_string(f.image->width) + "x" + std::to_string(f.image->height) : "empty") +
                  " but the lightmap is " + std::to_string(lightmap_.width) + "x" + std::to_string(lightmap_.height));
  }
}

void Presenter::takeTarget(const ReadyFrame& f, Tick scheduleT0, VsyncRecord& rec) {
  checkFrame(f);
  if (target_.seq >= 0) {
    if (f.seq > target_.seq + 1) counters_.framesDropped += f.seq - target_.seq - 1;
    if (params_.loop && f.seq / stream_.frameCount > target_.seq / stream_.frameCount) ++counters_.loopWraps;
  }
  target_ = Target{f.seq, f.variant, f.readyAt > dueTime(stream_, scheduleT0, f.seq), f.image};
  ++targetGeneration_;
  ++counters_.framesShown;
  if (target_.late) ++counters_.framesLate;
  rec.targetSeq = f.seq;
}

Task<void> Presenter::present(std::int64_t vsync) {
  const Tick now = sched_.now();
  VsyncRecord rec;
  rec.vsync = vsync;
  rec.at = now;
  open_ = &rec;

  while (!branches_.empty() && branches_.front().at <= now) {
    const int variant = branches_.front().variant;
    branches_.erase(branches_.begin());
    const std::int64_t from = dueSeq(stream_, opt_.t0 + counters_.slip, now) + 1;
    source_.branch(variant, from, now);
    variant_ = variant;
    ++counters_.branches;
  }

  const Tick scheduleBefore = opt_.t0 + counters_.slip;
  if (policy_ == CatchUp::PlayLate) {
    // Never skip: if the next frame is due but arrived late, shift the schedule so it is due now.
    const std::int64_t next = target_.seq + 1;
    if (dueTime(stream_, scheduleBefore, next) <= now) {
      const auto g = source_.newestReady(next, now);
      if (g && g->seq == next && g->readyAt > dueTime(stream_, scheduleBefore, next)) {
        counters_.slip = std::max(counters_.slip, now - dueTime(stream_, opt_.t0, next));
      }
    }
  }
  std::int64_t due = dueSeq(stream_, opt_.t0 + counters_.slip, now);
  if (!params_.loop) due = std::min(due, stream_.frameCount - 1);
  rec.dueSeq = due;
  const auto f = source_.newestReady(due, now);
  rec.behind = due >= 0 && (!f || f->seq < due);
  bool newTarget = false;
  if (f && (f->seq != target_.seq || f->variant != target_.variant)) {
    takeTarget(*f, scheduleBefore, rec);
    newTarget = true;
  }
  rec.targetSeq = target_.seq;
  rec.variant = target_.variant;
  if (rec.behind) ++counters_.behindVsyncs;

  const bool initialFill = target_.image && !filled_;
  if (target_.image) {
    rec.catchUp = target_.late;
    if (rec.catchUp) ++counters_.catchUpVsyncs;
    BlendSpec spec = spec_;
    if (!filled_ || (policy_ == CatchUp::HardSkip && newTarget && target_.late)) {
      spec.fix = 0x80;  // a copy: the first frame, or a hard skip
      spec.dither = false;
      rec.snapped = true;
      ++counters_.snaps;
    } else if (params_.catchup_fix > 0 && (rec.behind || target_.late)) {
      spec = catchupSpec_;
    }
    if (newTarget && target_.late && !rec.snapped) ++counters_.framesCaughtUp;
    rec.fix = spec.fix;
    co_await drawAll(spec, newTarget, rec);
    filled_ = true;
  }

  ++counters_.vsyncs;
  if (!initialFill) counters_.maxPop = std::max(counters_.maxPop, rec.pop);
  if (opt_.keepHistory) history_.push_back(rec);
  last_ = rec;
  open_ = nullptr;
  trace(rec);
  if (opt_.onVsync) opt_.onVsync(rec, lightmap_);
  presented_ = vsync + 1;
  presentedEvent_.notify();
}

Task<void> Presenter::drawAll(const BlendSpec& spec, bool newTarget, VsyncRecord& rec) {
  const int w = lightmap_.width;
  const int h = lightmap_.height;
  if (opt_.gs != nullptr) {
    const Tick asked = sched_.now();
    co_await opt_.gs->acquire();
    rec.gsWait = sched_.now() - asked;
  }
  const Tick start = sched_.now();
  const std::uint64_t id = sourceIdOf(target_);
  Tracer* tr = opt_.tracer != nullptr && opt_.tracer->enabled() ? opt_.tracer : nullptr;
  // In strip mode a vsync is 2 x strips spans of about a microsecond (32 for a 512x512 lightmap:
  // 700 MB of trace.json per simulated hour). Unless the trace keeps full detail they share one
  // label, so the tracer joins the vsync's back-to-back GS work into one `strips` span.
  const bool oneSpan = strips_ && tr != nullptr && tr->detail() != TraceDetail::Full;
  const char* uploadLabel = oneSpan ? "strips" : "upload";
  const char* blendLabel = oneSpan ? "strips" : "blend";
  // Full mode re-uploads only a new frame (the staging texture keeps it); strip mode has room for one
  // strip, so every vsync streams the whole frame through it again.
  const int rows = strips_ ? static_cast<int>(params_.strip_rows) : h;
  if (sixteen_ && newTarget) staging16FromRgb32(*target_.image, staging16_);  // the IPU's RGB16 output
  const Rgba8Image& source = sixteen_ ? staging16_ : *target_.image;
  for (int y0 = 0; y0 < h; y0 += rows) {
    const int y1 = std::min(h, y0 + rows);
    if (strips_ || newTarget) {
      const std::int64_t bytes = static_cast<std::int64_t>(w) * (y1 - y0) * (sixteen_ ? 2 : 4);
      // The IPU's 16x16 macroblocks one transfer each (the last row and column may be partial), or
      // the rows as one raster transfer. Strips are whole macroblock rows (32-row multiples).
      const std::int64_t transfers =
          macroblockUploads_ ? std::int64_t{(w + 15) / 16} * ((y1 - y0 + 15) / 16) : std::int64_t{1};
      const Tick t = sched_.now();
      co_await sched_.delay(timing_.imageTransfer(bytes, transfers));
      if (tr != nullptr) tr->span(track_, t, sched_.now(), uploadLabel);
      counters_.uploadBytes += bytes;
      counters_.uploadTransfers += transfers;
      counters_.uploadSetupQwords += timing_.setupQwords(transfers, bytes);
    }
    const Tick t = sched_.now();
    co_await sched_.delay(timing_.spriteDraw(w, y1 - y0));
    if (tr != nullptr) tr->span(track_, t, sched_.now(), blendLabel);
    TiledBlender::Result r;
    prevBlend_ = lastBlend_;
    lastBlend_ = BlendPlace{rec.vsync, y1};
    if (!waitForTwin(source, spec, id, y0, y1)) {
      // The run: a mirroring reference waiting for this blend takes it afterwards; else it has its
      // own bytes again by now, and the two share tiles as usual.
      const bool taken = twinTakes(source, spec, id, y0, y1);
      TiledBlender::Twin twin;
      const bool share = twin_ != nullptr && !taken;
      if (share) {
        twin = TiledBlender::Twin{&twin_->blender_, &twin_->lightmap_, twinTiles_, twinRunSide_, sameSourceAsTwin()};
      }
      r = blender_.blend(lightmap_, source, spec, id, y0, y1, share ? &twin : nullptr);
      if (taken) twin_->takeFromTwin();
    }
    rec.pop = std::max(rec.pop, r.pop);
    counters_.tilesBlended += r.tilesBlended;
    counters_.tilesSkipped += r.tilesSkipped;
    counters_.tilesCopied += r.tilesCopied;
  }
  rec.gsBusy = sched_.now() - start;
  counters_.gsBusy += rec.gsBusy;
  if (opt_.gs != nullptr) opt_.gs->release();
}

void Presenter::trace(const VsyncRecord& rec) {
  Tracer* tr = opt_.tracer;
  if (tr == nullptr || !tr->enabled()) return;
  const Tick t = sched_.now();
  tr->value(popCounter_, t, rec.pop);
  tr->value(targetCounter_, t, rec.targetSeq);
  tr->value(lateCounter_, t, counters_.framesLate);
  tr->value(droppedCounter_, t, counters_.framesDropped);
  tr->value(catchUpCounter_, t, counters_.catchUpVsyncs);
  if (rec.snapped) tr->instant(track_, t, "snap");
}

}  // namespace vbim::gs
