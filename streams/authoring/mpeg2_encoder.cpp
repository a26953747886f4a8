#include "streams/authoring/mpeg2_encoder.hpp"

#include "streams/authoring/error.hpp"

namespace vbim::streams {

namespace {

SwsContext* makeRgbaToYuv(int width, int height) {
  SwsContext* sws = sws_getContext(width, height, AV_PIX_FMT_RGBA, width, height, AV_PIX_FMT_YUV420P,
                                   SWS_BICUBIC | SWS_ACCURATE_RND | SWS_BITEXACT, nullptr, nullptr, nullptr);
  if (!sws) throw AuthoringError("cannot set up the RGB -> YCbCr conversion");
  // Full-range RGB in, BT.601 limited-range YCbCr out: the IPU's CSC matrix (docs/hardware.md#colour-conversion).
  const int* bt601 = sws_getCoefficients(SWS_CS_ITU601);
  sws_setColorspaceDetails(sws, bt601, 1, bt601, 0, 0, 1 << 16, 1 << 16);
  return sws;
}

}  // namespace

std::string gopProblem(const EncoderSettings& s) {
  if (s.gop < 1 || s.gop > kMaxGop)
    return "--gop " + std::to_string(s.gop) + " is outside 1.." + std::to_string(kMaxGop) + " (pictures per GOP)";
  if (s.bFrames < 0 || s.bFrames > kMaxBFrames)
    return "--b-frames " + std::to_string(s.bFrames) + " is outside 0.." + std::to_string(kMaxBFrames);
  if (s.bFrames > 0 && s.bFrames >= s.gop) {
    return "--b-frames " + std::to_string(s.bFrames) + " needs --gop above it (a GOP of " + std::to_string(s.gop) +
           " has room for at most " + std::to_string(s.gop - 1) + " B pictures after its I picture)";
  }
  if (s.openGop && s.bFrames == 0) return "--open-gop needs --b-frames: only B pictures can refer across a GOP header";
  return {};
}

Yuv420Image rgbaToYuv420(const Rgba8Image& img) {
  SwsContext* sws = makeRgbaToYuv(img.width, img.height);
  Yuv420Image out(img.width, img.height);
  const std::uint8_t* src[1] = {img.pixels.data()};
  const int srcStride[1] = {img.width * 4};
  std::uint8_t* dst[3] = {out.y.data(), out.cb.data(), out.cr.data()};
  const int dstStride[3] = {out.width, out.chromaWidth(), out.chromaWidth()};
  sws_scale(sws, src, srcStride, 0, img.height, dst, dstStride);
  sws_freeContext(sws);
  return out;
}

Mpeg2Encoder::Mpeg2Encoder(int width, int height, const EncoderSettings& s) : intraOnly_(s.gop == 1) {
  if (const std::string why = gopProblem(s); !why.empty()) throw AuthoringError(why);
  const AVCodec* codec = avcodec_find_encoder(AV_CODEC_ID_MPEG2VIDEO);
  if (!codec) throw AuthoringError("libavcodec has no MPEG-2 video encoder");
  ctx_ = avcodec_alloc_context3(codec);
  ctx_->width = width;
  ctx_->height = height;
  ctx_->pix_fmt = AV_PIX_FMT_YUV420P;
  ctx_->time_base = AVRational{static_cast<int>(s.containerFps.den), static_cast<int>(s.containerFps.num)};
  ctx_->framerate = AVRational{static_cast<int>(s.containerFps.num), static_cast<int>(s.containerFps.den)};
  // gop_size 1: every picture intra, the IPU's IDEC path (the default, and the samples' bytes).
  ctx_->gop_size = s.gop;
  ctx_->max_b_frames = s.bFrames;
  if (s.gop > 1) {
    // A fixed pattern: no I pictures at scene changes (sc_threshold), B pictures exactly as asked
    // (b_strategy 0), GOPs of exactly gop pictures (mpv_flags strict_gop): the private options of
    // libavcodec's MPEG video encoders (mpegvideoenc.h, FF_MPV_COMMON_OPTS).
    av_opt_set_int(ctx_->priv_data, "sc_threshold", 1'000'000'000, 0);
    av_opt_set_int(ctx_->priv_data, "b_strategy", 0, 0);
    av_opt_set(ctx_->priv_data, "mpv_flags", "+strict_gop", 0);
    if (!s.openGop) ctx_->flags |= AV_CODEC_FLAG_CLOSED_GOP;
  }
  ctx_->flags |= AV_CODEC_FLAG_BITEXACT;
  ctx_->color_range = AVCOL_RANGE_MPEG;
  ctx_->colorspace = AVCOL_SPC_BT470BG;  // BT.601, the IPU's CSC matrix (docs/hardware.md)
  // VBV sized for DVD so the muxer's buffer model matches a DVD drive. Beware
  // (docs/dependencies.md#vbv-size): a picture that overflows the VBV is re-quantised even with a
  // fixed quantiser, which maxQscaleUsed() reveals.
  ctx_->rc_buffer_size = kDvdVbvBits;
  ctx_->rc_max_rate = kDvdMaxVideoRate;
  if (s.bitrate > 0) {
    ctx_->bit_rate = s.bitrate;
  } else {
    // Fixed quantiser: the flag and global_quality are not enough, every frame's `quality` must
    // carry the lambda too, or the encoder silently uses qmin (docs/dependencies.md#fixed-quantiser).
    ctx_->flags |= AV_CODEC_FLAG_QSCALE;
    ctx_->global_quality = FF_QP2LAMBDA * s.qscale;
    ctx_->qmin = std::min(2, s.qscale);
    quality_ = ctx_->global_quality;
  }
  if (int r = avcodec_open2(ctx_, codec, nullptr); r < 0) {
    avcodec_free_context(&ctx_);
    throw AuthoringError("cannot open the MPEG-2 encoder for " + std::to_string(width) + "x" + std::to_string(height) +
                         ": " + avError(r));
  }
  sws_ = makeRgbaToYuv(width, height);
  frame_ = av_frame_alloc();
  frame_->format = AV_PIX_FMT_YUV420P;
  frame_->width = width;
  frame_->height = height;
  if (av_frame_get_buffer(frame_, 0) < 0) throw AuthoringError("cannot allocate the encoder's frame");
}

Mpeg2Encoder::~Mpeg2Encoder() {
  av_frame_free(&frame_);
  sws_freeContext(sws_);
  avcodec_free_context(&ctx_);
}

void Mpeg2Encoder::encode(const Rgba8Image& img, std::int64_t pts, std::vector<AVPacket*>& out, Force force) {
  if (av_frame_make_writable(frame_) < 0) throw AuthoringError("cannot write the encoder's frame");
  const std::uint8_t* src[1] = {img.pixels.data()};
  const int stride[1] = {img.width * 4};
  sws_scale(sws_, src, stride, 0, img.height, frame_->data, frame_->linesize);
  frame_->pts = pts;
  // A forced type: libavcodec codes a frame given as I as a new GOP, and one given as P as the
  // reference that ends the run of B pictures before it (mpegvideo_enc.c, select_input_picture).
  frame_->pict_type = intraOnly_ || force == Force::Intra ? AV_PICTURE_TYPE_I
                      : force == Force::Reference         ? AV_PICTURE_TYPE_P
                                                          : AV_PICTURE_TYPE_NONE;
  frame_->quality = quality_;
  if (int r = avcodec_send_frame(ctx_, frame_); r < 0) throw AuthoringError("MPEG-2 encoder: " + avError(r));
  drain(out);
}

void Mpeg2Encoder::flush(std::vector<AVPacket*>& out) {
  avcodec_send_frame(ctx_, nullptr);
  drain(out);
}

void Mpeg2Encoder::drain(std::vector<AVPacket*>& out) {
  for (;;) {
    AVPacket* pkt = av_packet_alloc();
    const int r = avcodec_receive_packet(ctx_, pkt);
    if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) {
      av_packet_free(&pkt);
      return;
    }
    if (r < 0) {
      av_packet_free(&pkt);
      throw AuthoringError("MPEG-2 encoder: " + avError(r));
    }
    std::size_t size = 0;
    if (const std::uint8_t* q = av_packet_get_side_data(pkt, AV_PKT_DATA_QUALITY_STATS, &size); q && size >= 4) {
      const int lambda = q[0] | (q[1] << 8) | (q[2] << 16) | (q[3] << 24);
      maxQ_ = std::max(maxQ_, (lambda + FF_QP2LAMBDA / 2) / FF_QP2LAMBDA);
    }
    out.push_back(pkt);
  }
}

}  // namespace vbim::streams
