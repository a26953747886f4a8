// The vsync presenter: a cooperating process that, at every vsync, blends the lightmap in place
// toward the newest decoded frame that is due (gs/README.md, "Catch-up policies"). Stream frame k is due at
// t0 + k / fps. The GS work of a vsync is simulated in order: the IMAGE upload of a new frame over
// PATH3 into the staging texture, then the textured SPRITE with ALPHA (Cs, Cd, FIX, Cd) into the
// lightmap; in strip mode each horizontal strip is uploaded and drawn in turn, every vsync, through
// a staging area one strip high. The lightmap's pixels change when each draw completes.
//
// Catch-up when frames are late (CatchUp):
//   blend-through  target the newest due frame that is ready; while none is new, keep blending
//                  toward the last one (Hoffman & Mitchell, GDC 2001: "the frame interpolation process will continue
//                  unhindered ... smooth 'catch up' frames").
//   hard-skip      the same targets, but a frame that arrived late is copied in outright (FIX 128),
//                  skipping the in-between: the pop blend-through avoids.
//   play-late      never skip: show the next frame in sequence, and slip the schedule by however
//                  late it was; the lag stays.
// catchupFix > 0 blends with that FIX instead while behind (a due frame missing, or the target
// arrived late).
//
// Looping: seq k shows stream frame k % frameCount; the blend hides the jump from the last frame to
// the first. Branching: at a scheduled time the presenter asks the source for another variant from
// the next due frame on, at the same time of day; it keeps blending toward the old target until
// the new variant's frame arrives, then blends toward it.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "gs/blend.hpp"
#include "gs/draw_checks.hpp"
#include "gs/draw_setup.hpp"
#include "gs/frame_source.hpp"
#include "gs/gs_timing.hpp"
#include "gs/params.hpp"
#include "gs/tiled_blender.hpp"
#include "gs/vram.hpp"
#include "gs/vram_plan.hpp"
#include "runtime/event.hpp"
#include "runtime/scheduler.hpp"
#include "runtime/serial_unit.hpp"
#include "runtime/trace.hpp"
#include "runtime/vsync.hpp"

namespace vbim::gs {

// What happened at one vsync.
struct VsyncRecord {
  std::int64_t vsync = 0;
  Tick at = 0;
  std::int64_t dueSeq = -1;     // newest frame due (on the presenter's own, possibly slipped, schedule)
  std::int64_t targetSeq = -1;  // frame blended toward (-1: none yet)
  int variant = 0;
  int fix = 0;           // FIX used (128 for a copy)
  int pop = 0;           // largest per-byte change made to the lightmap
  bool behind = false;   // the newest due frame was not ready
  bool catchUp = false;  // blended toward a frame that arrived after it was due
  bool snapped = false;  // copied in (first frame, or hard skip)
  Tick gsBusy = 0;       // simulated GS time spent at this vsync
  Tick gsWait = 0;       // time waiting for a shared GS (PresenterOptions::gs) busy with another presenter
};

struct PresenterCounters {
  std::int64_t vsyncs = 0;
  std::int64_t framesShown = 0;     // distinct frames that became the target
  std::int64_t framesLate = 0;      // of those, ready after they were due
  std::int64_t framesCaughtUp = 0;  // late frames blended toward (not copied in): smooth catch-up
  std::int64_t framesDropped = 0;   // frames skipped over, never the target
  std::int64_t catchUpVsyncs = 0;   // vsyncs blending toward a late frame (catch-up frames)
  std::int64_t behindVsyncs = 0;    // vsyncs at which the newest due frame was not ready
  std::int64_t missedVsyncs = 0;    // vsyncs lost because the GS work of the previous one overran
  std::int64_t snaps = 0;           // frames copied in instead of blended
  std::int64_t loopWraps = 0;
  std::int64_t branches = 0;
  std::int64_t uploadBytes = 0;
  std::int64_t uploadTransfers = 0;    // IMAGE transfers: one per macroblock with gs.upload_strategy = macroblocks
  std::int64_t uploadSetupQwords = 0;  // their GIFtags and register writes
  std::int64_t tilesBlended = 0;       // host work (convergence-aware mode skips the rest)
  std::int64_t tilesSkipped = 0;
  std::int64_t tilesCopied = 0;       // taken from a twin instead of blended (followTwin)
  std::int64_t tilesMirrored = 0;     // blends the run made for this mirroring reference (followTwin)
  std::int64_t mirrorStops = 0;       // times the mirroring reference stopped (and took its own bytes back)
  std::int64_t mirrorRowsCopied = 0;  // lightmap rows it copied back from the run when it stopped
  Tick gsBusy = 0;
  Tick slip = 0;   // play-late: how far the schedule has slipped
  int maxPop = 0;  // largest pop, not counting the first frame copied into the empty lightmap
};

struct PresenterOptions {
  Tick t0 = 0;                            // when stream frame 0 is due
  const BlendKernels* kernels = nullptr;  // null: the scalar reference
  Tracer* tracer = nullptr;
  std::string name = "gs";  // trace track and counter prefix
  bool keepHistory = true;  // keep a VsyncRecord per vsync
  // Called after every vsync with its record and the lightmap as it now is (a frame sink: the
  // player writes lightmap frames from here; tests check invariants).
  std::function<void(const VsyncRecord&, const Rgba8Image&)> onVsync{};
  // The GS this presenter draws on, shared with the other presenters of the same console (one GIF,
  // one drawing engine: their work of a vsync runs one after the other). Null: a GS of its own.
  SerialUnit* gs = nullptr;
  // What this presenter blends. The lightmap presenter (console null) plans the console's VRAM
  // (planVram); given the sky stream's size in `sky`, the plan holds the sky's staging area too.
  // The sky presenter is given that plan in `console` (the lightmap presenter's vram(), copied) and
  // plans nothing: it draws into the plan's "sky" texture from its "sky staging" area.
  SkyTexture sky{};                     // the lightmap presenter only
  const VramLayout* console = nullptr;  // the sky presenter only
  // Keep the frame hash's chain of the lightmap up to date as it is blended (TiledBlender, hash
  // mode): hashChain() then costs only the tile rows the blend did not fold.
  bool hashChain = false;
};

class Presenter {
 public:
  // Checks the parameters and plans VRAM with checkParams (throws GsError on FIX outside 0..255,
  // unknown names, strip rows not a multiple of 32, a layout that does not fit), and throws GsError
  // for streams of different sizes.
  Presenter(Scheduler& sched, FrameSource& source, const GsParams& params, PresenterOptions options = {});

