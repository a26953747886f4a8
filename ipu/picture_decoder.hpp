// The IPU's picture decoder as a plain function of bytes: headers (sequence, GOP, picture and
// their extensions, the SETIQ matrices), then every slice of the picture (IDEC), into a frame
// store that persists between pictures for concealment. No timing here: ipu/ipu_unit.hpp puts
// this on the simulated clock.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "ipu/csc.hpp"
#include "ipu/decode_report.hpp"
#include "ipu/frame_store.hpp"
#include "ipu/headers.hpp"
#include "ipu/inter_slice_decoder.hpp"
#include "ipu/reference_frames.hpp"
#include "ipu/slice_decoder.hpp"

namespace vbim {
class WorkerPool;
}

namespace vbim::ipu {

// Runs fn(0) .. fn(count - 1), possibly on several host threads, and returns when all are done.
// The decoder core stays free of the kernel; vbim::WorkerPool is adapted in ipu/pool_runner.cpp.
class SliceRunner {
 public:
  virtual ~SliceRunner() = default;
  virtual unsigned threads() const = 0;  // besides the caller
  virtual void run(std::size_t count, const std::function<void(std::size_t)>& fn) = 0;
};

struct DecoderOptions {
  int maxWidth = 4096;  // larger sizes are reported as absurd (MPEG-2 MP@HL is 1920x1152)
  int maxHeight = 4096;
  // The IPU's IDP field holds 8, 9 or 10 bits; 11 bits is invalid there and PCSX2 treats it as 9
  // (docs/hardware.md#idec). By default we decode 11-bit DC precision as the standard says.
  bool dcPrecision11AsNine = false;
  bool recordMacroblocks = false;  // fill macroblockTrace() for the timing model
  // Each decode starts from a mid-grey store (Y = Cb = Cr = 128), so what it conceals is mid-grey
  // instead of the previous picture's: the player's IpuUnit, which decodes two streams in turn.
  bool freshStorePerDecode = false;
  const Kernels* kernels = nullptr;  // null: scalarKernels(); any choice gives the same bytes
  IdctKind idct = kDefaultIdct;      // which inverse DCT (ipu/kernels.hpp; platform parameter ipu.idct)
};

// RGB32 output written by the decode itself (alpha 0x80, SETTH thresholds): after each picture the
// image holds the conversion of the frame store. With a runner, each job of a frame picture
// converts the rows it decoded, so the conversion is split across the threads with the decode.
struct RgbaOutput {
  Rgba8Image* image = nullptr;
  CscThresholds thresholds;
  bool wholeMacroblocks = false;  // the padded store's size (the IPU's output) instead of the display size
};

class Decoder {
 public:
  explicit Decoder(DecoderOptions options = {});

  // Decodes every header and slice in `bytes` (normally one picture with the headers before it;
  // see ipu/elementary_stream.hpp). With a runner, the slices of an MPEG-2 picture are decoded in
  // parallel; the result is bit-identical to the serial decode.
  PictureReport decode(std::span<const std::uint8_t> bytes, SliceRunner* runner = nullptr);
  // The same, also converting to RGB32 into rgba.image (left unchanged if no picture is produced).
  PictureReport decode(std::span<const std::uint8_t> bytes, SliceRunner* runner, const RgbaOutput& rgba);
  // The same on a kernel worker pool (defined in ipu/pool_runner.cpp, library vbim_ipu).
  PictureReport decode(std::span<const std::uint8_t> bytes, WorkerPool& pool);

