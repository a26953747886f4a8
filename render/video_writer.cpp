#include "render/video_writer.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <string>

#include "render/error.hpp"
#include "streams/authoring/libav.hpp"

namespace vbim::render {

struct VideoWriter::Av {
  std::filesystem::path path;
  AVFormatContext* fmt = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* sws = nullptr;
  std::int64_t count = 0;
  std::int64_t lastPts = -1;
  std::deque<std::int64_t> durations;  // of the frames sent, not yet out as packets, in order
  int quality = 0;
  bool headerWritten = false, finished = false;

  ~Av() {
    if (headerWritten && !finished) av_write_trailer(fmt);
    sws_freeContext(sws);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&codec);
    if (fmt != nullptr) {
      if (fmt->pb != nullptr) avio_closep(&fmt->pb);
      avformat_free_context(fmt);
    }
  }

  void check(int rc, const char* what) const {
    if (rc < 0) throw RenderError(path.string() + ": " + what + ": " + streams::avError(rc));
  }

  void drain() {
    for (;;) {
      const int rc = avcodec_receive_packet(codec, packet);
      if (rc == AVERROR(EAGAIN) || rc == AVERROR_EOF) return;
      check(rc, "encoding the video");
      // No B-frames: packets come out in the order the frames went in, one each. The MP4 muxer
      // takes a sample's length from the next one's start; the last one's from this duration.
      if (!durations.empty()) {
        packet->duration = durations.front();
        durations.pop_front();
      }
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      check(av_interleaved_write_frame(fmt, packet), "writing the video");
    }
  }
};

std::vector<VideoSlot> videoSlots(const std::vector<double>& startS, double endS, int fps) {
  std::vector<VideoSlot> slots(startS.size());
  if (startS.empty()) return slots;
  const double origin = startS.front();
  const auto tick = [&](double t) { return static_cast<std::int64_t>(std::llround((t - origin) * fps)); };
  std::size_t last = 0;  // the shown frame before
  for (std::size_t i = 0; i < startS.size(); ++i) {
    if (i > 0 && !(startS[i] >= startS[i - 1])) {
      throw RenderError("video: frame " + std::to_string(i) + " at " + std::to_string(startS[i]) +
                        " s comes before the frame before it (" + std::to_string(startS[i - 1]) + " s)");
    }
    const std::int64_t pts = tick(startS[i]);
    if (i > 0 && pts <= slots[last].pts) continue;
    if (i > 0) slots[last].duration = pts - slots[last].pts;
    slots[i] = VideoSlot{true, pts, 0};
    last = i;
  }
  if (!(endS >= startS.back())) {
    throw RenderError("video: the run ends at " + std::to_string(endS) + " s, before its last saved frame (" +
                      std::to_string(startS.back()) + " s)");
  }
  slots[last].duration = std::max<std::int64_t>(1, tick(endS) - slots[last].pts);
  return slots;
}