  // At the first vsync at or after `at`, switch to stream `variant` from the next due frame on.
  // Throws GsError if the source has no such stream.
  void scheduleBranch(Tick at, int variant);

  // The process: presents at vsyncs 0, 1, ... while their time is before `end`.
  Task<void> run(Tick end);

  // While mirroring (followTwin), the run's lightmap, which holds the same bytes.
  const Rgba8Image& lightmap() const { return mirror_ ? twin_->lightmap_ : lightmap_; }
  // The blender that writes the lightmap (nothing else does): its tileChanges() say which tiles moved.
  const TiledBlender& blender() const { return blender_; }
  // A run and its fault-free reference (issue #31; the player) follow each other: each records its
  // blends, and whichever blends a tile second copies the other's where the other made the blend it
  // is about to make from the same bytes (same source bytes and spec: TiledBlender::Twin), with the
  // facts of which tiles are equal in `equal` (runSide: this presenter's counts are its run side).
  // Same bytes, records and hash as blending; host time only. Call on both before either runs; the
  // twin must outlive this presenter's run.
  //
  // Mirroring: once every tile of the reference's lightmap is known equal to the run's, the
  // reference (runSide false) stops writing its own: lightmap() is then the run's, and each blend
  // it is asked for waits, in order, until the run blends. The run's next blend, if it is the
  // oldest waiting one (same source bytes, spec and rows), is taken as the reference's
  // (TiledBlender::takeTwinBlend: counts, pop, no bytes); anything else first gives the reference
  // its own bytes again (the run's copied, then the waiting blends made), and so does
  // settleTwin(). No copy and no second blend while the two agree; the same bytes, counts and pops
  // as blending. Not with a tracer or onVsync on the reference (their pop would be read before the
  // run's blend).
  // mirror false: the reference never mirrors (each blend made or copied as above).
  void followTwin(Presenter& twin, TwinTiles& equal, bool runSide, bool mirror = true);
  // The reference: the blends still waiting for the run's are made now (the run will not make it; the
  // player calls this once every presenter has presented a vsync, before reading the lightmaps).
  void settleTwin();
  bool mirroring() const { return mirror_; }
  // With PresenterOptions::hashChain: the frame hash's chain after the lightmap's header and bytes.
  const HashChain& hashChain() { return blender_.hashChain(lightmap_); }
  // The console's VRAM plan: this presenter's own (the lightmap's), or the one it was given (the sky's).
  const VramLayout& vram() const { return vram_; }
  // The register values of the draw that blends rows [y0, y1) of the picture (gs/draw_setup.hpp):
  // the whole picture in full upload mode, one strip of gs.strip_rows rows in strip mode.
  BlendDraw blendDraw(int y0, int y1) const;
  const PresenterCounters& counters() const { return counters_; }
  const std::vector<VsyncRecord>& history() const { return history_; }
  const VsyncRecord& last() const { return last_; }
  VsyncClock clock() const { return clock_; }
  // Number of vsyncs presented so far, and an event notified after each one.
  std::int64_t presented() const { return presented_; }
  int variant() const { return variant_; }  // the stream in force after the branches so far
  Event& presentedEvent() { return presentedEvent_; }

