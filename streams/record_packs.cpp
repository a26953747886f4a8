#include "streams/record_packs.hpp"

#include <map>
#include <stdexcept>

#include "streams/format.hpp"
#include "streams/pack_parser.hpp"

namespace vbim::streams {

std::size_t authoringRecordSectors(std::size_t textBytes) {
  return descriptorPackCount(textBytes, 0);
}

void appendAuthoringRecord(std::vector<std::uint8_t>& stream, std::string_view text) {
  if (stream.empty() || stream.size() % kSectorBytes != 0) {
    throw std::invalid_argument("the authoring record follows whole 2048-byte packs");
  }
  ParsedPack last;
  const std::span<const std::uint8_t> lastSector(stream.data() + stream.size() - kSectorBytes, kSectorBytes);
  if (parsePack(lastSector, 0, last) || last.muxRate == 0) {
    throw std::invalid_argument("the stream's last sector is not a well-formed pack");
  }
  // One pack time at the mux rate (50 B/s units) on the 27 MHz clock, as the descriptor packs count.
  const std::int64_t packTicks = static_cast<std::int64_t>(kSectorBytes) * 27'000'000 / (last.muxRate * 50LL);
  const auto body = std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  std::vector<std::int64_t> scr(authoringRecordSectors(text.size()));
  for (std::size_t i = 0; i < scr.size(); ++i) scr[i] = last.scr27MHz + static_cast<std::int64_t>(i + 1) * packTicks;
  const std::vector<std::uint8_t> packs = makeDescriptorPacks(body, {}, last.muxRate, scr, ChunkMagic(kAuthoringMagic));
  stream.insert(stream.end(), packs.begin(), packs.end());
}

std::optional<std::string> findAuthoringRecord(std::span<const std::uint8_t> sectors) {
  std::map<std::uint16_t, std::span<const std::uint8_t>> chunks;
  std::uint16_t count = 0;
  for (std::size_t at = 0; at + kSectorBytes <= sectors.size(); at += kSectorBytes) {
    ParsedPack pack;
    if (parsePack(sectors.subspan(at, kSectorBytes), 0, pack)) continue;
    for (const PesPacket& p : pack.packets) {
      if (p.streamId != kPrivateStream2) continue;
      const auto c = parseDescriptorChunk(p.payload, ChunkMagic(kAuthoringMagic));
      if (!c || (count != 0 && c->count != count)) continue;
      count = c->count;
      chunks[c->index] = c->data;
    }
  }
  if (count == 0 || chunks.size() != count) return std::nullopt;
  std::string text;
  for (const auto& [index, data] : chunks) text.append(data.begin(), data.end());
  return text;
}

}  // namespace vbim::streams
