#include "streams/pack_parser.hpp"

#include <string>

#include "streams/format.hpp"

namespace vbim::streams {

namespace {

// Stream ids whose PES packets have no optional header (13818-1 §2.4.3.7: padding, private_stream_2,
// program_stream_map, ECM, EMM, directory, DSM-CC, H.222.1 type E).
bool hasNoPesHeader(std::uint8_t id) {
  return id == 0xBC || id == kPaddingStream || id == kPrivateStream2 || id == 0xF0 || id == 0xF1 || id == 0xF2 ||
         id == 0xF8 || id == 0xFF;
}

std::string hex(unsigned v) {
  static const char* digits = "0123456789ABCDEF";
  std::string s = "0x";
  s += digits[(v >> 4) & 15];
  s += digits[v & 15];
  return s;
}

// One pack, either a whole VBIM sector (`sector`: exactly 2048 bytes, MPEG-2 only, used up exactly)
// or the pack at `start` of a program stream of packs of any size.
class Parser {
 public:
  Parser(std::span<const std::uint8_t> d, std::size_t start, bool sector, std::uint32_t lsn, ParsedPack& out)
      : d_(d), start_(start), sector_(sector), lsn_(lsn), out_(out) {}

  std::optional<StreamError> run() {
    if (sector_ && d_.size() != kSectorBytes) {
      return fail(ErrorKind::ShortSector, 0,
                  "pack of " + std::to_string(d_.size()) + " bytes; every pack is 2048 bytes (truncated stream?)");
    }
    std::size_t pos = start_;
    if (auto e = packHeader(pos)) return e;
    const char* where = sector_ ? "the pack" : "the data";
    while (pos < d_.size()) {
      const std::size_t left = d_.size() - pos;
      if (!sector_ && left < 4) {
        return fail(ErrorKind::Truncated, pos,
                    "the last " + std::to_string(left) + " bytes are too few for a start code (truncated stream?)");
      }
      if (left < 4 || d_[pos] != 0 || d_[pos + 1] != 0 || d_[pos + 2] != 1) {
        return fail(ErrorKind::BadPes, pos,
                    "expected a start code 00 00 01 xx, found " + hexBytes(pos) + " (" + std::to_string(left) +
                        " bytes left in " + where + ")");
      }
      const std::uint8_t id = d_[pos + 3];
      if (id == kProgramEndCode) {
        out_.hasEndCode = true;
        out_.size = pos + 4 - start_;
        return std::nullopt;
      }
      if (id == kPackStartCode && !sector_) break;  // the next pack
      if (id < 0xBB)
        return fail(ErrorKind::BadPes, pos, "start code " + hex(id) + " is not a stream id (expected 0xBB..0xFF)");
      if (left < 6) {
        if (sector_) return fail(ErrorKind::BadPes, pos, "PES header cut by the end of the pack");
        return fail(ErrorKind::Truncated, pos, "PES header cut by the end of the data (truncated stream?)");
      }
      const std::size_t len = (std::size_t{d_[pos + 4]} << 8) | d_[pos + 5];
      const std::size_t end = pos + 6 + len;
      if (end > d_.size()) {
        if (sector_) {
          return fail(ErrorKind::PackOverrun, pos,
                      "packet " + hex(id) + " of " + std::to_string(len + 6) +
                          " bytes overruns the 2048-byte pack by " + std::to_string(end - d_.size()) + " bytes");
        }
        // Keep what there is of a cut PES packet: a decoder may still use the start of its picture.
        if (id != kSystemHeaderStartCode) (void)pesPacket(id, pos, d_.size());
        return fail(ErrorKind::Truncated, pos,
                    "packet " + hex(id) + " of " + std::to_string(len + 6) +
                        " bytes runs past the end of the data by " + std::to_string(end - d_.size()) +
                        " bytes (truncated stream?)");
      }
      if (id == kSystemHeaderStartCode) {
        out_.hasSystemHeader = true;
      } else if (auto e = pesPacket(id, pos, end)) {
        return e;
      }
      pos = end;
    }
    out_.size = pos - start_;
    return std::nullopt;
  }

 private:
  std::uint8_t at(std::size_t i) const { return d_[start_ + i]; }

  // A pack header cut by the end of the data (only a program stream in memory can be cut: a sector is
  // 2048 bytes, more than any pack header).
  std::optional<StreamError> needHeader(std::size_t bytes) const {
    if (d_.size() - start_ >= bytes) return std::nullopt;
    return fail(ErrorKind::Truncated, start_,
                "pack header of " + std::to_string(bytes) + " bytes cut by the end of the data after " +
                    std::to_string(d_.size() - start_) + " bytes (truncated stream?)");
  }