  // The frame the last picture was decoded into (decode order; a field picture fills half of it).
  const FrameStore& frame() const { return frames_.current(); }
  // Display order (§6.1.1.11): the frame that became due for display during the last decode(), or
  // null (an I or P frame waits for the next I or P frame; the first field of a frame waits for the
  // second). With several pictures in one decode() call, only the last frame due is kept.
  const FrameStore* displayFrame() const { return frames_.display(); }
  int displayWidth() const { return frames_.displayWidth(); }
  int displayHeight() const { return frames_.displayHeight(); }
  // End of the stream, called until it returns false: each call makes the next frame still due
  // the display frame (a frame left waiting for its second field, then the last I or P frame).
  bool flushDisplay();
  bool hasSequence() const { return haveSequence_; }
  // A first field waits for its second: the next field picture of the other parity fills its frame
  // (ipu/ipu_unit_shared_decodes.hpp: then a picture after a sequence header still depends on the past).
  bool fieldPending() const { return pendingField_ != 0; }
  // Takes `other`'s whole state (headers, frame stores, the frame due for display), as if this
  // decoder had decoded what it did: the next decode of the same bytes gives the same result. Not
  // while `other` has a field pending (its frame's concealment source is one of its own stores).
  // Shared decodes of the BDEC flow (ipu/ipu_unit_shared_decodes.hpp) bring a stale decoder up to
  // date this way instead of decoding its pictures again.
  void copyStateFrom(const Decoder& other);
  const SequenceHeader& sequence() const { return seq_; }
  const PictureHeader& picture() const { return pic_; }
  // Display size of the picture last decoded into frame() (0 before the first). A sequence header
  // or extension read after it may announce another size (sequence().width): frame() is only
  // resized, and so only cropped to the new size, when a picture of that sequence is decoded.
  int width() const { return frameWidth_; }
  int height() const { return frameHeight_; }
  const std::vector<MacroblockBits>& macroblockTrace() const { return trace_; }
  const Kernels& kernels() const { return options_.kernels ? *options_.kernels : scalarKernels(); }

 private:
  struct Slice {
    int code;
    int row;
    std::size_t begin;
    std::size_t end;
  };
  void beginPicture(PictureReport& report, std::size_t offset);
  void beginFrame(int codingType, int mbw, int mbh);
  void completeFrame();
  void concealMissing(const std::vector<int>& rows, const RgbaOutput* rgba);
  void finishPicture(std::span<const std::uint8_t> bytes, PictureReport& report, SliceRunner* pool,
                     const RgbaOutput* rgba);
  void handleExtension(BitReader& br, PictureReport& report, std::size_t offset);
  // Decodes slices_[first, last); with `rgba`, then converts the lines of their rows (first to last).
  void decodeSlices(std::span<const std::uint8_t> bytes, std::size_t first, std::size_t last, const SliceOutput& out,
                    const RgbaOutput* rgba);
  void convertLines(int y0, int y1, const RgbaOutput& rgba) const;  // lines [y0, y1), clipped to the image

  DecoderOptions options_;
  SequenceHeader seq_;
  PictureHeader pic_;
  bool haveSequence_ = false;
  bool pictureOpen_ = false;   // a picture header was seen and not finished
  bool pictureValid_ = false;  // it can be decoded
  bool sawSlice_ = false;
  PictureParams params_;
  InterParams inter_;
  bool interPicture_ = false;  // P or B: slices go to decodeInterSlice()
  FrameBuffers frames_;
  int pendingField_ = 0;                     // picture_structure of a first field waiting for its second (0: none)
  int frameType_ = 0;                        // picture_coding_type of the frame being decoded (its first field's)
  const FrameStore* concealFrom_ = nullptr;  // where macroblocks no slice decoded are copied from
  int concealedBefore_ = 0;                  // report.macroblocksConcealed when the picture began
  bool clearFrame_ = false;                  // the next picture starts from a mid-grey store (freshStorePerDecode)
  int frameWidth_ = 0;                       // display size of the picture the store holds
  int frameHeight_ = 0;
  std::vector<Slice> slices_;
  std::vector<std::uint8_t> decoded_;  // per macroblock (row stride decodedStride_): 1 once decoded
  int decodedStride_ = 0;
  // Slice-parallel decode: first slice of each job (plus the end), and each job's own results on
  // its own cache lines.
  struct alignas(64) JobResult {
    PictureReport report;
    std::vector<MacroblockBits> trace;
  };
  std::vector<std::size_t> jobStarts_;
  std::vector<JobResult> jobResults_;
  std::vector<MacroblockBits> trace_;
};

// Decodes one picture and, if one was produced, converts it to RGB32 (alpha 0x80, SETTH
// thresholds, display size) with the decoder's kernels. `out` is left unchanged otherwise.
PictureReport decodeToRgba(Decoder& decoder, std::span<const std::uint8_t> bytes, Rgba8Image& out,
                           CscThresholds th = {}, SliceRunner* runner = nullptr);
// The same, slice-parallel on a kernel worker pool (ipu/pool_runner.cpp).
PictureReport decodeToRgba(Decoder& decoder, std::span<const std::uint8_t> bytes, Rgba8Image& out, WorkerPool& pool,
                           CscThresholds th = {});

}  // namespace vbim::ipu
