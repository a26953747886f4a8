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

class Parser {
 public:
  Parser(std::span<const std::uint8_t> s, std::uint32_t lsn, ParsedPack& out) : s_(s), lsn_(lsn), out_(out) {}

  std::optional<StreamError> run() {
    if (s_.size() != kSectorBytes)
      return fail(ErrorKind::ShortSector, 0,
                  "pack of " + std::to_string(s_.size()) + " bytes; every pack is 2048 bytes (truncated stream?)");
    if (auto e = packHeader()) return e;
    std::size_t pos = kPackHeaderBytes + (s_[13] & 7);
    while (pos < s_.size()) {
      if (s_.size() - pos < 4 || s_[pos] != 0 || s_[pos + 1] != 0 || s_[pos + 2] != 1)
        return fail(ErrorKind::BadPes, pos,
                    "expected a start code 00 00 01 xx, found " + hexBytes(pos) + " (" +
                        std::to_string(s_.size() - pos) + " bytes left in the pack)");
      const std::uint8_t id = s_[pos + 3];
      if (id == kProgramEndCode) {
        out_.hasEndCode = true;
        return std::nullopt;
      }
      if (id < 0xBB)
        return fail(ErrorKind::BadPes, pos, "start code " + hex(id) + " is not a stream id (expected 0xBB..0xFF)");
      if (s_.size() - pos < 6) return fail(ErrorKind::BadPes, pos, "PES header cut by the end of the pack");
      const std::size_t len = (std::size_t{s_[pos + 4]} << 8) | s_[pos + 5];
      const std::size_t end = pos + 6 + len;
      if (end > s_.size())
        return fail(ErrorKind::PackOverrun, pos,
                    "packet " + hex(id) + " of " + std::to_string(len + 6) + " bytes overruns the 2048-byte pack by " +
                        std::to_string(end - s_.size()) + " bytes");
      if (id == kSystemHeaderStartCode) {
        out_.hasSystemHeader = true;
      } else if (auto e = pesPacket(id, pos, end)) {
        return e;
      }
      pos = end;
    }
    return std::nullopt;
  }

 private:
  std::optional<StreamError> packHeader() {
    if (s_[0] != 0 || s_[1] != 0 || s_[2] != 1 || s_[3] != kPackStartCode)
      return fail(ErrorKind::BadPackHeader, 0, "expected a pack start code 00 00 01 BA, found " + hexBytes(0));
    const std::uint8_t b4 = s_[4];
    if ((b4 & 0xF0) == 0x20)
      return fail(ErrorKind::BadPackHeader, 4, "MPEG-1 pack header; expected MPEG-2 ('01' bits)");
    if ((b4 & 0xC0) != 0x40) return fail(ErrorKind::BadPackHeader, 4, "pack header lacks the MPEG-2 '01' marker");
    if (!(b4 & 0x04) || !(s_[6] & 0x04) || !(s_[8] & 0x04) || !(s_[9] & 0x01) || (s_[12] & 0x03) != 0x03)
      return fail(ErrorKind::BadPackHeader, 4, "pack header marker bit is 0 (expected 1)");
    const std::int64_t base = (std::int64_t{(b4 >> 3) & 7} << 30) | (std::int64_t{b4 & 3} << 28) |
                              (std::int64_t{s_[5]} << 20) | (std::int64_t{s_[6] >> 3} << 15) |
                              (std::int64_t{s_[6] & 3} << 13) | (std::int64_t{s_[7]} << 5) | (s_[8] >> 3);
    const std::int64_t ext = ((s_[8] & 3) << 7) | (s_[9] >> 1);
    out_.scr27MHz = base * 300 + ext;
    out_.muxRate = (std::uint32_t{s_[10]} << 14) | (std::uint32_t{s_[11]} << 6) | (s_[12] >> 2);
    if (out_.muxRate == 0) return fail(ErrorKind::BadPackHeader, 10, "program_mux_rate is 0 (forbidden)");
    return std::nullopt;
  }

  std::optional<StreamError> pesPacket(std::uint8_t id, std::size_t pos, std::size_t end) {
    PesPacket p;
    p.streamId = id;
    p.offset = static_cast<std::uint32_t>(pos);
    std::size_t payload = pos + 6;
    if (!hasNoPesHeader(id)) {
      if (end - pos < 9) return fail(ErrorKind::BadPes, pos, "PES packet " + hex(id) + " too short for its header");
      if ((s_[pos + 6] & 0xC0) != 0x80)
        return fail(ErrorKind::BadPes, pos + 6,
                    "PES packet " + hex(id) + " lacks the MPEG-2 '10' header marker (MPEG-1 PES is not supported)");
      const unsigned ptsDts = s_[pos + 7] >> 6;
      const std::size_t headerLen = s_[pos + 8];
      payload = pos + 9 + headerLen;
      if (payload > end)
        return fail(ErrorKind::BadPes, pos + 8,
                    "PES header length " + std::to_string(headerLen) + " runs past its packet " + hex(id));
      if (ptsDts == 1) return fail(ErrorKind::BadPes, pos + 7, "PTS_DTS_flags '01' is forbidden");
      if (ptsDts >= 2) {
        if (headerLen < 5) return fail(ErrorKind::BadPes, pos + 8, "PTS flag set but PES header is too short");
        const std::uint8_t* t = s_.data() + pos + 9;
        if ((t[0] >> 4) != (ptsDts == 3 ? 3 : 2) || !(t[0] & 1) || !(t[2] & 1) || !(t[4] & 1))
          return fail(ErrorKind::BadPes, pos + 9, "PTS field prefix or marker bits wrong");
        p.pts = (std::int64_t{(t[0] >> 1) & 7} << 30) | (std::int64_t{t[1]} << 22) | (std::int64_t{t[2] >> 1} << 15) |
                (std::int64_t{t[3]} << 7) | (t[4] >> 1);
      }
    }
    p.payloadOffset = static_cast<std::uint32_t>(payload);
    p.payload = s_.subspan(payload, end - payload);
    out_.packets.push_back(p);
    return std::nullopt;
  }

  std::string hexBytes(std::size_t pos) const {
    std::string s;
    for (std::size_t i = pos; i < pos + 4 && i < s_.size(); ++i) s += (s.empty() ? "" : " ") + hex(s_[i]).substr(2);
    return s;
  }

  StreamError fail(ErrorKind kind, std::size_t pos, std::string message) const {
    return StreamError{kind, std::uint64_t{lsn_} * kSectorBytes + pos, lsn_, std::move(message)};
  }

  std::span<const std::uint8_t> s_;
  std::uint32_t lsn_;
  ParsedPack& out_;
};

}  // namespace

std::optional<StreamError> parsePack(std::span<const std::uint8_t> sector, std::uint32_t lsn, ParsedPack& out) {
  out = ParsedPack{};
  return Parser(sector, lsn, out).run();
}

}  // namespace vbim::streams
