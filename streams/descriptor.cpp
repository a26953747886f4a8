#include "streams/descriptor.hpp"

#include <stdexcept>

#include "streams/byte_io.hpp"
#include "streams/crc32.hpp"
#include "streams/format.hpp"

namespace vbim::streams {

namespace {
constexpr std::size_t kCrcOffset = 44;

// Version 2's u16 after an index entry's offset: bits 0-1 picture_coding_type (1 I, 2 P, 3 B), bit 2
// GOP start, bit 3 closed GOP, the rest 0 (docs/stream-format.md).
constexpr std::uint16_t kTypeMask = 3, kGopStartBit = 4, kClosedGopBit = 8;

std::uint16_t pictureFlags(const IndexEntry& e) {
  return static_cast<std::uint16_t>(static_cast<unsigned>(e.type) | (e.gopStart ? kGopStartBit : 0) |
                                    (e.closedGop ? kClosedGopBit : 0));
}
}  // namespace

int Descriptor::streamIndex(std::uint8_t id) const {
  for (std::size_t i = 0; i < streams.size(); ++i)
    if (streams[i].id == id) return static_cast<int>(i);
  return -1;
}

std::optional<std::uint32_t> Descriptor::frameOfPts(std::int64_t pts) const {
  if (ptsPerFrame == 0 || pts < firstPts) return std::nullopt;
  const std::int64_t d = pts - firstPts;
  if (d % ptsPerFrame != 0) return std::nullopt;
  const std::int64_t f = d / ptsPerFrame;
  if (f >= totalFrames()) return std::nullopt;
  return static_cast<std::uint32_t>(f);
}

bool Descriptor::intraOnly() const {
  for (const auto& table : index) {
    for (const IndexEntry& e : table) {
      if (e.type != PictureType::I) return false;
    }
  }
  return true;
}

std::uint32_t Descriptor::resumeFrame(std::size_t s, std::uint32_t g) const {
  const std::uint32_t first = g - g % framesPerVariant;
  while (g > first && !index[s][g].gopStart) --g;
  return g;
}

std::string Descriptor::validate() const {
  if (gameFps.num == 0 || gameFps.den == 0) return "game frame rate must be a positive rational";
  if (framesPerVariant == 0) return "a variant must hold at least one frame";
  if (loopFrame >= framesPerVariant) {
    return "loop frame " + std::to_string(loopFrame) + " is not below the frame count " +
           std::to_string(framesPerVariant);
  }
  if (streams.empty() || streams.size() > 2) return "a stream holds 1 or 2 video streams";
  if (variants.empty() || variants.size() > 255) return "a stream holds 1 to 255 variants";
  if (std::uint64_t{framesPerVariant} * variants.size() > 0xFFFFFFFFull) return "too many frames";
  for (std::size_t v = 0; v < variants.size(); ++v) {
    const Variant& var = variants[v];
    if (var.name.empty() || var.name.size() > kMaxVariantName)
      return "variant name '" + var.name + "' must have 1 to " + std::to_string(kMaxVariantName) + " bytes";
    if (var.name.find('\0') != std::string::npos) return "variant name contains a NUL byte";
    for (std::size_t w = 0; w < v; ++w)
      if (variants[w].name == var.name) return "variant name '" + var.name + "' is used twice";
    if (var.firstFrame != v * framesPerVariant) return "variant '" + var.name + "' does not start at its frame";
  }
  if (index.size() != streams.size()) return "index must have one table per stream";
  for (const auto& table : index)
    if (table.size() != totalFrames()) return "index table must have one entry per frame";
  // A loop, seek or branch resumes at an I picture: every variant's first frame and loop frame start a
  // GOP (the writer forces them, StreamWriter::addFrame).
  for (std::size_t s = 0; s < index.size(); ++s) {
    for (std::uint32_t v = 0; v < variants.size(); ++v) {
      for (const std::uint32_t f : {std::uint32_t{0}, loopFrame}) {
        const IndexEntry& e = index[s][v * framesPerVariant + f];
        if (!e.gopStart || e.type != PictureType::I) {
          return "frame " + std::to_string(f) + " of variant '" + variants[v].name + "' (stream " + std::to_string(s) +
                 ") is not an I picture that starts a GOP (a loop or branch must resume at one)";
        }
      }
      for (std::uint32_t f = 0; f < framesPerVariant; ++f) {
        const IndexEntry& e = index[s][v * framesPerVariant + f];
        if (e.gopStart && e.type != PictureType::I) return "a GOP starts at a picture that is not an I picture";
      }
      // A B picture is decoded after the reference that follows it: a variant that ends on one
      // needs the next variant's picture, so neither it nor a loop lap decodes on its own
      // (ee/decode_order.hpp). The writer ends each variant on a reference.
      if (index[s][v * framesPerVariant + framesPerVariant - 1].type == PictureType::B) {
        return "the last frame of variant '" + variants[v].name + "' (stream " + std::to_string(s) +
               ") is a B picture (a variant must end on an I or P picture)";
      }
    }
  }
  return {};
}

std::size_t serializedSize(std::size_t streams, std::size_t variants, std::size_t framesPerVariant) {
  return Descriptor::kHeaderBytes + streams * Descriptor::kStreamBytes + variants * Descriptor::kVariantBytes +
         streams * variants * framesPerVariant * Descriptor::kEntryBytes;
}

std::vector<std::uint8_t> serialize(const Descriptor& d) {
  if (std::string why = d.validate(); !why.empty()) throw std::invalid_argument("descriptor: " + why);
  const bool v1 = d.intraOnly();
  ByteWriter w;
  w.u16(v1 ? Descriptor::kVersionIntra : Descriptor::kVersion);
  w.u16(Descriptor::kHeaderBytes);
  w.u32(d.gameFps.num);
  w.u32(d.gameFps.den);
  w.u32(d.framesPerVariant);
  w.u32(d.loopFrame);
  w.u8(static_cast<std::uint8_t>(d.streams.size()));
  w.u8(static_cast<std::uint8_t>(d.variants.size()));
  w.u16(0);
  w.u64(static_cast<std::uint64_t>(d.firstPts));
  w.u32(d.ptsPerFrame);
  w.u32(d.descriptorSectors);
  w.u32(d.totalSectors);
  w.u32(0);  // CRC, filled below
  for (const StreamEntry& s : d.streams) {
    w.u8(s.id);
    w.u8(static_cast<std::uint8_t>(s.role));
    w.u16(s.width);
    w.u16(s.height);
    w.u16(0);
  }
  for (const Variant& v : d.variants) {
    w.bytes(v.name.data(), v.name.size());
    w.zeros(24 - v.name.size());
    w.u32(v.firstFrame);
    w.u32(v.firstSector);
  }
  for (const auto& table : d.index) {
    for (const IndexEntry& e : table) {
      w.u32(e.sector);
      w.u16(e.offset);
      w.u16(v1 ? 0 : pictureFlags(e));
      w.u32(e.bytes);
      w.u32(e.crc);
    }
  }
  std::vector<std::uint8_t> out = w.take();
  const std::uint32_t crc = crc32(out);
  for (int i = 0; i < 4; ++i) out[kCrcOffset + i] = static_cast<std::uint8_t>(crc >> (24 - 8 * i));
  return out;
}

DescriptorParse parseDescriptor(std::span<const std::uint8_t> body) {
  DescriptorParse r;
  auto fail = [&](std::size_t at, std::string why) {
    r.errorOffset = at;
    r.error = std::move(why);
    return r;
  };
  if (body.size() < Descriptor::kHeaderBytes)
    return fail(body.size(), "descriptor of " + std::to_string(body.size()) + " bytes; the header alone is 48");
  ByteReader in(body);
  Descriptor d;
  const std::uint16_t version = in.u16();
  if (version != Descriptor::kVersionIntra && version != Descriptor::kVersion) {
    return fail(0, "descriptor version " + std::to_string(version) + "; this reader knows versions 1 and 2");
  }
  if (in.u16() != Descriptor::kHeaderBytes) return fail(2, "descriptor header size is not 48");
  d.gameFps.num = in.u32();
  d.gameFps.den = in.u32();
  d.framesPerVariant = in.u32();
  d.loopFrame = in.u32();
  const std::size_t streams = in.u8();
  const std::size_t variants = in.u8();
  in.u16();
  d.firstPts = static_cast<std::int64_t>(in.u64() & ((1ull << 33) - 1));
  d.ptsPerFrame = in.u32();
  d.descriptorSectors = in.u32();
  d.totalSectors = in.u32();
  const std::uint32_t storedCrc = in.u32();
  const std::size_t expect = serializedSize(streams, variants, d.framesPerVariant);
  if (body.size() < expect) {
    return fail(body.size(),
                "descriptor of " + std::to_string(body.size()) + " bytes; its counts need " + std::to_string(expect));
  }
  std::vector<std::uint8_t> copy(body.begin(), body.begin() + static_cast<std::ptrdiff_t>(expect));
  for (std::size_t i = 0; i < 4; ++i) copy[kCrcOffset + i] = 0;
  if (crc32(copy) != storedCrc) return fail(kCrcOffset, "descriptor CRC-32 mismatch (damaged descriptor)");
  for (std::size_t s = 0; s < streams; ++s) {
    StreamEntry e;
    e.id = in.u8();
    const std::uint8_t role = in.u8();
    if (role > 1) return fail(in.pos() - 1, "stream role " + std::to_string(role) + " (expected 0 or 1)");
    e.role = static_cast<StreamRole>(role);
    e.width = in.u16();
    e.height = in.u16();
    in.u16();
    d.streams.push_back(e);
  }
  for (std::size_t v = 0; v < variants; ++v) {
    Variant var;
    const auto name = in.take(24);
    std::size_t n = 0;
    while (n < 24 && name[n] != 0) ++n;
    var.name.assign(reinterpret_cast<const char*>(name.data()), n);
    var.firstFrame = in.u32();
    var.firstSector = in.u32();
    d.variants.push_back(std::move(var));
  }
  d.index.assign(streams, {});
  for (auto& table : d.index) {
    table.resize(d.totalFrames());
    for (IndexEntry& e : table) {
      e.sector = in.u32();
      e.offset = in.u16();
      const std::uint16_t flags = in.u16();
      if (e.offset >= kSectorBytes) return fail(in.pos() - 4, "index entry offset is not inside a 2048-byte pack");
      if (version == Descriptor::kVersion) {
        const unsigned type = flags & kTypeMask;
        if (type == 0 || (flags & ~(kTypeMask | kGopStartBit | kClosedGopBit)) != 0)
          return fail(in.pos() - 2, "index entry flags " + std::to_string(flags) + " (expected a type 1..3, bits 2-3)");
        e.type = static_cast<PictureType>(type);
        e.gopStart = (flags & kGopStartBit) != 0;
        e.closedGop = (flags & kClosedGopBit) != 0;
      }
      e.bytes = in.u32();
      e.crc = in.u32();
    }
  }
  if (std::string why = d.validate(); !why.empty()) return fail(0, why);
  r.descriptor = std::move(d);
  return r;
}

}  // namespace vbim::streams
