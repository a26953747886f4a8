#include "player/stream_frame_decoder.hpp"

#include <utility>

#include "ipu/csc.hpp"
#include "ipu/kernels.hpp"

namespace vbim::player {

StreamFrameDecoder::StreamFrameDecoder(const streams::Descriptor& d, int streamIndex, ipu::DecoderOptions options,
                                       PictureSource pictures)
    : descriptor_(d), order_(d, streamIndex), options_(options), pictures_(std::move(pictures)) {
  const streams::StreamEntry& e = d.streams[static_cast<std::size_t>(streamIndex)];
  width_ = e.width;
  height_ = e.height;
}

bool StreamFrameDecoder::decodeIntra(std::uint32_t g, Rgba8Image& out) {
  const std::span<const std::uint8_t> bytes = pictures_(g);
  if (bytes.empty()) return false;
  ipu::Decoder decoder(options_);
  ipu::decodeToRgba(decoder, bytes, out);
  return true;
}

void StreamFrameDecoder::restart(std::int64_t variant, std::int64_t frame) {
  variant_ = variant;
  runStart_ = order_.resumeFrame(static_cast<int>(variant), frame);
  nextRank_ = runStart_;
  held_ = -1;
  missing_ = false;
  ready_.clear();
  decoder_ = std::make_unique<ipu::Decoder>(options_);
}

void StreamFrameDecoder::keep(std::int64_t frame) {
  const ipu::FrameStore* shown = decoder_->displayFrame();
  if (frame < 0 || shown == nullptr) return;
  ready_[frame] = Frame{*shown, decoder_->displayWidth(), decoder_->displayHeight(), !missing_};
}

bool StreamFrameDecoder::step(std::int64_t wanted) {
  const auto frames = static_cast<std::int64_t>(descriptor_.framesPerVariant);
  const auto v = static_cast<int>(variant_);
  if (nextRank_ >= frames) {
    // The run's end: the last reference leaves as the stream's end makes it (Decoder::flushDisplay).
    if (held_ >= 0 && decoder_->flushDisplay()) keep(std::exchange(held_, -1));
    return false;
  }
  const std::int64_t f = order_.frameAtRank(v, nextRank_++, runStart_);
  const std::int64_t g = variant_ * frames + f;
  // A B picture before the frame asked for is no one's reference: the player's demux skips it too.
  if (f < wanted && order_.type(g) == streams::PictureType::B) return true;
  const std::span<const std::uint8_t> bytes = pictures_(static_cast<std::uint32_t>(g));
  if (bytes.empty()) {
    missing_ = true;
    return true;
  }
  const ipu::PictureReport report = decoder_->decode(bytes);
  if (!report.produced) return true;
  if (order_.type(g) == streams::PictureType::B) {
    keep(f);
  } else {
    keep(std::exchange(held_, f));
  }
  return true;
}

std::optional<StreamFrameDecoder::Frame> StreamFrameDecoder::frame(std::uint32_t g) {
  if (order_.intraOnly()) {
    const std::span<const std::uint8_t> bytes = pictures_(g);
    if (bytes.empty()) return std::nullopt;
    ipu::Decoder decoder(options_);
    if (!decoder.decode(bytes).produced) return std::nullopt;
    return Frame{decoder.frame(), decoder.width(), decoder.height(), true};
  }
  const auto frames = static_cast<std::int64_t>(descriptor_.framesPerVariant);
  const std::int64_t v = g / frames;
  const std::int64_t f = g % frames;
  // Continue the run when frame f is still ahead in it; otherwise start one at f's GOP.
  const bool ahead =
      decoder_ && v == variant_ && f >= runStart_ &&
      (ready_.count(f) != 0 || held_ == f || order_.rank(static_cast<int>(v), f, runStart_) >= nextRank_);
  if (!ahead) restart(v, f);
  while (ready_.count(f) == 0 && step(f)) {
  }
  ready_.erase(ready_.begin(), ready_.lower_bound(f));
  const auto it = ready_.find(f);
  if (it == ready_.end()) return std::nullopt;
  return it->second;
}

bool StreamFrameDecoder::decode(std::uint32_t g, Rgba8Image& out) {
  if (out.width != width_ || out.height != height_) out = Rgba8Image(width_, height_);
  if (order_.intraOnly()) return decodeIntra(g, out);
  const std::optional<Frame> f = frame(g);
  if (!f) return false;
  const ipu::Kernels& kernels = options_.kernels != nullptr ? *options_.kernels : ipu::scalarKernels();
  ipu::convertToRgba32(f->store, f->width, f->height, {}, out, kernels.cscRow);
  return f->complete;
}

}  // namespace vbim::player
