#include "streams/authoring/stream_writer.hpp"

#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <utility>

#include "streams/authoring/error.hpp"
#include "streams/authoring/ps_muxer.hpp"
#include "streams/descriptor_packs.hpp"
#include "streams/format.hpp"
#include "streams/stream_stats.hpp"
#include "streams/temporary_files.hpp"

namespace vbim::streams {

struct StreamWriter::Encoders {
  PsMuxer mux;
  std::unique_ptr<Mpeg2Encoder> lightmap, sky;
  int lightmapStream = -1, skyStream = -1;
  // Encoded pictures wait here until finish(), which knows the largest frame and so how far apart
  // the frames must be in container time (containerStretch).
  struct Pending {
    AVPacket* packet;
    int stream;  // the muxer's: lightmapStream or skyStream
  };
  std::vector<Pending> pending;
  Encoders() = default;
  Encoders(const Encoders&) = delete;
  Encoders& operator=(const Encoders&) = delete;
  ~Encoders() {
    for (Pending& p : pending) av_packet_free(&p.packet);
  }
};

namespace {

// How many container frame periods apart the frames must be so that the largest frame (lightmap
// plus sky) fits into one spacing at the DVD mux rate with a fifth to spare (pack and PES headers
// take ~2 %, the muxer's scheduling the rest). libavformat's MPEG-PS muxer sends packs at the mux
// rate in container time; when the frames carry more bytes than that, it falls behind and the
// stream whose buffer is larger runs ahead: measured on 64 noise frames of 512x512 + 256x128 at
// 25 fps, the last sky picture landed 1,400 sectors (2.8 MB) after its lightmap picture, all of
// which the EE demux had to hold. Container time is only a preview clock (the descriptor's game
// rate drives playback), so it is stretched instead.
std::uint32_t stretchFor(std::int64_t largestFrameBytes, std::uint32_t ptsPerFrame) {
  const std::int64_t perPeriod = kDvdMuxRate / 8 * std::int64_t{ptsPerFrame} / kPtsHz;  // bytes
  const std::int64_t usable = perPeriod * 4 / 5;
  return static_cast<std::uint32_t>(std::max<std::int64_t>(1, (largestFrameBytes + usable - 1) / usable));
}

}  // namespace

void quietLibavLog() {
  av_log_set_level(AV_LOG_ERROR);
}

StreamWriter::StreamWriter(AuthorSettings s) : settings_(s) {
  const Rational c = s.encoder.containerFps;
  if (s.gameFps.num == 0 || s.gameFps.den == 0) throw AuthoringError("the game frame rate must be positive");
  if (c.num == 0 || c.den == 0 || (std::uint64_t{kPtsHz} * c.den) % c.num != 0) {
    throw AuthoringError("container frame rate " + std::to_string(c.num) + "/" + std::to_string(c.den) +
                         " does not give a whole number of 90 kHz ticks per frame (use 24, 25, 30, 30000/1001, 50, "
                         "60 or 60000/1001)");
  }
  if (s.encoder.bitrate == 0 && (s.encoder.qscale < 1 || s.encoder.qscale > 31))
    throw AuthoringError("quantiser " + std::to_string(s.encoder.qscale) + " is outside 1..31");
  if (s.encoder.bitrate < 0 || s.encoder.bitrate > kDvdMaxVideoRate) {
    throw AuthoringError("bitrate " + std::to_string(s.encoder.bitrate) +
                         " bit/s is outside 1..9800000 (the DVD video maximum)");
  }
  descriptor_.gameFps = s.gameFps;
  descriptor_.loopFrame = s.loopFrame;
  descriptor_.ptsPerFrame = static_cast<std::uint32_t>(std::uint64_t{kPtsHz} * c.den / c.num);
}

StreamWriter::~StreamWriter() = default;

int StreamWriter::maxQscaleUsed() const {
  if (!enc_) return 0;
  return std::max(enc_->lightmap->maxQscaleUsed(), enc_->sky ? enc_->sky->maxQscaleUsed() : 0);
}

void StreamWriter::beginVariant(const std::string& name) {
  if (finished_) throw AuthoringError("beginVariant after finish");
  if (!descriptor_.variants.empty()) closeVariant();
  if (name.empty() || name.size() > Descriptor::kMaxVariantName)
    throw AuthoringError("variant name '" + name + "' must have 1 to 23 bytes");
  for (const Variant& v : descriptor_.variants)
    if (v.name == name) throw AuthoringError("variant '" + name + "' is given twice");
  if (descriptor_.variants.size() == 255) throw AuthoringError("at most 255 variants");
  descriptor_.variants.push_back(Variant{name, framesTotal_, 0});
  framesInVariant_ = 0;
}

void StreamWriter::closeVariant() {
  sendHeld(true);  // the variant's last frame: the next variant starts with an I picture
  const Variant& v = descriptor_.variants.back();
  if (framesInVariant_ == 0) throw AuthoringError("variant '" + v.name + "' has no frames");
  if (descriptor_.variants.size() == 1) {
    descriptor_.framesPerVariant = framesInVariant_;
  } else if (framesInVariant_ != descriptor_.framesPerVariant) {
    throw AuthoringError("variant '" + v.name + "' has " + std::to_string(framesInVariant_) + " frames; variant '" +
                         descriptor_.variants.front().name + "' has " + std::to_string(descriptor_.framesPerVariant) +
                         " (branching needs equal lengths)");
  }
}

void StreamWriter::checkSize(const Rgba8Image& img, const char* what, int& w, int& h) const {
  const std::string frame = std::string(what) + " frame " + std::to_string(framesInVariant_) + " of variant '" +
                            descriptor_.variants.back().name + "'";
  if (img.width % 16 || img.height % 16 || img.width < 16 || img.height < 16 || img.width > kMaxFrameSide ||
      img.height > kMaxFrameSide) {
    throw AuthoringError(frame + " is " + std::to_string(img.width) + "x" + std::to_string(img.height) +
                         "; width and height must be multiples of 16 from 16 to 4080 (the IPU decodes whole 16x16 "
                         "macroblocks)");
  }
  if (img.pixels.size() != static_cast<std::size_t>(img.width) * img.height * 4)
    throw AuthoringError(frame + " has a pixel buffer of the wrong size");
  if (w == 0) {
    w = img.width;
    h = img.height;
  } else if (img.width != w || img.height != h) {
    throw AuthoringError(frame + " is " + std::to_string(img.width) + "x" + std::to_string(img.height) +
                         "; the first " + what + " frame is " + std::to_string(w) + "x" + std::to_string(h) +
                         " (all frames of a stream must have one size)");
  }
}

void StreamWriter::open() {
  enc_ = std::make_unique<Encoders>();
  enc_->lightmap = std::make_unique<Mpeg2Encoder>(lmW_, lmH_, settings_.encoder);
  enc_->lightmapStream = enc_->mux.addStream(enc_->lightmap->context());
  descriptor_.streams.push_back(StreamEntry{kLightmapStream, StreamRole::Lightmap, static_cast<std::uint16_t>(lmW_),
                                            static_cast<std::uint16_t>(lmH_)});
  if (settings_.withSky) {
    enc_->sky = std::make_unique<Mpeg2Encoder>(skyW_, skyH_, settings_.encoder);
    enc_->skyStream = enc_->mux.addStream(enc_->sky->context());
    descriptor_.streams.push_back(
        StreamEntry{kSkyStream, StreamRole::Sky, static_cast<std::uint16_t>(skyW_), static_cast<std::uint16_t>(skyH_)});
  }
  enc_->mux.begin();
}

void StreamWriter::addFrame(const Rgba8Image& lightmap, const Rgba8Image* sky) {
  if (finished_) throw AuthoringError("addFrame after finish");
  if (descriptor_.variants.empty()) beginVariant("default");
  if (settings_.withSky != (sky != nullptr)) {
    throw AuthoringError(std::string("frame ") + std::to_string(framesInVariant_) + " of variant '" +
                         descriptor_.variants.back().name + "' " +
                         (settings_.withSky ? "has no sky picture (the stream was set up with a sky)"
                                            : "has a sky picture but the stream was set up without one"));
  }
  checkSize(lightmap, "lightmap", lmW_, lmH_);
  if (sky) checkSize(*sky, "sky", skyW_, skyH_);
  if (!enc_) open();
  using Force = Mpeg2Encoder::Force;
  // A loop or branch resumes at an I picture: the variant's first frame and its loop frame start GOPs.
  const bool intra = framesInVariant_ == 0 || framesInVariant_ == settings_.loopFrame;
  const Force force = settings_.encoder.gop > 1 && intra ? Force::Intra : Force::None;
  if (settings_.encoder.bFrames == 0) {
    send(lightmap, sky, framesTotal_, force);
  } else {
    sendHeld(force == Force::Intra);
    held_ = Held{lightmap, sky ? std::optional<Rgba8Image>(*sky) : std::nullopt, framesTotal_, force};
  }
  ++framesInVariant_;
  ++framesTotal_;
}

void StreamWriter::sendHeld(bool beforeIntra) {
  if (!held_) return;
  Held h = std::move(*held_);
  held_.reset();
  if (beforeIntra && h.force == Mpeg2Encoder::Force::None) h.force = Mpeg2Encoder::Force::Reference;
  send(h.lightmap, h.sky ? &*h.sky : nullptr, h.pts, h.force);
}

void StreamWriter::send(const Rgba8Image& lightmap, const Rgba8Image* sky, std::int64_t pts,
                        Mpeg2Encoder::Force force) {
  std::vector<AVPacket*> packets;
  enc_->lightmap->encode(lightmap, pts, packets, force);
  for (AVPacket* p : packets) enc_->pending.push_back({p, enc_->lightmapStream});
  packets.clear();
  if (sky) {
    enc_->sky->encode(*sky, pts, packets, force);
    for (AVPacket* p : packets) enc_->pending.push_back({p, enc_->skyStream});
  }
}

std::vector<std::uint8_t> StreamWriter::finish() {
  if (finished_) throw AuthoringError("finish called twice");
  if (descriptor_.variants.empty() || !enc_) throw AuthoringError("the stream has no frames");
  closeVariant();
  finished_ = true;
  std::vector<AVPacket*> packets;
  const AVRational tb = enc_->lightmap->context()->time_base;
  enc_->lightmap->flush(packets);
  for (AVPacket* p : packets) enc_->pending.push_back({p, enc_->lightmapStream});
  packets.clear();
  if (enc_->sky) {
    enc_->sky->flush(packets);
    for (AVPacket* p : packets) enc_->pending.push_back({p, enc_->skyStream});
  }
  // Frames (pts in container frames) as far apart as the largest one needs, then muxed in order.
  std::map<std::int64_t, std::int64_t> frameBytes;
  for (const auto& p : enc_->pending) frameBytes[p.packet->pts] += p.packet->size;
  std::int64_t largest = 0;
  for (const auto& [pts, bytes] : frameBytes) largest = std::max(largest, bytes);
  // Each stream's pictures in stream (decode) order: the frame each one shows. With B pictures this
  // is not the frame order; the muxer keeps it.
  std::array<std::vector<std::uint32_t>, 2> shows;
  for (const auto& p : enc_->pending)
    shows[p.stream == enc_->lightmapStream ? 0 : 1].push_back(static_cast<std::uint32_t>(p.packet->pts));
  stretch_ = settings_.stretchContainerTime ? stretchFor(largest, descriptor_.ptsPerFrame) : 1;
  descriptor_.ptsPerFrame *= stretch_;
  for (auto& p : enc_->pending) {
    AVPacket* pkt = std::exchange(p.packet, nullptr);
    if (pkt->pts != AV_NOPTS_VALUE) pkt->pts *= stretch_;
    if (pkt->dts != AV_NOPTS_VALUE) pkt->dts *= stretch_;
    pkt->duration *= stretch_;
    enc_->mux.write(pkt, p.stream, tb);
  }
  enc_->pending.clear();
  const std::vector<std::uint8_t> muxed = enc_->mux.finish();

  // Read the muxed stream back, as a player would, to find where each picture landed.
  const StreamScan scan = scanStream(muxed);
  if (!scan.every2048 || !scan.errors.empty()) {
    throw AuthoringError(
        "internal: the muxer wrote a malformed pack: " +
        (scan.errors.empty() ? std::string("size not a multiple of 2048") : scan.errors.front().describe()));
  }
  Descriptor& d = descriptor_;
  d.index.assign(d.streams.size(), std::vector<IndexEntry>(d.totalFrames()));
  // Each stream's pictures come out of the muxer in the encoder's order (`shows`). Where a picture
  // carries a PTS it must be its frame's time: a cross-check of that order.
  // The time origin is the lightmap stream's first picture. It is looked up first: pictures are
  // listed in completion order, and small sky pictures (a dark night sky) can complete before the
  // first lightmap picture does.
  std::vector<std::uint32_t> next(d.streams.size(), 0);
  std::optional<std::int64_t> firstPts;
  for (const PictureRecord& p : scan.pictures) {
    if (d.streamIndex(p.streamId) == 0) {
      firstPts = p.pts;
      if (firstPts && !shows[0].empty()) *firstPts -= std::int64_t{shows[0][0]} * d.ptsPerFrame;
      break;
    }
  }
  for (const PictureRecord& p : scan.pictures) {
    const auto s = static_cast<std::size_t>(d.streamIndex(p.streamId));
    const std::uint32_t k = next[s]++;
    const std::uint32_t frame = k < shows[s].size() ? shows[s][k] : d.totalFrames();
    if (frame >= d.totalFrames() || !firstPts || !p.header ||
        (p.pts && *p.pts != *firstPts + std::int64_t{frame} * d.ptsPerFrame)) {
      throw AuthoringError("internal: stream " + std::to_string(s) + " picture " + std::to_string(k) + " has PTS " +
                           (p.pts ? std::to_string(*p.pts) : "none") + ", expected frame " + std::to_string(frame) +
                           "'s time and a picture header");
    }
    IndexEntry e{p.firstSector, static_cast<std::uint16_t>(p.byteOffset % kSectorBytes), p.bytes, p.crc};
    e.type = p.header->type;
    e.gopStart = p.header->gopHeader;
    e.closedGop = p.header->gopHeader && p.header->closedGop;
    d.index[s][frame] = e;
  }
  if (d.intraOnly()) {
    // Every picture stands alone: version 1, whose entries say so (libavcodec marks its GOPs of one
    // picture open).
    for (auto& table : d.index)
      for (IndexEntry& e : table) e.gopStart = e.closedGop = true;
  }
  if (std::string why = d.validate(); !why.empty()) throw AuthoringError("internal: " + why);
  for (std::size_t s = 0; s < d.streams.size(); ++s) {
    if (next[s] != d.totalFrames()) {
      throw AuthoringError("internal: stream " + std::to_string(s) + " has " + std::to_string(next[s]) +
                           " pictures, expected " + std::to_string(d.totalFrames()));
    }
  }
  d.firstPts = *firstPts;

  // The first muxed pack's system header is repeated in the first descriptor pack.
  const std::size_t sysAt = kPackHeaderBytes + (muxed[13] & 7);
  std::span<const std::uint8_t> sys;
  if (muxed[sysAt + 3] == kSystemHeaderStartCode)
    sys = std::span(muxed).subspan(sysAt, 6 + ((std::size_t{muxed[sysAt + 4]} << 8) | muxed[sysAt + 5]));
  const std::size_t k =
      descriptorPackCount(serializedSize(d.streams.size(), d.variants.size(), d.framesPerVariant), sys.size());
  d.descriptorSectors = static_cast<std::uint32_t>(k);
  d.totalSectors = static_cast<std::uint32_t>(k + muxed.size() / kSectorBytes);
  for (auto& table : d.index)
    for (IndexEntry& e : table) e.sector += static_cast<std::uint32_t>(k);
  for (Variant& v : d.variants) {
    v.firstSector = d.index[0][v.firstFrame].sector;
    for (const auto& table : d.index) v.firstSector = std::min(v.firstSector, table[v.firstFrame].sector);
  }
  const std::vector<std::uint8_t> body = serialize(d);

  // Descriptor packs take the SCRs just before the first muxed pack, one pack time apart at the mux
  // rate, so the SCR still rises through the file (clamped at 0).
  const std::uint32_t muxRate = scan.muxRate;
  const std::int64_t packTicks = std::int64_t{kSectorBytes} * 27'000'000 / (std::int64_t{muxRate} * 50);
  ParsedPack first;
  parsePack(std::span(muxed).first(kSectorBytes), 0, first);
  std::vector<std::int64_t> scr(k);
  for (std::size_t i = 0; i < k; ++i)
    scr[i] = std::max<std::int64_t>(0, first.scr27MHz - static_cast<std::int64_t>(k - i) * packTicks);
  std::vector<std::uint8_t> out = makeDescriptorPacks(body, sys, muxRate, scr);
  out.insert(out.end(), muxed.begin(), muxed.end());
  return out;
}

void writeStreamFile(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw AuthoringError(path.string() + ": is a directory; expected a stream file name");
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec))
    throw AuthoringError(path.string() + ": directory " + dir.string() + " does not exist");
  removeStaleTemporaries(dir);  // what a killed run left here (streams/temporary_files.hpp)
  const fs::path tmp = temporarySibling(path);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw AuthoringError(path.string() + ": cannot create " + tmp.string() + ": " + std::strerror(errno));
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
      const std::string why = std::strerror(errno);
      fs::remove(tmp, ec);
      throw AuthoringError(path.string() + ": cannot write " + tmp.string() + ": " + why);
    }
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    const std::string why = ec.message();
    fs::remove(tmp, ec);
    throw AuthoringError(path.string() + ": cannot move the finished stream into place: " + why);
  }
}

}  // namespace vbim::streams
