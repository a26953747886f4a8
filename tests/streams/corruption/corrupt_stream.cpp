// vbim_corrupt: writes a damaged copy of a VBIM stream, for the corruption harness
// (scripts/corruption-check.sh, issue #16). Seeded: the same input, kind and seed give the same
// bytes.
//
//   vbim_corrupt IN OUT KIND SEED
//
// KIND (a sector is one 2048-byte pack, docs/stream-format.md; a ring bank is 32 sectors,
// iop/params.hpp):
//   bitflips      1-64 random bits flipped anywhere
//   zeros         1-4 runs of 16-4096 zero bytes
//   truncate      cut at a random byte (also mid-sector)
//   drop          1-4 whole sectors removed
//   duplicate     1-4 sectors repeated in place
//   reorder       two sectors, or two runs of sectors, swapped
//   bank_loss     the sectors around a ring-bank boundary (32 k - 2 .. 32 k + 1) lost or zeroed
//   pack_header   bytes of 1-4 pack headers (00 00 01 BA ...) randomised
//   pes_header    bytes of 1-4 video PES headers (00 00 01 E0/E1 ...) randomised
//   sequence      bytes of 1-4 sequence headers (00 00 01 B3 ...) randomised
//   descriptor    bytes of the playback descriptor (private_stream_2 in the first packs) randomised
//   descriptor_text  the first variant's name in the descriptor replaced by bytes that are not UTF-8,
//                 with the descriptor's CRC-32 made right again, so readers take the name as given
//   sky           payload bytes of 1-8 sky PES packets (00 00 01 E1) randomised or zeroed
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

namespace {

constexpr std::size_t kSector = 2048;
constexpr std::size_t kBankSectors = 32;

using Bytes = std::vector<std::uint8_t>;

struct Damage {
  Bytes b;
  std::mt19937_64 rng;

  std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(rng() % n); }
  std::size_t between(std::size_t lo, std::size_t hi) { return lo + below(hi - lo + 1); }
  std::size_t sectors() const { return b.size() / kSector; }

  // Offsets where 00 00 01 <code> starts, for codes in [lo, hi].
  std::vector<std::size_t> startCodes(std::uint8_t lo, std::uint8_t hi) const {
    std::vector<std::size_t> at;
    for (std::size_t i = 0; i + 3 < b.size(); ++i) {
      if (b[i] == 0 && b[i + 1] == 0 && b[i + 2] == 1 && b[i + 3] >= lo && b[i + 3] <= hi) at.push_back(i);
    }
    return at;
  }
  void randomise(std::size_t from, std::size_t n) {
    for (std::size_t i = from; i < from + n && i < b.size(); ++i) b[i] = static_cast<std::uint8_t>(rng());
  }
  // Randomises a few bytes of 1..maxHits of the headers starting at `at` (the start code itself
  // included now and then).
  void mangle(const std::vector<std::size_t>& at, std::size_t maxHits, std::size_t span) {
    if (at.empty()) return;
    const std::size_t hits = between(1, maxHits);
    for (std::size_t h = 0; h < hits; ++h) {
      const std::size_t where = at[below(at.size())];
      const std::size_t first = where + (below(4) == 0 ? 0 : 4);
      const std::size_t n = between(1, 4);
      for (std::size_t k = 0; k < n; ++k) randomise(first + below(span), 1);
    }
  }
  void eraseSectors(std::size_t first, std::size_t n) {
    first = std::min(first, sectors());
    n = std::min(n, sectors() - first);
    b.erase(b.begin() + static_cast<std::ptrdiff_t>(first * kSector),
            b.begin() + static_cast<std::ptrdiff_t>((first + n) * kSector));
  }
};

// CRC-32 (IEEE, as zlib), bit by bit: the descriptor's checksum (docs/stream-format.md).
std::uint32_t crc32(const std::uint8_t* p, std::size_t n) {
  std::uint32_t c = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < n; ++i) {
    c ^= p[i];
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
  }
  return ~c;
}