  // Reads the pack header at start_ and moves `pos` past it.
  std::optional<StreamError> packHeader(std::size_t& pos) {
    if (auto e = needHeader(4)) return e;
    if (at(0) != 0 || at(1) != 0 || at(2) != 1 || at(3) != kPackStartCode) {
      return fail(ErrorKind::BadPackHeader, start_,
                  "expected a pack start code 00 00 01 BA, found " + hexBytes(start_));
    }
    if (auto e = needHeader(5)) return e;
    const std::uint8_t b4 = at(4);
    if ((b4 & 0xF0) == 0x20) {
      if (sector_) return fail(ErrorKind::BadPackHeader, start_ + 4, "MPEG-1 pack header; expected MPEG-2 ('01' bits)");
      return mpeg1PackHeader(pos);
    }
    if ((b4 & 0xC0) != 0x40) {
      if (sector_) return fail(ErrorKind::BadPackHeader, start_ + 4, "pack header lacks the MPEG-2 '01' marker");
      return fail(ErrorKind::BadPackHeader, start_ + 4,
                  "pack header is neither MPEG-1 ('0010' bits) nor MPEG-2 ('01' bits)");
    }
    if (auto e = needHeader(kPackHeaderBytes)) return e;
    if (!(b4 & 0x04) || !(at(6) & 0x04) || !(at(8) & 0x04) || !(at(9) & 0x01) || (at(12) & 0x03) != 0x03)
      return fail(ErrorKind::BadPackHeader, start_ + 4, "pack header marker bit is 0 (expected 1)");
    const std::int64_t base = (std::int64_t{(b4 >> 3) & 7} << 30) | (std::int64_t{b4 & 3} << 28) |
                              (std::int64_t{at(5)} << 20) | (std::int64_t{at(6) >> 3} << 15) |
                              (std::int64_t{at(6) & 3} << 13) | (std::int64_t{at(7)} << 5) | (at(8) >> 3);
    const std::int64_t ext = ((at(8) & 3) << 7) | (at(9) >> 1);
    out_.scr27MHz = base * 300 + ext;
    out_.muxRate = (std::uint32_t{at(10)} << 14) | (std::uint32_t{at(11)} << 6) | (at(12) >> 2);
    if (out_.muxRate == 0) return fail(ErrorKind::BadPackHeader, start_ + 10, "program_mux_rate is 0 (forbidden)");
    const std::size_t length = kPackHeaderBytes + (at(13) & 7);  // plus pack_stuffing_length bytes
    if (auto e = needHeader(length)) return e;
    pos = start_ + length;
    return std::nullopt;
  }

  // ISO/IEC 11172-1 §2.4.3.2: '0010', SCR (33 bits, 90 kHz) and mux_rate (22 bits) with marker bits.
  std::optional<StreamError> mpeg1PackHeader(std::size_t& pos) {
    if (auto e = needHeader(kMpeg1PackHeaderBytes)) return e;
    const std::uint8_t b4 = at(4);
    if (!(b4 & 0x01) || !(at(6) & 0x01) || !(at(8) & 0x01) || !(at(9) & 0x80) || !(at(11) & 0x01))
      return fail(ErrorKind::BadPackHeader, start_ + 4, "MPEG-1 pack header marker bit is 0 (expected 1)");
    const std::int64_t scr = (std::int64_t{(b4 >> 1) & 7} << 30) | (std::int64_t{at(5)} << 22) |
                             (std::int64_t{at(6) >> 1} << 15) | (std::int64_t{at(7)} << 7) | (at(8) >> 1);
    out_.mpeg1 = true;
    out_.scr27MHz = scr * 300;
    out_.muxRate = (std::uint32_t{at(9) & 0x7Fu} << 15) | (std::uint32_t{at(10)} << 7) | (at(11) >> 1);
    if (out_.muxRate == 0) return fail(ErrorKind::BadPackHeader, start_ + 9, "mux_rate is 0 (forbidden)");
    pos = start_ + kMpeg1PackHeaderBytes;
    return std::nullopt;
  }

  // The PES packet of stream `id` in [pos, end).
  std::optional<StreamError> pesPacket(std::uint8_t id, std::size_t pos, std::size_t end) {
    PesPacket p;
    p.streamId = id;
    p.offset = pos;
    std::size_t payload = pos + 6;
    if (!hasNoPesHeader(id)) {
      const bool mpeg2 = end - pos > 6 && (d_[pos + 6] & 0xC0) == 0x80;
      if (sector_ || mpeg2) {
        if (auto e = mpeg2PesHeader(id, pos, end, p, payload)) return e;
      } else if (auto e = mpeg1PesHeader(id, pos, end, p, payload)) {
        return e;
      }
    }
    p.payloadOffset = payload;
    p.payload = d_.subspan(payload, end - payload);
    out_.packets.push_back(p);
    return std::nullopt;
  }