 private:
  struct Target {
    std::int64_t seq = -1;
    int variant = 0;
    bool late = false;
    std::shared_ptr<const Rgba8Image> image;
  };
  struct Branch {
    Tick at;
    int variant;
  };

  Task<void> present(std::int64_t vsync);
  Task<void> drawAll(const BlendSpec& spec, bool newTarget, VsyncRecord& rec);
  void takeTarget(const ReadyFrame& f, Tick scheduleT0, VsyncRecord& rec);
  void checkFrame(const ReadyFrame& f) const;
  void trace(const VsyncRecord& rec);
  static std::uint64_t sourceIdOf(const Target& t) {
    return (static_cast<std::uint64_t>(t.seq) << 16) ^ static_cast<std::uint64_t>(t.variant);
  }
  bool sameSourceAsTwin();
  // Mirroring (followTwin): a blend of the reference waiting for the run's.
  struct Waiting {
    std::shared_ptr<const Rgba8Image> source;
    BlendSpec spec;
    std::uint64_t sourceId = 0;
    int y0 = 0;
    int y1 = 0;
    std::int64_t vsync = 0;
    std::uint64_t generation = 0;  // of the reference's target
  };
  bool waitForTwin(const Rgba8Image& source, const BlendSpec& spec, std::uint64_t id, int y0, int y1);
  bool twinTakes(const Rgba8Image& source, const BlendSpec& spec, std::uint64_t id, int y0, int y1);
  void takeFromTwin();
  void stopMirroring();
  void addPop(std::int64_t vsync, int pop);

  Scheduler& sched_;
  FrameSource& source_;
  GsParams params_;
  PresenterOptions opt_;
  StreamInfo stream_;
  GsTiming timing_;
  VsyncClock clock_;
  BlendSpec spec_;
  BlendSpec catchupSpec_;
  CatchUp policy_;
  bool strips_;
  bool macroblockUploads_;
  bool sixteen_;  // gs.texture_format = ct16 (gs/blend16.hpp)
  VramLayout vram_;
  Rgba8Image lightmap_;
  Rgba8Image staging16_;  // the 16-bit path: the target as its PSMCT16 staging texture
  TiledBlender blender_;
  Target target_;
  std::uint64_t targetGeneration_ = 0;  // moves with every new target
  bool filled_ = false;
  // followTwin: the twin, the tile facts, and whether the two targets hold the same bytes, as last
  // found for the two targets' generations.
  Presenter* twin_ = nullptr;
  TwinTiles* twinTiles_ = nullptr;
  bool twinRunSide_ = false;
  std::uint64_t sameSeenTwin_ = ~std::uint64_t{0};
  std::uint64_t sameSeenOwn_ = ~std::uint64_t{0};
  bool sameSeen_ = false;
  bool mayMirror_ = false;
  // Where this presenter's GS work stands: the vsync and the end of the rows of its last blend (or
  // of the last it was asked for, mirroring), and of the one before that. Two presenters at the same
  // place have made the same blends since their targets last changed (mirroring's start rule).
  struct BlendPlace {
    std::int64_t vsync = -1;
    int y1 = 0;
    bool operator==(const BlendPlace&) const = default;
  };
  BlendPlace lastBlend_;
  BlendPlace prevBlend_;
  bool mirror_ = false;
  // While mirroring, the rows [mirrorRow0_, mirrorRow1_) hold every blend the run made for this
  // presenter: the only rows where its lightmap and this one's came apart since the mirror began.
  int mirrorRow0_ = 0;
  int mirrorRow1_ = 0;
  // The blends the reference was asked for and the run has not made yet, oldest first: the run's GS
  // work may run behind the reference's by some strips (e.g. when its sky goes first on the GS).
  // A vector read from waitingHead_ (emptied when all are read), not a deque: no allocation per
  // blend once it has held a vsync's strips.
  std::vector<Waiting> waiting_;
  std::size_t waitingHead_ = 0;
  bool waitingEmpty() const { return waitingHead_ == waiting_.size(); }
  const Waiting& waitingFront() const { return waiting_[waitingHead_]; }
  void popWaiting();
  // The run: whether its target holds the bytes of the reference's waiting blend's source, as last
  // found for the two generations (a frame's image does not change once decoded).
  std::uint64_t takeSeenOwn_ = ~std::uint64_t{0};
  std::uint64_t takeSeenTwin_ = ~std::uint64_t{0};
  bool takeSame_ = false;
  VsyncRecord* open_ = nullptr;  // the record of the vsync being presented (its pop may be added to)
  int variant_ = 0;
  std::vector<Branch> branches_;
  PresenterCounters counters_;
  std::vector<VsyncRecord> history_;
  VsyncRecord last_;
  std::int64_t presented_ = 0;
  Event presentedEvent_;
  Tracer::TrackId track_ = 0;
  Tracer::CounterId popCounter_ = 0, targetCounter_ = 0, lateCounter_ = 0, droppedCounter_ = 0, catchUpCounter_ = 0;
};

}  // namespace vbim::gs
