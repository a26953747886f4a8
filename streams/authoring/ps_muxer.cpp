#include "streams/authoring/ps_muxer.hpp"

#include <cstring>

#include "streams/authoring/error.hpp"
#include "streams/format.hpp"

namespace vbim::streams {

PsMuxer::PsMuxer() {
  if (int r = avformat_alloc_output_context2(&oc_, nullptr, "vob", nullptr); r < 0 || !oc_)
    throw AuthoringError("libavformat has no 'vob' (MPEG-2 PS) muxer: " + avError(r));
  oc_->packet_size = static_cast<unsigned>(kSectorBytes);
  oc_->flags |= AVFMT_FLAG_BITEXACT;
  av_opt_set_int(oc_->priv_data, "muxrate", kDvdMuxRate, 0);
  if (int r = avio_open_dyn_buf(&oc_->pb); r < 0) throw AuthoringError("cannot open the mux buffer: " + avError(r));
}

PsMuxer::~PsMuxer() {
  if (oc_ && oc_->pb) {
    std::uint8_t* buf = nullptr;
    avio_close_dyn_buf(oc_->pb, &buf);
    av_free(buf);
    oc_->pb = nullptr;
  }
  avformat_free_context(oc_);
}

int PsMuxer::addStream(const AVCodecContext* enc) {
  AVStream* st = avformat_new_stream(oc_, nullptr);
  if (!st) throw AuthoringError("cannot add a stream to the muxer");
  st->time_base = enc->time_base;
  avcodec_parameters_from_context(st->codecpar, enc);
  // The muxer reads the VBV size from stream side data; without it it assumes 230 KiB
  // (docs/dependencies.md#stream-side-data).
  for (int i = 0; i < enc->nb_coded_side_data; ++i) {
    const AVPacketSideData& sd = enc->coded_side_data[i];
    std::uint8_t* dst = av_stream_new_side_data(st, sd.type, sd.size);
    if (!dst) throw AuthoringError("cannot copy the encoder's side data");
    std::memcpy(dst, sd.data, sd.size);
  }
  return st->index;
}

void PsMuxer::begin() {
  if (int r = avformat_write_header(oc_, nullptr); r < 0) throw AuthoringError("MPEG-PS muxer: " + avError(r));
  begun_ = true;
}

void PsMuxer::write(AVPacket* pkt, int stream, AVRational encoderTimeBase) {
  pkt->stream_index = stream;
  av_packet_rescale_ts(pkt, encoderTimeBase, oc_->streams[stream]->time_base);
  const int r = av_interleaved_write_frame(oc_, pkt);
  av_packet_free(&pkt);
  if (r < 0) throw AuthoringError("MPEG-PS muxer: " + avError(r));
}

std::vector<std::uint8_t> PsMuxer::finish() {
  if (begun_) {
    if (int r = av_write_trailer(oc_); r < 0) throw AuthoringError("MPEG-PS muxer: " + avError(r));
  }
  std::uint8_t* buf = nullptr;
  const int size = avio_close_dyn_buf(oc_->pb, &buf);
  oc_->pb = nullptr;
  std::vector<std::uint8_t> out(buf, buf + size);
  av_free(buf);
  return out;
}

}  // namespace vbim::streams