  // 13818-1 §2.4.3.6: '10', flags, PES_header_data_length, then the optional fields.
  std::optional<StreamError> mpeg2PesHeader(std::uint8_t id, std::size_t pos, std::size_t end, PesPacket& p,
                                            std::size_t& payload) const {
    if (end - pos < 9) return fail(ErrorKind::BadPes, pos, "PES packet " + hex(id) + " too short for its header");
    if ((d_[pos + 6] & 0xC0) != 0x80) {
      return fail(ErrorKind::BadPes, pos + 6,
                  "PES packet " + hex(id) + " lacks the MPEG-2 '10' header marker (MPEG-1 PES is not supported)");
    }
    const unsigned ptsDts = d_[pos + 7] >> 6;
    const std::size_t headerLen = d_[pos + 8];
    payload = pos + 9 + headerLen;
    if (payload > end) {
      return fail(ErrorKind::BadPes, pos + 8,
                  "PES header length " + std::to_string(headerLen) + " runs past its packet " + hex(id));
    }
    if (ptsDts == 1) return fail(ErrorKind::BadPes, pos + 7, "PTS_DTS_flags '01' is forbidden");
    if (ptsDts >= 2) {
      if (headerLen < 5) return fail(ErrorKind::BadPes, pos + 8, "PTS flag set but PES header is too short");
      return readPts(pos + 9, ptsDts == 3 ? 3 : 2, p);
    }
    return std::nullopt;
  }

  // 11172-1 §2.4.3.3: stuffing bytes 0xFF, an optional STD buffer size ('01'), then a PTS ('0010'),
  // a PTS and a DTS ('0011') or the byte 0x0F.
  std::optional<StreamError> mpeg1PesHeader(std::uint8_t id, std::size_t pos, std::size_t end, PesPacket& p,
                                            std::size_t& payload) const {
    std::size_t q = pos + 6;
    while (q < end && d_[q] == 0xFF) ++q;
    if (q < end && (d_[q] & 0xC0) == 0x40) q += 2;
    std::size_t fields = 0;
    if (q < end && (d_[q] & 0xF0) == 0x20) {
      fields = 5;
    } else if (q < end && (d_[q] & 0xF0) == 0x30) {
      fields = 10;
    } else if (q < end && d_[q] == 0x0F) {
      fields = 1;
    } else {
      return fail(ErrorKind::BadPes, q,
                  "MPEG-1 PES packet " + hex(id) +
                      ": expected a PTS ('0010'), a PTS and DTS ('0011') or 0x0F after the stuffing and STD buffer "
                      "fields");
    }
    if (q + fields > end) return fail(ErrorKind::BadPes, q, "MPEG-1 PES header runs past its packet " + hex(id));
    payload = q + fields;
    if (fields > 1) return readPts(q, fields == 10 ? 3 : 2, p);
    return std::nullopt;
  }

  // The 5-byte PTS field at `pos`: 4-bit prefix, PTS[32..30], marker, PTS[29..15], marker, PTS[14..0],
  // marker (the same layout in MPEG-1 and MPEG-2).
  std::optional<StreamError> readPts(std::size_t pos, unsigned prefix, PesPacket& p) const {
    const std::uint8_t* t = d_.data() + pos;
    if ((t[0] >> 4) != prefix || !(t[0] & 1) || !(t[2] & 1) || !(t[4] & 1))
      return fail(ErrorKind::BadPes, pos, "PTS field prefix or marker bits wrong");
    p.pts = (std::int64_t{(t[0] >> 1) & 7} << 30) | (std::int64_t{t[1]} << 22) | (std::int64_t{t[2] >> 1} << 15) |
            (std::int64_t{t[3]} << 7) | (t[4] >> 1);
    return std::nullopt;
  }

  std::string hexBytes(std::size_t pos) const {
    std::string s;
    for (std::size_t i = pos; i < pos + 4 && i < d_.size(); ++i) s += (s.empty() ? "" : " ") + hex(d_[i]).substr(2);
    return s;
  }

  // A sector's errors are placed by its sector number; a program stream's by their offset in it.
  StreamError fail(ErrorKind kind, std::size_t pos, std::string message) const {
    if (sector_) return StreamError{kind, std::uint64_t{lsn_} * kSectorBytes + pos, lsn_, std::move(message)};
    return StreamError{kind, pos, static_cast<std::uint32_t>(pos / kSectorBytes), std::move(message)};
  }

  std::span<const std::uint8_t> d_;
  std::size_t start_;
  bool sector_;
  std::uint32_t lsn_;
  ParsedPack& out_;
};

}  // namespace

std::optional<StreamError> parsePack(std::span<const std::uint8_t> sector, std::uint32_t lsn, ParsedPack& out) {
  out = ParsedPack{};
  return Parser(sector, 0, true, lsn, out).run();
}

std::optional<StreamError> parsePackAt(std::span<const std::uint8_t> data, std::size_t pos, ParsedPack& out) {
  out = ParsedPack{};
  return Parser(data, pos, false, 0, out).run();
}

}  // namespace vbim::streams
