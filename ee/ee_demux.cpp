#include "ee/ee_demux.hpp"

#include <algorithm>
#include <limits>

#include "runtime/clock.hpp"

namespace vbim::ee {

EeDemux::EeDemux(Scheduler& s, iop::StreamRing& ring, const ProbedStream& stream, Timeline& timeline, const EeParams& p,
                 std::array<CompressedBuffer*, 2> buffers, Event& work, Tracer* tracer)
    : s_(s),
      ring_(ring),
      stream_(stream),
      timeline_(timeline),
      p_(p),
      buffers_(buffers),
      streamIndex_{stream.lightmapIndex, stream.skyIndex},
      tracer_(tracer != nullptr && tracer->enabled() ? tracer : nullptr),
      work_(work),
      buf_(static_cast<std::size_t>(p.read_sectors) * iop::kSectorBytes) {
  if (tracer_ != nullptr) track_ = tracer_->track("ee.demux");
  demux_.setDescriptor(stream.descriptor);
}

std::int64_t EeDemux::indexSector(int s, std::int64_t globalFrame) const {
  return stream_.descriptor.index[static_cast<std::size_t>(streamIndex_[s])][static_cast<std::size_t>(globalFrame)]
      .sector;
}

// Stream s's last picture of a variant ends where its next picture starts: the stream's first picture
// of the next variant. That is per stream, not the variant's first sector: the muxer lets a small sky
// stream run ahead, so the next variant's sky pictures can start long before this variant's last
// lightmap picture (docs/stream-format.md "Variants").
std::int64_t EeDemux::variantEndSector(int s, int variant) const {
  const auto& d = stream_.descriptor;
  if (static_cast<std::size_t>(variant) + 1 < d.variants.size()) {
    return indexSector(s, d.variants[static_cast<std::size_t>(variant) + 1].firstFrame) + 1;
  }
  return d.totalSectors;
}

void EeDemux::branch(std::int64_t from) {
  ++generation_;
  lastBranchFrom_ = from;
  for (int s = 0; s < 2; ++s) {
    if (!active(s)) continue;
    buffers_[static_cast<std::size_t>(s)]->dropFrom(from);
    if (next_[s] >= from) {
      next_[s] = from;
      positioned_[s] = false;
    }
  }
  checkReposition();
  work_.notify();
}

void EeDemux::checkReposition() {
  if (seekTo_ >= 0) return;
  // A stream still waiting for frames that follow in the file after the read position passed the
  // end of their variant lost them to damage: skip to its lap end (the loop wrap).
  for (int s = 0; s < 2; ++s) {
    if (!active(s)) continue;
    const std::int64_t k = next_[s];
    const bool waitingHere = positioned_[s] || timeline_.followsInFile(k);
    if (waitingHere && pos_ >= variantEndSector(s, timeline_.variantOf(k)) &&
        indexSector(s, timeline_.globalFrame(k)) < pos_) {
      const std::int64_t end = timeline_.lapEnd(k);
      c_.framesLost += end + 1 - k;
      next_[s] = end + 1;
      positioned_[s] = false;
    }
  }
  bool allJump = true;
  std::int64_t target = std::numeric_limits<std::int64_t>::max();
  for (int s = 0; s < 2; ++s) {
    if (!active(s)) continue;
    if (positioned_[s] || timeline_.followsInFile(next_[s])) allJump = false;
    target = std::min(target, indexSector(s, timeline_.globalFrame(next_[s])));
  }
  if (!allJump) return;
  seekTo_ = target;
  for (int s = 0; s < 2; ++s) positioned_[s] = active(s);
  if (next_[kLightmap] >= timeline_.framesPerVariant() &&
      timeline_.frameInVariant(next_[kLightmap]) == timeline_.frameInVariant(timeline_.framesPerVariant())) {
    ++c_.loopSeeks;
  }
}

Task<void> EeDemux::route(streams::Picture& pic) {
  const int s = pic.streamId == 0xE0 ? kLightmap : pic.streamId == 0xE1 ? kSky : -1;
  if (s < 0 || !active(s)) co_return;
  if (!pic.frame) {
    ++c_.picturesUnidentified;
    co_return;
  }
  const std::int64_t f = *pic.frame;
  std::int64_t k = next_[s];
  const std::int64_t want = timeline_.globalFrame(k);
  if (f != want) {
    // The wanted picture never came (damage) but a later one of the same lap did: skip to it.
    const std::int64_t ahead = f - want;
    if (ahead <= 0 || k + ahead > timeline_.lapEnd(k) || timeline_.globalFrame(k + ahead) != f) {
      ++c_.picturesIgnored;
      co_return;
    }
    c_.framesLost += ahead;
    k += ahead;
  }
  next_[s] = k + 1;
  positioned_[s] = false;
  // Copy into the compressed frame buffer (waiting for room: back-pressure from the IPU).
  const std::uint64_t gen = generation_;
  CompressedBuffer& out = *buffers_[static_cast<std::size_t>(s)];
  // Wait for room, unless the other stream is starved at or before this seq: the muxer lets one stream
  // run ahead of the other in the file, and the IPU feeder needs the other's picture first, so waiting
  // would deadlock. The buffer then holds more than its depth for a while (counted).
  for (;;) {
    if (!out.full()) break;
    // The feeder decodes in seq order, lightmap first at equal seqs: it can take our oldest picture only
    // after the other stream's picture at its next wanted seq, if that one comes first.
    const int o = 1 - s;
    const std::int64_t ours = out.front().seq;
    const std::int64_t theirs = next_[static_cast<std::size_t>(o)];
    const bool otherStarved = active(o) && buffers_[static_cast<std::size_t>(o)]->empty() &&
                              (theirs < ours || (theirs == ours && o == kLightmap));
    if (otherStarved) {
      // Stored beyond the depth, within the stream's share of EE RAM; past it the picture is
      // dropped (its frame lost, as with damage) so memory stays bounded however the file is muxed.
      if (out.bytes() + pic.data.size() > static_cast<std::size_t>(p_.compressed_budget_kib) * 1024) {
        ++c_.overBudget;
        ++c_.framesLost;
        co_return;
      }
      ++c_.overDepth;
      break;
    }
    co_await out.room().wait();
  }
  if (gen != generation_ && k >= lastBranchFrom_) co_return;  // a branch dropped this frame meanwhile
  const Tick t0 = s_.now();
  const std::int64_t qwords = (static_cast<std::int64_t>(pic.data.size()) + 15) / 16;
  co_await s_.delay(fromEeCycles(qwords * p_.copy_cycles_per_qword));
  c_.busy += s_.now() - t0;
  if (tracer_ != nullptr) tracer_->span(track_, t0, s_.now(), "copy");
  if (gen != generation_ && k >= lastBranchFrom_) co_return;
  if (pic.damaged) ++c_.picturesDamaged;
  ++c_.picturesLoaded;
  out.push(CompressedPicture{k, f, pic.damaged, std::move(pic.data)});
  work_.notify();
}

Task<void> EeDemux::run() {
  const std::int64_t total = stream_.descriptor.totalSectors;
  co_await ring_.start(stream_.file.lba);
  pos_ = 0;
  std::vector<streams::Picture> done;
  for (;;) {
    if (seekTo_ >= 0) {
      const std::int64_t to = seekTo_;
      co_await ring_.seek(stream_.file.lba + to);
      if (seekTo_ != to) continue;  // repositioned again meanwhile (a branch)
      seekTo_ = -1;
      demux_.seek();
      pos_ = to;
      ++c_.seeks;
      continue;
    }
    const std::uint32_t r = co_await ring_.read(static_cast<std::uint32_t>(p_.read_sectors), buf_);
    ++c_.reads;
    const std::uint32_t got = iop::stCount(r);
    const std::uint32_t err = iop::stError(r);
    if (err != 0 && err != iop::kCdErStreamIdle) ++c_.readErrors;
    if (got == 0) {
      ++c_.emptyReads;
      co_await s_.delay(fromUs(p_.poll_us));
      continue;
    }
    for (std::uint32_t i = 0; i < got && seekTo_ < 0; ++i) {
      if (pos_ >= total) {  // read-ahead past the end of the file: not stream data
        ++pos_;
        checkReposition();
        continue;
      }
      const Tick t0 = s_.now();
      co_await s_.delay(
          fromEeCycles(p_.cycles_per_pack + p_.cycles_per_byte * static_cast<std::int64_t>(iop::kSectorBytes)));
      c_.busy += s_.now() - t0;
      if (tracer_ != nullptr) tracer_->span(track_, t0, s_.now(), "demux");
      if (seekTo_ >= 0) break;  // a branch during the parse: this sector is from before the seek
      const std::span<const std::uint8_t> sector(buf_.data() + static_cast<std::size_t>(i) * iop::kSectorBytes,
                                                 iop::kSectorBytes);
      c_.streamErrors += static_cast<std::int64_t>(demux_.feed(sector, static_cast<std::uint32_t>(pos_)));
      ++pos_;
      ++c_.sectors;
      c_.bytes += static_cast<std::int64_t>(iop::kSectorBytes);
      if (pos_ == total) demux_.finish();
      done.clear();
      done.swap(demux_.pictures());
      for (streams::Picture& pic : done) co_await route(pic);
      checkReposition();
      work_.notify();
    }
  }
}

}  // namespace vbim::ee
