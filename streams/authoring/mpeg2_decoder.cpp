#include "streams/authoring/mpeg2_decoder.hpp"

#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>

#include "streams/authoring/error.hpp"
#include "streams/authoring/libav.hpp"

namespace vbim::streams {

Mpeg2Decoder::Mpeg2Decoder() {
  const AVCodec* codec = avcodec_find_decoder(AV_CODEC_ID_MPEG2VIDEO);
  if (!codec) throw AuthoringError("libavcodec has no MPEG-2 video decoder");
  ctx_ = avcodec_alloc_context3(codec);
  ctx_->flags |= AV_CODEC_FLAG_BITEXACT;
  ctx_->err_recognition = AV_EF_EXPLODE;
  if (int r = avcodec_open2(ctx_, codec, nullptr); r < 0) throw AuthoringError("MPEG-2 decoder: " + avError(r));
  frame_ = av_frame_alloc();
  pkt_ = av_packet_alloc();
}

Mpeg2Decoder::~Mpeg2Decoder() {
  av_packet_free(&pkt_);
  av_frame_free(&frame_);
  avcodec_free_context(&ctx_);
}

Yuv420Image Mpeg2Decoder::decodeYuv(std::span<const std::uint8_t> picture) {
  // Each picture is sent alone and the decoder drained, so it returns this picture (intra, no delay).
  if (av_new_packet(pkt_, static_cast<int>(picture.size())) < 0) throw AuthoringError("out of memory");
  std::memcpy(pkt_->data, picture.data(), picture.size());
  int r = avcodec_send_packet(ctx_, pkt_);
  av_packet_unref(pkt_);
  if (r < 0) throw AuthoringError("MPEG-2 decoder rejected the picture: " + avError(r));
  r = avcodec_send_packet(ctx_, nullptr);  // drain
  r = avcodec_receive_frame(ctx_, frame_);
  avcodec_flush_buffers(ctx_);
  if (r < 0) throw AuthoringError("MPEG-2 decoder returned no picture: " + avError(r));
  lastType_ = av_get_picture_type_char(frame_->pict_type);
  Yuv420Image out(frame_->width, frame_->height);
  for (int y = 0; y < out.height; ++y) {
    std::memcpy(out.y.data() + static_cast<std::size_t>(y) * out.width,
                frame_->data[0] + static_cast<std::ptrdiff_t>(y) * frame_->linesize[0],
                static_cast<std::size_t>(out.width));
  }
  for (int y = 0; y < out.chromaHeight(); ++y) {
    std::memcpy(out.cb.data() + static_cast<std::size_t>(y) * out.chromaWidth(),
                frame_->data[1] + static_cast<std::ptrdiff_t>(y) * frame_->linesize[1],
                static_cast<std::size_t>(out.chromaWidth()));
    std::memcpy(out.cr.data() + static_cast<std::size_t>(y) * out.chromaWidth(),
                frame_->data[2] + static_cast<std::ptrdiff_t>(y) * frame_->linesize[2],
                static_cast<std::size_t>(out.chromaWidth()));
  }
  av_frame_unref(frame_);
  return out;
}

Rgba8Image Mpeg2Decoder::decodeRgba(std::span<const std::uint8_t> picture) {
  const Yuv420Image yuv = decodeYuv(picture);
  SwsContext* sws = sws_getContext(yuv.width, yuv.height, AV_PIX_FMT_YUV420P, yuv.width, yuv.height, AV_PIX_FMT_RGBA,
                                   SWS_BICUBIC | SWS_ACCURATE_RND | SWS_BITEXACT, nullptr, nullptr, nullptr);
  const int* bt601 = sws_getCoefficients(SWS_CS_ITU601);
  sws_setColorspaceDetails(sws, bt601, 0, bt601, 1, 0, 1 << 16, 1 << 16);
  Rgba8Image out(yuv.width, yuv.height);
  const std::uint8_t* src[3] = {yuv.y.data(), yuv.cb.data(), yuv.cr.data()};
  const int srcStride[3] = {yuv.width, yuv.chromaWidth(), yuv.chromaWidth()};
  std::uint8_t* dst[1] = {out.pixels.data()};
  const int dstStride[1] = {out.width * 4};
  sws_scale(sws, src, srcStride, 0, yuv.height, dst, dstStride);
  sws_freeContext(sws);
  for (std::size_t i = 3; i < out.pixels.size(); i += 4) out.pixels[i] = 0x80;
  return out;
}

namespace {
double psnr(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b, std::size_t step) {
  if (a.size() != b.size()) throw AuthoringError("PSNR of images of different sizes");
  double se = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (step == 4 && i % 4 == 3) continue;  // alpha
    const double d = double(a[i]) - double(b[i]);
    se += d * d;
    ++n;
  }
  if (se == 0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(255.0 * 255.0 / (se / static_cast<double>(n)));
}
}  // namespace

double psnrRgb(const Rgba8Image& a, const Rgba8Image& b) {
  if (!a.sameSize(b)) throw AuthoringError("PSNR of images of different sizes");
  return psnr(a.pixels, b.pixels, 4);
}

PlanePsnr psnrYuv(const Yuv420Image& a, const Yuv420Image& b) {
  if (a.width != b.width || a.height != b.height) throw AuthoringError("PSNR of images of different sizes");
  return PlanePsnr{psnr(a.y, b.y, 1), psnr(a.cb, b.cb, 1), psnr(a.cr, b.cr, 1)};
}

}  // namespace vbim::streams
