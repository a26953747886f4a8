// The EE thread that feeds the one IPU ("ee.ipu"): it takes complete pictures from the compressed
// frame buffers in timeline order (for each sequence number the lightmap picture, then the sky
// picture, so the sky stays in step with the lightmap), issues one IPU command per picture (one at a
// time: the EE serialises IPU_CMD) and pushes each decoded frame into its stream's decoded frame
// buffers, where the GS presenter finds it.
//
// EE time: ee.decode_setup_cycles per picture (DMA chains and IDEC) before the IPU's own time
// (docs/timing/ee.md, docs/timing/ipu.md). When the EE reorders the IPU's macroblocks into a raster
// image (gs.upload_strategy = ee-reorder), ee.reorder_cycles_per_qword per output quadword after it:
// the frame is ready once reordered, and the EE feeds the IPU nothing meanwhile.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>

#include "ee/ee_demux.hpp"
#include "ee/frame_buffers.hpp"
#include "ee/params.hpp"
#include "ee/timeline.hpp"
#include "ipu/ipu_unit.hpp"
#include "runtime/event.hpp"
#include "runtime/image_pool.hpp"
#include "runtime/scheduler.hpp"
#include "runtime/trace.hpp"

namespace vbim::ee {

struct DecodeCounters {
  std::int64_t pictures = 0;
  std::int64_t idecCommands = 0;          // IDEC issued: one per slice (the EE restarts it per slice)
  std::int64_t concealedMacroblocks = 0;  // kept their previous value: damage the IPU hid
  std::int64_t picturesWithIssues = 0;
  std::int64_t reorderedQwords = 0;  // moved by the EE from macroblock to raster order
  Tick reorderBusy = 0;              // EE time spent on it
  std::int64_t undecodable = 0;      // produced nothing usable (wrong size or no picture): not shown
  std::int64_t staleDropped = 0;     // decoded for a variant a branch left meanwhile
  Tick busy = 0;                     // IPU command time, start to last output qword
  Tick maxPerPicture = 0;
  std::array<Tick, 2> perStream{0, 0};  // summed per stream
  std::array<std::int64_t, 2> picturesPerStream{0, 0};
  ipu::IpuCommandCounts commands;  // every IPU command, by kind (IDEC path: idec only)
  Tick eeBusy = 0;                 // the EE's work in the BDEC flow of P and B pictures (ipu/bdec_flow_timing.hpp)
  // Streams with P and B pictures (the BDEC flow):
  std::int64_t bdecPictures = 0;             // pictures decoded by it
  std::int64_t picturesForReference = 0;     // decoded only as references of later frames (not shown)
  std::int64_t brokenReferencePictures = 0;  // P or B pictures decoded while a reference was lost or damaged
};

class IpuFeeder {
 public:
  // `in` and `out` are indexed by stream (kLightmap, kSky); a stream the file does not have has a
  // null decoded-frame buffer. `work` is the demux's "a picture was loaded" event. `tracer` is null
  // or enabled; `track` is the feeder's busy-span track in it. `reorder`: the EE reorders each
  // decoded picture from macroblock to raster order before it is ready.
  // `ipuStreams`: each stream's IPU stream (ipu::IpuUnit::openStream); a kBdec stream's decoded
  // frames come out in display order, each when the IPU has it due (ipu/ipu_unit.hpp).
  IpuFeeder(Scheduler& s, std::array<CompressedBuffer*, 2> in, std::array<DecodedFrames*, 2> out, const EeDemux& demux,
            const Timeline& timeline, ipu::IpuUnit& ipu, const EeParams& p, bool reorder, Event& work, Tracer* tracer,
            Tracer::TrackId track, std::array<ipu::StreamId, 2> ipuStreams = {});
  IpuFeeder(const IpuFeeder&) = delete;
  IpuFeeder& operator=(const IpuFeeder&) = delete;

  // The process: feeds the IPU forever.
  Task<void> run();
  // A branch from seq `fromSeq` took effect: a picture of that seq or later still being decoded
  // belongs to the variant left and is dropped when it comes out.
  void branch(std::int64_t fromSeq);

  const DecodeCounters& counters() const { return dc_; }
  // Called after each picture the IPU decoded, with its stream (kLightmap, kSky), its variant and
  // what the IPU reported (the command log when the IPU records commands: ipu::IpuUnit::recordCommands).
  using CommandHook = std::function<void(int stream, int variant, const CompressedPicture&, const ipu::TimedPicture&)>;
  void setCommandHook(CommandHook hook) { commandHook_ = std::move(hook); }

 private:
  // A picture the IPU has decoded, waiting to be shown (BDEC flow: the last I or P picture).
  struct Held {
    std::int64_t seq = 0;
    bool shown = false;
    std::uint64_t generation = 0;
  };
  Task<void> decodeOne(int stream);
  // After a decode: the frame now in `image` (the picture decoded, or the reference it displaced).
  std::optional<Held> displayed(int stream, const CompressedPicture& pic, std::uint64_t gen, bool produced);
  void countReferences(int stream, const CompressedPicture& pic, const ipu::PictureReport& report);
  bool active(int s) const { return out_[static_cast<std::size_t>(s)] != nullptr; }

  Scheduler& s_;
  std::array<CompressedBuffer*, 2> in_;
  std::array<DecodedFrames*, 2> out_;
  const EeDemux& demux_;
  const Timeline& timeline_;
  ipu::IpuUnit& ipu_;
  EeParams p_;
  bool reorder_;
  Event& work_;
  Tracer* tracer_;
  Tracer::TrackId track_;
  std::uint64_t generation_ = 0;
  std::int64_t lastBranchFrom_ = 0;
  DecodeCounters dc_;
  std::array<ImagePool, 2> images_;  // per stream, so a recycled buffer already has the size
  std::array<ipu::StreamId, 2> ipuStreams_;
  std::array<bool, 2> bdec_{false, false};
  std::array<std::optional<Held>, 2> held_;
  std::array<bool, 2> brokenChain_{false, false};  // since the last clean I picture, a reference was lost or damaged
  CommandHook commandHook_;
};

}  // namespace vbim::ee