std::uint32_t be32(const Bytes& b, std::size_t at) {
  return (std::uint32_t{b[at]} << 24) | (std::uint32_t{b[at + 1]} << 16) | (std::uint32_t{b[at + 2]} << 8) | b[at + 3];
}

// The first variant's name (24 bytes at body offset 48 + 8 S) gets bytes that are not UTF-8, then
// the CRC-32 at body offset 44 is recomputed. False if the body is not in one chunk.
bool damageDescriptorText(Damage& d) {
  const auto at = d.startCodes(0xBF, 0xBF);
  if (at.empty()) return false;
  // The PES payload starts with a 12-byte chunk header ('VBIM', index, count, data bytes n,
  // reserved); a body in one chunk (count 1) is the n bytes after it.
  const std::size_t chunk = at.front() + 6;
  if (chunk + 12 + 48 > d.b.size() || d.b[chunk] != 'V' || d.b[chunk + 6] != 0 || d.b[chunk + 7] != 1) return false;
  const std::size_t length = (std::size_t{d.b[chunk + 8]} << 8) | d.b[chunk + 9];
  const std::size_t body = chunk + 12;
  if (d.b[body] != 0 || d.b[body + 1] != 1) return false;
  const std::size_t streams = d.b[body + 20], variants = d.b[body + 21];
  const std::size_t frames = be32(d.b, body + 12);
  const std::size_t size = 48 + 8 * streams + 32 * variants + 16 * streams * variants * frames;
  if (variants == 0 || size > length || body + size > d.b.size()) return false;
  const std::size_t name = body + 48 + 8 * streams;
  std::size_t nameLength = 0;
  while (nameLength < 24 && d.b[name + nameLength] != 0) ++nameLength;
  // Inside the name (bytes after its NUL are padding no reader looks at): a lead byte followed by
  // '(' (never well-formed), then now and then a lone continuation byte.
  const std::size_t first = d.below(nameLength > 1 ? nameLength - 1 : 1);
  d.b[name + first] = static_cast<std::uint8_t>(0xC2 + d.below(0x33));
  d.b[name + first + 1] = '(';
  if (first + 2 < 23 && d.below(2) == 0) d.b[name + first + 2] = static_cast<std::uint8_t>(0x80 + d.below(0x40));
  for (std::size_t i = 0; i < 4; ++i) d.b[body + 44 + i] = 0;
  const std::uint32_t crc = crc32(&d.b[body], size);
  for (std::size_t i = 0; i < 4; ++i) d.b[body + 44 + i] = static_cast<std::uint8_t>(crc >> (24 - 8 * i));
  return true;
}

