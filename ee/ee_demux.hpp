// The EE demux thread: pulls sectors from the IOP stream ring over SIF (sceCdStRead), parses packs
// and PES (streams::Demuxer), assembles each picture of the lightmap and sky streams, and copies a
// complete picture into that stream's compressed frame buffer, then goes on loading the next one
// at once ("Once a frame has been fully loaded into the stream buffer, it is copied into the
// compressed frame buffer, and the next frame begins to load immediately", Hoffman & Mitchell, GDC 2001).
//
// It follows the descriptor: it knows which global frame each stream needs next (Timeline), takes
// only those pictures, and when every stream has finished the frames before a discontinuity (the
// loop wrap, a branch) it seeks the ring to the indexed sector of the next ones (docs/stream-format.md
// "Variants"). Damage does not stop it: a picture lost to damage is skipped and counted; a damaged
// picture that is still identified goes to the IPU, which conceals what it cannot decode.
//
// EE time: ee.cycles_per_pack + ee.cycles_per_byte x 2048 per sector parsed, and
// ee.copy_cycles_per_qword per 16 bytes copied into the compressed frame buffer (docs/timing/ee.md).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "ee/decode_order.hpp"
#include "ee/frame_buffers.hpp"
#include "ee/params.hpp"
#include "ee/stream_probe.hpp"
#include "ee/timeline.hpp"
#include "iop/stream_ring.hpp"
#include "runtime/event.hpp"
#include "runtime/scheduler.hpp"
#include "runtime/trace.hpp"
#include "streams/demuxer.hpp"

namespace vbim::ee {

inline constexpr int kLightmap = 0;
inline constexpr int kSky = 1;

struct DemuxCounters {
  std::int64_t reads = 0;       // sceCdStRead calls
  std::int64_t emptyReads = 0;  // calls that returned no sector (underrun seen by the EE)
  std::int64_t readErrors = 0;  // calls whose result carried an error code (not counting 273)
  std::int64_t sectors = 0;     // sectors parsed
  std::int64_t bytes = 0;       // bytes received from the ring
  std::int64_t seeks = 0;       // ring seeks (loop wraps, branches, recovery)
  std::int64_t loopSeeks = 0;
  std::int64_t picturesLoaded = 0;        // copied into a compressed frame buffer
  std::int64_t picturesIgnored = 0;       // not needed (other variant, before the one wanted)
  std::int64_t picturesDamaged = 0;       // loaded although they disagree with the index
  std::int64_t picturesUnidentified = 0;  // assembled but not at an indexed position
  std::int64_t framesLost = 0;            // needed frames that never arrived (damage)
  std::int64_t picturesForReference = 0;  // loaded only as references of a frame shown later (a branch into a GOP)
  std::int64_t streamErrors = 0;          // defects the reader reported
  std::int64_t overDepth = 0;   // pictures stored beyond ee.compressed_frames (one stream ran ahead in the mux)
  std::int64_t overBudget = 0;  // pictures dropped: ee.compressed_budget_kib was full (their frames lost)
  Tick busy = 0;                // EE time spent parsing and copying
};

class EeDemux {
 public:
  EeDemux(Scheduler& s, iop::StreamRing& ring, const ProbedStream& stream, Timeline& timeline, const EeParams& p,
          std::array<CompressedBuffer*, 2> buffers, Event& work, Tracer* tracer);

  // The process: starts the ring at the file's first sector and demuxes forever.
  Task<void> run();
  // A branch from seq `from`: the frames already loaded from there on are gone; reposition.
  void branch(std::int64_t from);

  const DemuxCounters& counters() const { return c_; }
  const streams::Demuxer& reader() const { return demux_; }
  // The decode-order key of the next picture stream `stream` must load (ee/decode_order.hpp).
  std::int64_t nextKey(int stream) const { return next_[stream]; }
  const DecodeOrder& order(int stream) const { return order_[static_cast<std::size_t>(stream)]; }

 private:
  // The picture stream s needs at decode-order key `key`: the seq it is shown at, its global frame,
  // whether it is shown, and whether it can be skipped (a B picture before a branch's first frame).
  struct Want {
    std::int64_t seq = 0;
    std::int64_t frame = 0;
    bool shown = true;
    bool skip = false;
  };
  // The run a key belongs to: decoding starts at frame `start` of `variant` (a GOP-opening I) and
  // shows frames from `showFrom`; key = base + rank, seq = base + frame.
  struct Run {
    int variant = 0;
    std::int64_t base = 0;
    std::int64_t start = 0;
    std::int64_t showFrom = 0;
    std::int64_t startKey = 0;
  };
  Run runOf(int s, std::int64_t key) const;
  Want want(int s, std::int64_t key) const;
  // The first key >= key that is not skipped.
  std::int64_t wanted(int s, std::int64_t key) const;
  // The key of global frame g in the run of `key`, if it lies in that run.
  std::optional<std::int64_t> keyOfFrame(int s, std::int64_t key, std::int64_t g) const;
  // True when key's picture comes after key - 1's in the file with no seek (within one run).
  bool followsInFile(int s, std::int64_t key) const;
  Task<void> route(streams::Picture& pic);
  void checkReposition();
  bool active(int s) const { return streamIndex_[s] >= 0; }
  std::int64_t indexSector(int s, std::int64_t globalFrame) const;
  // Reading up to (not including) this sector completes every picture of `variant` in stream s.
  std::int64_t variantEndSector(int s, int variant) const;

  Scheduler& s_;
  iop::StreamRing& ring_;
  const ProbedStream& stream_;
  Timeline& timeline_;
  EeParams p_;
  std::array<CompressedBuffer*, 2> buffers_;
  std::array<int, 2> streamIndex_;
  Tracer* tracer_;
  Tracer::TrackId track_ = 0;
  Event& work_;  // notified when a picture was loaded or the wanted frames changed (wakes the IPU feeder)
  streams::Demuxer demux_;
  std::vector<std::uint8_t> buf_;
  std::array<DecodeOrder, 2> order_;
  // Branches in force, by seq they take effect from: the first key of the run each one starts, per stream.
  std::map<std::int64_t, std::array<std::int64_t, 2>> branchRuns_;
  std::array<bool, 2> lost_{false, false};      // a picture was lost since the last one loaded
  std::array<std::int64_t, 2> next_{0, 0};      // next key each stream must load
  std::array<bool, 2> positioned_{true, true};  // the read position was set for next_[s] (start, seek)
  std::int64_t pos_ = 0;                        // next sector of the file the ring delivers
  std::int64_t seekTo_ = -1;                    // pending reposition (file sector)
  std::uint64_t generation_ = 0;                // bumped by a branch: pictures in flight are stale
  std::array<std::int64_t, 2> lastBranchKey_{0, 0};
  DemuxCounters c_;
};

}  // namespace vbim::ee
