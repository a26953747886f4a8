// Program streams built byte by byte for the reader's tests, in the layouts other muxers write:
// MPEG-2 packs of any size (ffmpeg `-f vob -packetsize N`) and MPEG-1 system streams (ffmpeg
// `-f mpeg`: one pack header and system header, then PES packets with no further pack header).
// The bits are laid out here from ISO/IEC 13818-1 §2.5.3 and ISO/IEC 11172-1 §2.4.3, independently of
// the muxer in streams/authoring.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace vbim::streams::testing {

using Bytes = std::vector<std::uint8_t>;

inline void append(Bytes& out, const Bytes& part) {
  out.insert(out.end(), part.begin(), part.end());
}

inline std::uint8_t byte(std::uint64_t v) {
  return static_cast<std::uint8_t>(v & 0xFF);
}

// '0010', SCR (90 kHz), mux_rate, with every marker bit set.
inline Bytes mpeg1PackHeader(std::int64_t scr90kHz, std::uint32_t muxRate) {
  const auto s = static_cast<std::uint64_t>(scr90kHz);
  return {0,
          0,
          1,
          0xBA,
          byte(0x21 | ((s >> 29) & 0x0E)),
          byte(s >> 22),
          byte(((s >> 14) & 0xFE) | 1),
          byte(s >> 7),
          byte(((s << 1) & 0xFE) | 1),
          byte(0x80 | (muxRate >> 15)),
          byte(muxRate >> 7),
          byte((muxRate << 1) | 1)};
}

// '01', SCR base and extension (27 MHz), mux_rate, `stuffing` (0..7) bytes 0xFF.
inline Bytes mpeg2PackHeader(std::int64_t scr27MHz, std::uint32_t muxRate, int stuffing = 0) {
  const auto base = static_cast<std::uint64_t>(scr27MHz / 300);
  const auto ext = static_cast<std::uint64_t>(scr27MHz % 300);
  Bytes h = {0,
             0,
             1,
             0xBA,
             byte(0x44 | ((base >> 27) & 0x38) | ((base >> 28) & 0x03)),
             byte(base >> 20),
             byte(((base >> 12) & 0xF8) | 0x04 | ((base >> 13) & 0x03)),
             byte(base >> 5),
             byte(((base << 3) & 0xF8) | 0x04 | ((ext >> 7) & 0x03)),
             byte(((ext << 1) & 0xFE) | 1),
             byte(muxRate >> 14),
             byte(muxRate >> 6),
             byte((muxRate << 2) | 0x03),
             byte(0xF8 | stuffing)};
  h.insert(h.end(), static_cast<std::size_t>(stuffing), 0xFF);
  return h;
}

// A system header naming one video stream (its content is not read by the reader).
inline Bytes systemHeader() {
  return {0, 0, 1, 0xBB, 0, 9, 0x80, 0x01, 0x01, 0x04, 0xE1, 0xFF, 0xE0, 0xE0, 0xE6};
}

// The 5-byte PTS/DTS field with its 4-bit prefix.
inline Bytes ptsField(unsigned prefix, std::int64_t pts) {
  const auto t = static_cast<std::uint64_t>(pts);
  return {byte((prefix << 4) | ((t >> 29) & 0x0E) | 1), byte(t >> 22), byte(((t >> 14) & 0xFE) | 1), byte(t >> 7),
          byte(((t << 1) & 0xFE) | 1)};
}

inline Bytes packet(std::uint8_t id, const Bytes& header, const Bytes& payload) {
  const std::size_t len = header.size() + payload.size();
  Bytes p = {0, 0, 1, id, byte(len >> 8), byte(len)};
  append(p, header);
  append(p, payload);
  return p;
}

