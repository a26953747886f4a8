#include "streams/descriptor_packs.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "streams/format.hpp"

namespace vbim::streams {

namespace {
constexpr std::size_t kPesHeaderBytes = 6;  // private_stream_2 has no optional PES header

std::size_t capacity(std::size_t systemHeaderBytes) {
  return kSectorBytes - kPackHeaderBytes - systemHeaderBytes - kPesHeaderBytes - kChunkHeaderBytes;
}
}  // namespace

std::optional<DescriptorChunk> parseDescriptorChunk(std::span<const std::uint8_t> payload, ChunkMagic magic) {
  if (payload.size() < kChunkHeaderBytes || std::memcmp(payload.data(), magic.data(), 4) != 0) return std::nullopt;
  DescriptorChunk c;
  c.index = static_cast<std::uint16_t>((payload[4] << 8) | payload[5]);
  c.count = static_cast<std::uint16_t>((payload[6] << 8) | payload[7]);
  const std::size_t bytes = (std::size_t{payload[8]} << 8) | payload[9];
  if (c.count == 0 || c.index >= c.count || bytes > payload.size() - kChunkHeaderBytes) return std::nullopt;
  c.data = payload.subspan(kChunkHeaderBytes, bytes);
  return c;
}

std::size_t descriptorPackCount(std::size_t bodyBytes, std::size_t systemHeaderBytes) {
  const std::size_t first = capacity(systemHeaderBytes);
  if (bodyBytes <= first) return 1;
  const std::size_t rest = capacity(0);
  return 1 + (bodyBytes - first + rest - 1) / rest;
}

void writePackHeader(std::uint8_t* p, std::int64_t scr27MHz, std::uint32_t muxRate) {
  const std::uint64_t base = static_cast<std::uint64_t>(scr27MHz / 300) & ((1ull << 33) - 1);
  const std::uint32_t ext = static_cast<std::uint32_t>(scr27MHz % 300);
  p[0] = 0;
  p[1] = 0;
  p[2] = 1;
  p[3] = kPackStartCode;
  p[4] = static_cast<std::uint8_t>(0x40 | ((base >> 27) & 0x38) | 0x04 | ((base >> 28) & 3));
  p[5] = static_cast<std::uint8_t>(base >> 20);
  p[6] = static_cast<std::uint8_t>(((base >> 12) & 0xF8) | 0x04 | ((base >> 13) & 3));
  p[7] = static_cast<std::uint8_t>(base >> 5);
  p[8] = static_cast<std::uint8_t>(((base << 3) & 0xF8) | 0x04 | ((ext >> 7) & 3));
  p[9] = static_cast<std::uint8_t>(((ext << 1) & 0xFE) | 1);
  p[10] = static_cast<std::uint8_t>(muxRate >> 14);
  p[11] = static_cast<std::uint8_t>(muxRate >> 6);
  p[12] = static_cast<std::uint8_t>(((muxRate << 2) & 0xFC) | 3);
  p[13] = 0xF8;  // reserved '11111', pack_stuffing_length 0
}

std::vector<std::uint8_t> makeDescriptorPacks(std::span<const std::uint8_t> body,
                                              std::span<const std::uint8_t> systemHeader, std::uint32_t muxRate,
                                              std::span<const std::int64_t> scr27MHz, ChunkMagic magic) {
  const std::size_t count = descriptorPackCount(body.size(), systemHeader.size());
  if (count > 0xFFFF) throw std::invalid_argument("descriptor needs more than 65535 packs");
  if (scr27MHz.size() != count) throw std::invalid_argument("one SCR per descriptor pack is needed");
  std::vector<std::uint8_t> out(count * kSectorBytes, 0);
  std::size_t done = 0;
  for (std::size_t i = 0; i < count; ++i) {
    std::uint8_t* p = out.data() + i * kSectorBytes;
    writePackHeader(p, scr27MHz[i], muxRate);
    std::size_t pos = kPackHeaderBytes;
    const std::span<const std::uint8_t> sys = i == 0 ? systemHeader : std::span<const std::uint8_t>{};
    std::copy(sys.begin(), sys.end(), p + pos);
    pos += sys.size();
    const std::size_t pesLen = kSectorBytes - pos - kPesHeaderBytes;  // the packet fills the pack
    p[pos] = 0;
    p[pos + 1] = 0;
    p[pos + 2] = 1;
    p[pos + 3] = kPrivateStream2;
    p[pos + 4] = static_cast<std::uint8_t>(pesLen >> 8);
    p[pos + 5] = static_cast<std::uint8_t>(pesLen);
    pos += kPesHeaderBytes;
    const std::size_t n = std::min(capacity(sys.size()), body.size() - done);
    std::memcpy(p + pos, magic.data(), 4);
    p[pos + 4] = static_cast<std::uint8_t>(i >> 8);
    p[pos + 5] = static_cast<std::uint8_t>(i);
    p[pos + 6] = static_cast<std::uint8_t>(count >> 8);
    p[pos + 7] = static_cast<std::uint8_t>(count);
    p[pos + 8] = static_cast<std::uint8_t>(n >> 8);
    p[pos + 9] = static_cast<std::uint8_t>(n);
    std::copy(body.begin() + static_cast<std::ptrdiff_t>(done), body.begin() + static_cast<std::ptrdiff_t>(done + n),
              p + pos + kChunkHeaderBytes);
    done += n;
  }
  return out;
}

}  // namespace vbim::streams