bool apply(Damage& d, const std::string& kind) {
  const std::size_t sectors = d.sectors();
  if (kind == "bitflips") {
    const std::size_t n = d.between(1, 64);
    for (std::size_t i = 0; i < n; ++i) d.b[d.below(d.b.size())] ^= static_cast<std::uint8_t>(1u << d.below(8));
  } else if (kind == "zeros") {
    const std::size_t runs = d.between(1, 4);
    for (std::size_t r = 0; r < runs; ++r) {
      const std::size_t n = d.between(16, 4096);
      const std::size_t at = d.below(d.b.size());
      for (std::size_t i = at; i < at + n && i < d.b.size(); ++i) d.b[i] = 0;
    }
  } else if (kind == "truncate") {
    d.b.resize(d.below(d.b.size()));
  } else if (kind == "drop") {
    const std::size_t n = d.between(1, 4);
    for (std::size_t i = 0; i < n && d.sectors() > 1; ++i) d.eraseSectors(d.below(d.sectors()), d.between(1, 3));
  } else if (kind == "duplicate") {
    const std::size_t n = d.between(1, 4);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t s = d.below(d.sectors());
      const Bytes copy(d.b.begin() + static_cast<std::ptrdiff_t>(s * kSector),
                       d.b.begin() + static_cast<std::ptrdiff_t>((s + 1) * kSector));
      d.b.insert(d.b.begin() + static_cast<std::ptrdiff_t>(s * kSector), copy.begin(), copy.end());
    }
  } else if (kind == "reorder") {
    const std::size_t run = d.between(1, 4);
    if (sectors < 2 * run) return false;
    const std::size_t a = d.below(sectors - 2 * run + 1);
    const std::size_t c = a + run + d.below(sectors - a - 2 * run + 1);
    std::swap_ranges(d.b.begin() + static_cast<std::ptrdiff_t>(a * kSector),
                     d.b.begin() + static_cast<std::ptrdiff_t>((a + run) * kSector),
                     d.b.begin() + static_cast<std::ptrdiff_t>(c * kSector));
  } else if (kind == "bank_loss") {
    if (sectors <= kBankSectors) return false;
    const std::size_t banks = (sectors - 1) / kBankSectors;
    const std::size_t boundary = kBankSectors * d.between(1, banks);
    const std::size_t first = boundary - d.between(0, 2);
    const std::size_t n = d.between(1, 3);
    if (d.below(2) == 0) {
      d.eraseSectors(first, n);  // the sectors never arrive
    } else {
      for (std::size_t i = first * kSector; i < (first + n) * kSector && i < d.b.size(); ++i) d.b[i] = 0;
    }
  } else if (kind == "pack_header") {
    d.mangle(d.startCodes(0xBA, 0xBA), 4, 14);
  } else if (kind == "pes_header") {
    d.mangle(d.startCodes(0xE0, 0xE1), 4, 9);
  } else if (kind == "sequence") {
    d.mangle(d.startCodes(0xB3, 0xB3), 4, 12);
  } else if (kind == "descriptor") {
    const auto at = d.startCodes(0xBF, 0xBF);
    if (at.empty()) return false;
    const std::size_t hits = d.between(1, 8);
    for (std::size_t h = 0; h < hits; ++h) {
      const std::size_t where = at[d.below(at.size())];
      d.randomise(where + d.below(64), d.between(1, 4));  // the PES header and the body's first fields
    }
  } else if (kind == "descriptor_text") {
    return damageDescriptorText(d);
  } else if (kind == "sky") {
    const auto at = d.startCodes(0xE1, 0xE1);
    if (at.empty()) return false;
    const std::size_t hits = d.between(1, 8);
    for (std::size_t h = 0; h < hits; ++h) {
      const std::size_t from = at[d.below(at.size())] + 9 + d.below(256);
      const std::size_t n = d.between(1, 512);
      if (d.below(2) == 0) {
        d.randomise(from, n);
      } else {
        for (std::size_t i = from; i < from + n && i < d.b.size(); ++i) d.b[i] = 0;
      }
    }
  } else {
    std::cerr << "vbim_corrupt: unknown kind '" << kind << "'\n";
    std::exit(2);
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::cerr << "usage: vbim_corrupt IN OUT KIND SEED (kinds: see the source's header)\n";
    return 2;
  }
  std::ifstream in(argv[1], std::ios::binary);
  if (!in) {
    std::cerr << "vbim_corrupt: " << argv[1] << ": cannot open\n";
    return 2;
  }
  Damage d{Bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()),
           std::mt19937_64(std::strtoull(argv[4], nullptr, 10))};
  if (d.b.size() < kSector) {
    std::cerr << "vbim_corrupt: " << argv[1] << ": shorter than one sector\n";
    return 2;
  }
  if (!apply(d, argv[3])) {
    std::cerr << "vbim_corrupt: " << argv[1] << ": nothing to damage for '" << argv[3] << "'\n";
    return 3;  // the harness skips this combination
  }
  const std::string tmp = std::string(argv[2]) + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    out.write(reinterpret_cast<const char*>(d.b.data()), static_cast<std::streamsize>(d.b.size()));
    if (!out) {
      std::cerr << "vbim_corrupt: " << tmp << ": cannot write\n";
      return 2;
    }
  }
  if (std::rename(tmp.c_str(), argv[2]) != 0) {
    std::cerr << "vbim_corrupt: " << argv[2] << ": cannot rename into place\n";
    return 2;
  }
  return 0;
}