VideoWriter::VideoWriter(const std::filesystem::path& path, int width, int height, int fps, int quantiser)
    : av_(std::make_unique<Av>()) {
  Av& a = *av_;
  a.path = path;
  if (width % 2 != 0 || height % 2 != 0 || width <= 0 || height <= 0) {
    throw RenderError(path.string() + ": the video needs an even width and height, got " + std::to_string(width) + "x" +
                      std::to_string(height));
  }
  if (fps < 1 || fps > 120) throw RenderError(path.string() + ": video frame rate must be 1..120");
  a.check(avformat_alloc_output_context2(&a.fmt, nullptr, "mp4", path.string().c_str()), "creating the MP4 muxer");
  const AVCodec* enc = avcodec_find_encoder(AV_CODEC_ID_MPEG4);
  if (enc == nullptr) throw RenderError(path.string() + ": this libavcodec has no MPEG-4 encoder");
  a.stream = avformat_new_stream(a.fmt, nullptr);
  a.codec = avcodec_alloc_context3(enc);
  if (a.stream == nullptr || a.codec == nullptr) throw RenderError(path.string() + ": out of memory");
  a.codec->width = width;
  a.codec->height = height;
  a.codec->pix_fmt = AV_PIX_FMT_YUV420P;
  a.codec->time_base = AVRational{1, fps};
  a.codec->framerate = AVRational{fps, 1};
  a.codec->gop_size = 12;
  a.codec->max_b_frames = 0;
  // Fixed quantiser: the encoder takes lambda from every frame's quality (docs/dependencies.md#fixed-quantiser).
  a.codec->flags |= AV_CODEC_FLAG_QSCALE;
  a.quality = FF_QP2LAMBDA * quantiser;
  a.codec->global_quality = a.quality;
  if (a.fmt->oformat->flags & AVFMT_GLOBALHEADER) a.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  // One encoder thread: the bytes then do not depend on the machine.
  a.codec->thread_count = 1;
  a.check(avcodec_open2(a.codec, enc, nullptr), "opening the MPEG-4 encoder");
  a.check(avcodec_parameters_from_context(a.stream->codecpar, a.codec), "setting the stream parameters");
  a.stream->time_base = a.codec->time_base;
  a.check(avio_open(&a.fmt->pb, path.string().c_str(), AVIO_FLAG_WRITE), "opening the file");
  // No creation time or encoder string that would change between runs.
  a.fmt->flags |= AVFMT_FLAG_BITEXACT;
  a.codec->flags |= AV_CODEC_FLAG_BITEXACT;
  a.check(avformat_write_header(a.fmt, nullptr), "writing the MP4 header");
  a.headerWritten = true;
  a.frame = av_frame_alloc();
  a.packet = av_packet_alloc();
  if (a.frame == nullptr || a.packet == nullptr) throw RenderError(path.string() + ": out of memory");
  a.frame->format = AV_PIX_FMT_YUV420P;
  a.frame->width = width;
  a.frame->height = height;
  a.check(av_frame_get_buffer(a.frame, 0), "allocating a frame");
  a.sws = sws_getContext(width, height, AV_PIX_FMT_RGBA, width, height, AV_PIX_FMT_YUV420P, SWS_BILINEAR, nullptr,
                         nullptr, nullptr);
  if (a.sws == nullptr) throw RenderError(path.string() + ": cannot set up the RGB -> YUV conversion");
}

VideoWriter::~VideoWriter() = default;

void VideoWriter::add(const Rgba8Image& img, std::int64_t pts, std::int64_t duration) {
  Av& a = *av_;
  if (img.width != a.codec->width || img.height != a.codec->height) {
    throw RenderError(a.path.string() + ": video frame " + std::to_string(a.count) + " has another size");
  }
  if (pts <= a.lastPts || duration < 1) {
    throw RenderError(a.path.string() + ": video frame " + std::to_string(a.count) + " at tick " + std::to_string(pts) +
                      " for " + std::to_string(duration) +
                      " ticks: expected a start after the previous frame's and a positive duration");
  }
  a.check(av_frame_make_writable(a.frame), "preparing a frame");
  const std::uint8_t* src[1] = {img.pixels.data()};
  const int stride[1] = {img.width * 4};
  sws_scale(a.sws, src, stride, 0, img.height, a.frame->data, a.frame->linesize);
  a.frame->pts = pts;
  a.lastPts = pts;
  ++a.count;
  a.durations.push_back(duration);
  a.frame->quality = a.quality;
  a.check(avcodec_send_frame(a.codec, a.frame), "encoding the video");
  a.drain();
}

void VideoWriter::finish() {
  Av& a = *av_;
  if (a.finished) return;
  a.check(avcodec_send_frame(a.codec, nullptr), "flushing the encoder");
  a.drain();
  a.check(av_write_trailer(a.fmt), "writing the MP4 trailer");
  a.finished = true;
}

std::int64_t VideoWriter::frames() const {
  return av_->count;
}

}  // namespace vbim::render
