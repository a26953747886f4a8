#include "streams/demuxer.hpp"

#include "streams/crc32.hpp"
#include "streams/descriptor_packs.hpp"
#include "streams/format.hpp"

namespace vbim::streams {

namespace {
int slotOf(std::uint8_t id) {
  return id == kLightmapStream ? 0 : id == kSkyStream ? 1 : -1;
}
}  // namespace

Demuxer::Demuxer() : assemblers_{PictureAssembler(kLightmapStream), PictureAssembler(kSkyStream)} {}

std::size_t Demuxer::feed(std::span<const std::uint8_t> sector, std::uint32_t lsn) {
  const std::size_t errorsBefore = errors_.size();
  const std::size_t picturesBefore = pictures_.size();
  ++stats_.sectors;
  if (expectedLsn_ && *expectedLsn_ != lsn) {
    ++stats_.sectorGaps;
    dropInProgress(lsn, "sector numbers jump");
  }
  expectedLsn_ = lsn + 1;

  ParsedPack pack;
  if (auto err = parsePack(sector, lsn, pack)) {
    ++stats_.badSectors;
    errors_.push_back(std::move(*err));
    dropInProgress(lsn, "the pack holding part of it is malformed");
    return errors_.size() - errorsBefore;
  }
  if (pack.hasSystemHeader) ++stats_.systemHeaders;
  const std::uint64_t base = std::uint64_t{lsn} * kSectorBytes;
  for (const PesPacket& p : pack.packets) {
    const int slot = slotOf(p.streamId);
    if (slot >= 0) {
      if (!assemblers_[slot].append(p.payload, lsn, base + p.payloadOffset, p.pts, pictures_)) {
        ++stats_.droppedPictures;
        errors_.push_back(StreamError{ErrorKind::PictureDropped, base + p.offset, lsn,
                                      std::string("picture of stream ") + (slot == 0 ? "0xE0" : "0xE1") +
                                          " dropped: longer than the " + std::to_string(kMaxPictureBytes) +
                                          "-byte MPEG-2 VBV without a picture boundary"});
      }
    } else if (p.streamId == kPaddingStream) {
      stats_.paddingBytes += p.payload.size() + 6;
    } else if (p.streamId == kPrivateStream2 && parseDescriptorChunk(p.payload)) {
      onDescriptorChunk(p.payload, lsn, base + p.offset);
    } else {
      ++stats_.skippedPackets;
    }
  }
  pack_ = std::move(pack);
  identify(picturesBefore);
  return errors_.size() - errorsBefore;
}

void Demuxer::finish() {
  const std::size_t before = pictures_.size();
  for (auto& a : assemblers_) a.finish(pictures_);
  identify(before);
}

void Demuxer::seek() {
  for (auto& a : assemblers_) a.reset();
  expectedLsn_.reset();
}

void Demuxer::setDescriptor(Descriptor d) {
  descriptor_ = std::move(d);
  descriptorFailed_ = false;
  indexPositions();
}

void Demuxer::dropInProgress(std::uint32_t lsn, const char* why) {
  for (auto& a : assemblers_) {
    const std::uint8_t id = &a == &assemblers_[0] ? kLightmapStream : kSkyStream;
    if (a.reset()) {
      ++stats_.droppedPictures;
      errors_.push_back(StreamError{
          ErrorKind::PictureDropped, std::uint64_t{lsn} * kSectorBytes, lsn,
          std::string("picture of stream ") + (id == kLightmapStream ? "0xE0" : "0xE1") + " dropped: " + why});
    }
  }
}

void Demuxer::onDescriptorChunk(std::span<const std::uint8_t> payload, std::uint32_t lsn, std::uint64_t offset) {
  if (descriptor_ || descriptorFailed_) return;
  const DescriptorChunk c = *parseDescriptorChunk(payload);
  if (chunks_.empty()) chunks_.resize(c.count);
  if (c.count != chunks_.size()) {
    descriptorFailed_ = true;
    errors_.push_back(StreamError{ErrorKind::BadDescriptor, offset, lsn,
                                  "descriptor chunk says " + std::to_string(c.count) + " chunks, earlier ones said " +
                                      std::to_string(chunks_.size())});
    return;
  }
  chunks_[c.index].assign(c.data.begin(), c.data.end());
  for (const auto& chunk : chunks_)
    if (chunk.empty()) return;
  std::vector<std::uint8_t> body;
  for (const auto& chunk : chunks_) body.insert(body.end(), chunk.begin(), chunk.end());
  chunks_.clear();
  DescriptorParse r = parseDescriptor(body);
  if (!r.descriptor) {
    descriptorFailed_ = true;
    errors_.push_back(StreamError{ErrorKind::BadDescriptor, offset, lsn,
                                  r.error + " (descriptor byte " + std::to_string(r.errorOffset) + ")"});
    return;
  }
  descriptor_ = std::move(r.descriptor);
  indexPositions();
}

void Demuxer::indexPositions() {
  for (auto& m : positions_) m.clear();
  if (!descriptor_) return;
  for (std::size_t s = 0; s < descriptor_->streams.size(); ++s) {
    const int slot = slotOf(descriptor_->streams[s].id);
    if (slot < 0) continue;
    const auto& table = descriptor_->index[s];
    for (std::uint32_t f = 0; f < table.size(); ++f)
      positions_[slot][std::uint64_t{table[f].sector} * kSectorBytes + table[f].offset] = f;
  }
}

// Gives each new picture its global frame number by its position in the file (the index holds the
// sector and offset of every picture's first byte) and checks its size and CRC against the index.
void Demuxer::identify(std::size_t firstNew) {
  for (std::size_t i = firstNew; i < pictures_.size(); ++i) {
    Picture& p = pictures_[i];
    ++stats_.pictures;
    const int slot = slotOf(p.streamId);
    if (!descriptor_) continue;
    const int s = descriptor_->streamIndex(p.streamId);
    if (s < 0) continue;
    const auto it = positions_[slot].find(p.byteOffset);
    if (it == positions_[slot].end()) {
      p.damaged = true;
      ++stats_.damagedPictures;
      errors_.push_back(StreamError{
          ErrorKind::PictureMismatch, p.byteOffset, p.firstSector,
          std::string("picture of stream ") + (slot == 0 ? "0xE0" : "0xE1") + " starts where the index has none"});
      continue;
    }
    p.frame = it->second;
    const IndexEntry& e = descriptor_->index[static_cast<std::size_t>(s)][it->second];
    if (e.bytes != p.data.size() || e.crc != crc32(p.data)) {
      p.damaged = true;
      ++stats_.damagedPictures;
      errors_.push_back(StreamError{ErrorKind::PictureMismatch, p.byteOffset, p.firstSector,
                                    "frame " + std::to_string(it->second) + " of stream " +
                                        (slot == 0 ? "0xE0" : "0xE1") + ": " + std::to_string(p.data.size()) +
                                        " bytes, CRC " + std::to_string(crc32(p.data)) + "; the index says " +
                                        std::to_string(e.bytes) + " bytes, CRC " + std::to_string(e.crc)});
    }
  }
}

}  // namespace vbim::streams
