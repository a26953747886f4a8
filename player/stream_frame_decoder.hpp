// The frames of one stream as the player's IPU decodes them, for `vbim replay` (which has no IPU on
// its clock, only the frames): frame g of the stream, in RGB32 at the stream's size.
//
// An intra-only stream: each picture decoded on its own, as the IDEC path does (a fresh frame store,
// so a concealed macroblock is mid-grey). A stream with P and B pictures: as the BDEC flow does, in
// decode order from the GOP-opening I picture at or before g (ee/decode_order.hpp), B pictures before
// g skipped; consecutive frames continue the same run, so a replay decodes each picture about once.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "ee/decode_order.hpp"
#include "ipu/frame_store.hpp"
#include "ipu/picture_decoder.hpp"
#include "runtime/image.hpp"
#include "streams/descriptor.hpp"

namespace vbim::player {

class StreamFrameDecoder {
 public:
  // The picture of a global frame, or an empty span when the file lacks it (damage).
  using PictureSource = std::function<std::span<const std::uint8_t>(std::uint32_t globalFrame)>;

  StreamFrameDecoder(const streams::Descriptor& d, int streamIndex, ipu::DecoderOptions options,
                     PictureSource pictures);

  // Frame g into `out` (resized to the stream's size). False when a picture g needs is missing; `out`
  // then holds what the decoder made of the rest (all zero when g's own picture is missing).
  bool decode(std::uint32_t g, Rgba8Image& out);

  // Frame g in YCbCr as the IPU holds it (whole macroblocks), with its display size: what a CSC of
  // the frame converts. Empty when the decoder produced no such frame.
  struct Frame {
    ipu::FrameStore store;
    int width = 0;
    int height = 0;
    bool complete = true;  // every picture it needs was there
  };
  std::optional<Frame> frame(std::uint32_t g);

 private:
  bool decodeIntra(std::uint32_t g, Rgba8Image& out);
  void restart(std::int64_t variant, std::int64_t frame);
  // Decodes the next picture of the run; false at the run's end (after the last frame is out).
  bool step(std::int64_t wanted);
  void keep(std::int64_t frame);

  streams::Descriptor descriptor_;
  int width_ = 0;
  int height_ = 0;
  ee::DecodeOrder order_;
  ipu::DecoderOptions options_;
  PictureSource pictures_;
  // The run in progress (a stream with P and B pictures).
  std::unique_ptr<ipu::Decoder> decoder_;
  std::int64_t variant_ = -1;
  std::int64_t runStart_ = 0;
  std::int64_t nextRank_ = 0;
  std::int64_t held_ = -1;               // the reference decoded last, shown when the next one is decoded
  bool missing_ = false;                 // a picture of the run was missing
  std::map<std::int64_t, Frame> ready_;  // frames of the run that came out, not yet asked for
};

}  // namespace vbim::player
