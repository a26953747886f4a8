#include "tests/ipu/support/libav_mpeg.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
}

namespace vbim::ipu::testing {
namespace {

struct Lcg {
  std::uint32_t s;
  std::uint32_t next() {
    s = s * 1664525u + 1013904223u;
    return s >> 8;
  }
};

void check(int rc, const char* what) {
  if (rc < 0) {
    char buf[256];
    av_strerror(rc, buf, sizeof buf);
    throw std::runtime_error(std::string(what) + ": " + buf);
  }
}

}  // namespace

std::string EncodeOptions::describe() const {
  std::string s = (mpeg1 ? "mpeg1 " : "mpeg2 ") + std::to_string(width) + "x" + std::to_string(height) + " q" +
                  std::to_string(quantiser);
  if (intraVlc) s += " intra_vlc";
  if (alternateScan) s += " alternate_scan";
  if (nonLinearQuant) s += " non_linear_quant";
  if (dcPrecision) s += " dc" + std::to_string(8 + dcPrecision);
  if (customMatrix) s += " custom_matrix";
  if (customInterMatrix) s += " custom_inter_matrix";
  if (interlacedDct) s += " field_dct";
  if (interlacedMe) s += " field_me";
  if (gopSize > 1) s += " gop" + std::to_string(gopSize) + "b" + std::to_string(bFrames);
  static const char* const kNames[] = {" smooth", " busy", " noise", " interlaced", " lightmap", " pattern", " pan"};
  s += kNames[static_cast<int>(content)];
  return s;
}

std::vector<Yuv420Image> makeFrames(const EncodeOptions& o) {
  std::vector<Yuv420Image> frames;
  Lcg rng{o.seed * 2654435761u + 7};
  for (int f = 0; f < o.frames; ++f) {
    Yuv420Image img(o.width, o.height);
    for (int y = 0; y < o.height; ++y) {
      for (int x = 0; x < o.width; ++x) {
        int v;
        switch (o.content) {
          case Content::kSmooth:  // slowly varying, like a baked lightmap
            v = 40 + (x * 150) / (o.width + 1) + (y * 50) / (o.height + 1) + ((x * y + 7 * f) % 23) / 8;
            break;
          case Content::kBusy:  // edges and texture at many frequencies
            v = (((x / 3) ^ (y / 5)) & 1 ? 200 : 40) + ((x * x + y * 3 + f * 11) % 37) - 18;
            break;
          case Content::kInterlaced:  // two fields of a moving edge: strong line-to-line combing
            v = ((x + ((y & 1) ? 9 : 0) + 3 * f) / 6) % 2 ? 190 : 60;
            v += (y & 1) ? 25 : -25;
            break;
          case Content::kLightmap:  // soft light and shadow shapes, slowly drifting with f
            v = static_cast<int>(120 + 70 * std::sin((x + 3 * f) / 47.0) * std::cos(y / 61.0) +
                                 30 * std::sin((x + y) / 23.0 + f * 0.05));
            break;
          case Content::kPattern: {  // a test card: bars, a checkerboard, rings, a ramp
            const int dx = x - o.width / 2, dy = y - o.height / 2;
            if (y < o.height / 3) {
              v = 40 + 25 * ((x * 8 / (o.width + 1) + f) % 8);
            } else if (y < 2 * o.height / 3) {
              v = (((x + 2 * f) / 16 + y / 16) & 1) ? 200 : 50;
              if ((dx * dx + dy * dy) / 300 % 4 == 0) v = 128;
            } else {
              v = 16 + (x * 219) / (o.width + 1);
            }
            break;
          }
          case Content::kPan: {  // in 1/4 samples: 6 per frame across, 3 down
            const int u = 4 * x + 6 * f;
            const int w = 4 * y + 3 * f;
            v = static_cast<int>(128 + 70 * std::sin(u / 37.0) * std::cos(w / 53.0) +
                                 25 * std::sin((u + 2 * w) / 19.0));
            break;
          }
          default:
            v = static_cast<int>(rng.next() & 0xFF);
            break;
        }
        img.y[static_cast<std::size_t>(y) * o.width + x] = static_cast<std::uint8_t>(v < 0 ? 0 : (v > 255 ? 255 : v));
      }
    }
    for (int y = 0; y < img.chromaHeight(); ++y) {
      for (int x = 0; x < img.chromaWidth(); ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * img.chromaWidth() + x;
        if (o.content == Content::kNoise) {
          img.cb[i] = static_cast<std::uint8_t>(rng.next() & 0xFF);
          img.cr[i] = static_cast<std::uint8_t>(rng.next() & 0xFF);
        } else if (o.content == Content::kPan) {
          const int u = 8 * x + 6 * f;
          const int w = 8 * y + 3 * f;
          img.cb[i] = static_cast<std::uint8_t>(128 + 40 * std::sin(u / 41.0 + w / 67.0));
          img.cr[i] = static_cast<std::uint8_t>(128 + 40 * std::cos(w / 29.0 - u / 83.0));
        } else if (o.content == Content::kLightmap) {
          img.cb[i] = static_cast<std::uint8_t>(118 + 8 * std::sin(x / 31.0));
          img.cr[i] = static_cast<std::uint8_t>(134 + 10 * std::cos(y / 27.0 + f * 0.03));
        } else if (o.content == Content::kPattern) {
          img.cb[i] = static_cast<std::uint8_t>(
              y < img.chromaHeight() / 3 ? 60 + 20 * ((x * 8 / (img.chromaWidth() + 1)) % 8) : 128);
          img.cr[i] = static_cast<std::uint8_t>(
              y < img.chromaHeight() / 3 ? 200 - 18 * ((x * 8 / (img.chromaWidth() + 1)) % 8) : 120);
        } else if (o.content == Content::kBusy) {
          img.cb[i] = static_cast<std::uint8_t>(((x + y + f) & 4) ? 90 : 170);
          img.cr[i] = static_cast<std::uint8_t>(128 + ((x * 7 + y * 3) % 61) - 30);
        } else {
          img.cb[i] = static_cast<std::uint8_t>(110 + (x * 30) / (img.chromaWidth() + 1));
          img.cr[i] = static_cast<std::uint8_t>(140 - (y * 20) / (img.chromaHeight() + 1));
        }
      }
    }
    frames.push_back(std::move(img));
  }
  return frames;
}

std::vector<std::uint8_t> encodeIntra(const EncodeOptions& o, const std::vector<Yuv420Image>& frames) {
  av_log_set_level(AV_LOG_ERROR);
  const AVCodec* codec = avcodec_find_encoder(o.mpeg1 ? AV_CODEC_ID_MPEG1VIDEO : AV_CODEC_ID_MPEG2VIDEO);
  if (!codec) throw std::runtime_error("no MPEG encoder in libavcodec");
  AVCodecContext* c = avcodec_alloc_context3(codec);
  c->width = o.width;
  c->height = o.height;
  c->pix_fmt = AV_PIX_FMT_YUV420P;
  c->time_base = AVRational{1, 25};
  c->framerate = AVRational{25, 1};
  c->gop_size = o.gopSize;
  c->max_b_frames = o.bFrames;
  c->thread_count = 1;
  c->flags |= AV_CODEC_FLAG_QSCALE;
  c->qmin = 1;
  c->qmax = o.nonLinearQuant ? 28 : 31;  // libavcodec's non-linear quantiser stops at 28
  c->global_quality = FF_QP2LAMBDA * o.quantiser;
  c->intra_dc_precision = o.dcPrecision;
  if (o.dcPrecision == 3) c->profile = FF_PROFILE_MPEG2_HIGH;  // 11-bit DC needs the high profile
  if (o.interlacedDct) c->flags |= AV_CODEC_FLAG_INTERLACED_DCT;
  if (o.interlacedMe) {
    c->flags |= AV_CODEC_FLAG_INTERLACED_ME;
    c->field_order = AV_FIELD_TT;
  }
  std::uint16_t* matrix = nullptr;
  if (o.customMatrix) {
    matrix = static_cast<std::uint16_t*>(av_malloc(64 * sizeof(std::uint16_t)));
    for (int i = 0; i < 64; ++i) matrix[i] = static_cast<std::uint16_t>(i == 0 ? 8 : 9 + ((i * 37) % 50));
    c->intra_matrix = matrix;  // freed by avcodec_free_context
  }
  if (o.customInterMatrix) {
    auto* inter = static_cast<std::uint16_t*>(av_malloc(64 * sizeof(std::uint16_t)));
    for (int i = 0; i < 64; ++i) inter[i] = static_cast<std::uint16_t>(12 + ((i * 29) % 40));
    c->inter_matrix = inter;  // freed by avcodec_free_context
  }
  if (!o.mpeg1) {
    if (o.intraVlc) check(av_opt_set_int(c->priv_data, "intra_vlc", 1, 0), "intra_vlc");
    if (o.alternateScan) check(av_opt_set_int(c->priv_data, "alternate_scan", 1, 0), "alternate_scan");
    if (o.nonLinearQuant) check(av_opt_set_int(c->priv_data, "non_linear_quant", 1, 0), "non_linear_quant");
  }
  check(avcodec_open2(c, codec, nullptr), "avcodec_open2");
  std::vector<std::uint8_t> out;
  AVFrame* frame = av_frame_alloc();
  AVPacket* pkt = av_packet_alloc();
  auto drain = [&]() {
    for (;;) {
      const int rc = avcodec_receive_packet(c, pkt);
      if (rc == AVERROR(EAGAIN) || rc == AVERROR_EOF) return;
      check(rc, "avcodec_receive_packet");
      out.insert(out.end(), pkt->data, pkt->data + pkt->size);
      av_packet_unref(pkt);
    }
  };
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const Yuv420Image& img = frames[f];
    frame->format = AV_PIX_FMT_YUV420P;
    frame->width = o.width;
    frame->height = o.height;
    check(av_frame_get_buffer(frame, 0), "av_frame_get_buffer");
    for (int y = 0; y < o.height; ++y)
      std::memcpy(frame->data[0] + y * frame->linesize[0], img.y.data() + static_cast<std::size_t>(y) * o.width,
                  o.width);
    for (int y = 0; y < img.chromaHeight(); ++y) {
      std::memcpy(frame->data[1] + y * frame->linesize[1],
                  img.cb.data() + static_cast<std::size_t>(y) * img.chromaWidth(), img.chromaWidth());
      std::memcpy(frame->data[2] + y * frame->linesize[2],
                  img.cr.data() + static_cast<std::size_t>(y) * img.chromaWidth(), img.chromaWidth());
    }
    frame->pts = static_cast<std::int64_t>(f);
    if (o.interlacedMe) {
      frame->interlaced_frame = 1;
      frame->top_field_first = 1;
    }
    frame->quality = c->global_quality;
    frame->pict_type = o.gopSize == 1 ? AV_PICTURE_TYPE_I : AV_PICTURE_TYPE_NONE;
    check(avcodec_send_frame(c, frame), "avcodec_send_frame");
    drain();
    av_frame_unref(frame);
  }
  check(avcodec_send_frame(c, nullptr), "flush");
  drain();
  av_packet_free(&pkt);
  av_frame_free(&frame);
  avcodec_free_context(&c);
  return out;
}

