// libFuzzer target: the pack parser and the demuxer (with the descriptor reader they feed) on any
// bytes, read as a whole stream and as sectors fed with gaps and seeks. They must report damage,
// never crash, read out of bounds or hang.
#include <cstddef>
#include <cstdint>
#include <span>

#include "streams/demuxer.hpp"
#include "streams/format.hpp"
#include "streams/pack_parser.hpp"
#include "streams/stream_stats.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  (void)vbim::streams::scanStream(bytes);
  vbim::streams::ParsedPack pack;
  for (std::size_t pos = 0; pos < size && pos < 4 * vbim::streams::kSectorBytes; pos += 97)
    (void)vbim::streams::parsePackAt(bytes, pos, pack);
  // Sectors out of order: the first byte of each sector picks a jump, a seek or the next number.
  vbim::streams::Demuxer d;
  std::uint32_t lsn = 0;
  for (std::size_t at = 0; at < size; at += vbim::streams::kSectorBytes) {
    const auto sector = bytes.subspan(at, std::min(vbim::streams::kSectorBytes, size - at));
    if (sector[0] % 7 == 0) d.seek();
    lsn = sector[0] % 5 == 0 ? lsn + sector[0] : lsn + 1;
    d.feed(sector, lsn);
    d.pictures().clear();
  }
  d.finish();
  return 0;
}