// A PES packet with the MPEG-2 header ('10', flags, header length), with a PTS when given and
// `stuffing` bytes 0xFF at the end of the header.
inline Bytes mpeg2Pes(std::uint8_t id, const Bytes& payload, std::optional<std::int64_t> pts = std::nullopt,
                      int stuffing = 0) {
  Bytes header = {0x81, byte(pts ? 0x80 : 0x00), byte((pts ? 5 : 0) + stuffing)};
  if (pts) append(header, ptsField(2, *pts));
  header.insert(header.end(), static_cast<std::size_t>(stuffing), 0xFF);
  return packet(id, header, payload);
}

// A PES packet with the MPEG-1 header: `stuffing` bytes 0xFF, an STD buffer size when `std`, then a
// PTS, a PTS and DTS (`dts`), or 0x0F.
inline Bytes mpeg1Pes(std::uint8_t id, const Bytes& payload, std::optional<std::int64_t> pts = std::nullopt,
                      std::optional<std::int64_t> dts = std::nullopt, int stuffing = 0, bool std = false) {
  Bytes header(static_cast<std::size_t>(stuffing), 0xFF);
  if (std) append(header, {0x60, 0xE6});
  if (pts && dts) {
    append(header, ptsField(3, *pts));
    append(header, ptsField(1, *dts));
  } else if (pts) {
    append(header, ptsField(2, *pts));
  } else {
    header.push_back(0x0F);
  }
  return packet(id, header, payload);
}

// A padding packet of `total` bytes (at least 6) in all.
inline Bytes padding(std::size_t total) {
  return packet(0xBE, {}, Bytes(total - 6, 0xFF));
}

// `es` as video stream `id` in MPEG-2 packs of exactly `packBytes` bytes (the last one padded),
// the first with a system header, as ffmpeg's `-f vob -packetsize` lays them out.
inline Bytes muxMpeg2(const Bytes& es, std::uint8_t id, std::size_t packBytes) {
  Bytes out;
  std::size_t pos = 0;
  for (int n = 0; pos < es.size(); ++n) {
    Bytes pack = mpeg2PackHeader(300 * 3600 * n, 2500, n % 3);
    if (n == 0) append(pack, systemHeader());
    const std::size_t room = packBytes - pack.size() - 9 - (n == 0 ? 5 : 0);
    const std::size_t take = std::min(room, es.size() - pos);
    const Bytes chunk(es.begin() + static_cast<std::ptrdiff_t>(pos),
                      es.begin() + static_cast<std::ptrdiff_t>(pos + take));
    const std::optional<std::int64_t> pts = n == 0 ? std::optional<std::int64_t>(3600) : std::nullopt;
    const std::size_t gap = room - take;
    // A gap too small for a padding packet goes into the PES header as stuffing.
    append(pack, mpeg2Pes(id, chunk, pts, gap < 6 ? static_cast<int>(gap) : 0));
    if (gap >= 6) append(pack, padding(gap));
    pos += take;
    append(out, pack);
  }
  return out;
}

// `es` as video stream `id` in an MPEG-1 system stream: one pack header and a system header, then PES
// packets of `packetBytes` bytes with no further pack header, the first with a PTS, then a padding
// packet and the end code, as ffmpeg's `-f mpeg` writes short streams.
inline Bytes muxMpeg1(const Bytes& es, std::uint8_t id, std::size_t packetBytes) {
  Bytes out = mpeg1PackHeader(0, 275276);
  append(out, systemHeader());
  std::size_t pos = 0;
  for (int n = 0; pos < es.size(); ++n) {
    const std::size_t header = n == 0 ? 6 + 5 : 6 + 1;
    const std::size_t take = std::min(packetBytes - header, es.size() - pos);
    const Bytes chunk(es.begin() + static_cast<std::ptrdiff_t>(pos),
                      es.begin() + static_cast<std::ptrdiff_t>(pos + take));
    append(out, mpeg1Pes(id, chunk, n == 0 ? std::optional<std::int64_t>(3600) : std::nullopt));
    pos += take;
  }
  append(out, padding(100));
  append(out, {0, 0, 1, 0xB9});
  return out;
}

}  // namespace vbim::streams::testing