std::vector<Yuv420Image> decodeWithLibav(const std::vector<std::uint8_t>& es, bool mpeg1, int idctAlgo) {
  av_log_set_level(AV_LOG_ERROR);
  const AVCodec* codec = avcodec_find_decoder(mpeg1 ? AV_CODEC_ID_MPEG1VIDEO : AV_CODEC_ID_MPEG2VIDEO);
  AVCodecContext* c = avcodec_alloc_context3(codec);
  c->thread_count = 1;
  c->idct_algo = idctAlgo;
  check(avcodec_open2(c, codec, nullptr), "avcodec_open2 (decoder)");
  AVCodecParserContext* parser = av_parser_init(codec->id);
  AVPacket* pkt = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  std::vector<Yuv420Image> out;
  auto receive = [&]() {
    for (;;) {
      const int rc = avcodec_receive_frame(c, frame);
      if (rc == AVERROR(EAGAIN) || rc == AVERROR_EOF) return;
      check(rc, "avcodec_receive_frame");
      Yuv420Image img(frame->width, frame->height);
      for (int y = 0; y < frame->height; ++y)
        std::memcpy(img.y.data() + static_cast<std::size_t>(y) * img.width, frame->data[0] + y * frame->linesize[0],
                    img.width);
      for (int y = 0; y < img.chromaHeight(); ++y) {
        std::memcpy(img.cb.data() + static_cast<std::size_t>(y) * img.chromaWidth(),
                    frame->data[1] + y * frame->linesize[1], img.chromaWidth());
        std::memcpy(img.cr.data() + static_cast<std::size_t>(y) * img.chromaWidth(),
                    frame->data[2] + y * frame->linesize[2], img.chromaWidth());
      }
      out.push_back(std::move(img));
    }
  };
  const std::uint8_t* data = es.data();
  std::size_t left = es.size();
  while (left > 0) {
    std::uint8_t* pdata = nullptr;
    int psize = 0;
    const int used =
        av_parser_parse2(parser, c, &pdata, &psize, data, static_cast<int>(left), AV_NOPTS_VALUE, AV_NOPTS_VALUE, 0);
    check(used, "av_parser_parse2");
    data += used;
    left -= static_cast<std::size_t>(used);
    if (psize > 0) {
      pkt->data = pdata;
      pkt->size = psize;
      check(avcodec_send_packet(c, pkt), "avcodec_send_packet");
      receive();
    }
  }
  std::uint8_t* pdata = nullptr;
  int psize = 0;
  av_parser_parse2(parser, c, &pdata, &psize, nullptr, 0, AV_NOPTS_VALUE, AV_NOPTS_VALUE, 0);
  if (psize > 0) {
    pkt->data = pdata;
    pkt->size = psize;
    check(avcodec_send_packet(c, pkt), "avcodec_send_packet");
    receive();
  }
  avcodec_send_packet(c, nullptr);
  receive();
  av_parser_close(parser);
  av_packet_free(&pkt);
  av_frame_free(&frame);
  avcodec_free_context(&c);
  return out;
}

PlaneDiff compare(const Yuv420Image& a, const Yuv420Image& b) {
  PlaneDiff d;
  auto plane = [&](const std::vector<std::uint8_t>& p, const std::vector<std::uint8_t>& q) {
    const std::size_t n = p.size() < q.size() ? p.size() : q.size();
    d.samples += n;
    for (std::size_t i = 0; i < n; ++i) {
      const int diff = std::abs(static_cast<int>(p[i]) - static_cast<int>(q[i]));
      if (diff) {
        ++d.different;
        if (diff > d.maxAbs) d.maxAbs = diff;
      }
    }
  };
  plane(a.y, b.y);
  plane(a.cb, b.cb);
  plane(a.cr, b.cr);
  return d;
}

}  // namespace vbim::ipu::testing
