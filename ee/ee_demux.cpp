#include "ee/ee_demux.hpp"

#include <algorithm>
#include <limits>
#include <utility>

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
  for (int s = 0; s < 2; ++s) {
    if (active(s)) order_[static_cast<std::size_t>(s)] = DecodeOrder(stream.descriptor, streamIndex_[s]);
  }
}

// A key's run: the newest branch whose run the key is in (its lap, at or after its first key), or
// else the lap it is in. In an intra-only stream every key is its seq, so this is the timeline.
EeDemux::Run EeDemux::runOf(int s, std::int64_t key) const {
  const std::int64_t lapStart = timeline_.lapStart(key);
  for (auto it = branchRuns_.rbegin(); it != branchRuns_.rend(); ++it) {
    const std::int64_t from = it->first;
    const std::int64_t startKey = it->second[static_cast<std::size_t>(s)];
    if (key < startKey || key > timeline_.lapEnd(from)) continue;
    const std::int64_t showFrom = timeline_.frameInVariant(from);
    const int v = timeline_.variantOf(from);
    const std::int64_t base = from - showFrom;
    return Run{v, base, startKey - base, showFrom, startKey};
  }
  const std::int64_t startFrame = timeline_.frameInVariant(lapStart);
  return Run{timeline_.variantOf(key), lapStart - startFrame, startFrame, startFrame, lapStart};
}

EeDemux::Want EeDemux::want(int s, std::int64_t key) const {
  const Run r = runOf(s, key);
  const DecodeOrder& o = order(s);
  const std::int64_t f = o.frameAtRank(r.variant, key - r.base, r.start);
  Want w;
  w.seq = r.base + f;
  w.frame = r.variant * timeline_.framesPerVariant() + f;
  w.shown = f >= r.showFrom;
  w.skip = !w.shown && o.type(w.frame) == streams::PictureType::B;
  return w;
}

std::int64_t EeDemux::wanted(int s, std::int64_t key) const {
  while (want(s, key).skip) ++key;
  return key;
}

std::optional<std::int64_t> EeDemux::keyOfFrame(int s, std::int64_t key, std::int64_t g) const {
  const Run r = runOf(s, key);
  const std::int64_t frames = timeline_.framesPerVariant();
  if (g / frames != r.variant) return std::nullopt;
  const std::int64_t f = g % frames;
  if (f < r.start || r.base + f > timeline_.lapEnd(key)) return std::nullopt;
  return r.base + order(s).rank(r.variant, f, r.start);
}

bool EeDemux::followsInFile(int s, std::int64_t key) const {
  if (key == 0) return timeline_.variantOf(0) == 0;
  if (key != runOf(s, key).startKey) return true;
  return order(s).nextInFile(want(s, key - 1).frame) == want(s, key).frame;
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

// The new variant shows seq `from` on; each stream's run starts at the GOP-opening I picture at or
// before that frame (the frame itself in an intra-only stream), so its first key may be before `from`.
void EeDemux::branch(std::int64_t from) {
  ++generation_;
  branchRuns_.erase(branchRuns_.lower_bound(from), branchRuns_.end());
  // A run whose lap ended before every stream's next key is never asked about again (runOf skips a
  // key past its lap): drop it, so a long run with many branches keeps this map short.
  std::int64_t oldest = std::numeric_limits<std::int64_t>::max();
  for (int s = 0; s < 2; ++s) {
    if (active(s)) oldest = std::min(oldest, next_[s]);
  }
  while (!branchRuns_.empty() && timeline_.lapEnd(branchRuns_.begin()->first) + 1 < oldest) {
    branchRuns_.erase(branchRuns_.begin());
  }
  const std::int64_t f = timeline_.frameInVariant(from);
  const int v = timeline_.variantOf(from);
  std::array<std::int64_t, 2> startKeys{from, from};
  for (int s = 0; s < 2; ++s) {
    if (active(s)) startKeys[static_cast<std::size_t>(s)] = from - f + order(s).resumeFrame(v, f);
  }
  branchRuns_[from] = startKeys;
  for (int s = 0; s < 2; ++s) {
    if (!active(s)) continue;
    const std::int64_t k0 = startKeys[static_cast<std::size_t>(s)];
    lastBranchKey_[static_cast<std::size_t>(s)] = k0;
    buffers_[static_cast<std::size_t>(s)]->dropFrom(k0);
    if (next_[s] >= k0) {
      next_[s] = k0;
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
    const Want w = want(s, k);
    const bool waitingHere = positioned_[s] || followsInFile(s, k);
    if (waitingHere && pos_ >= variantEndSector(s, static_cast<int>(w.frame / timeline_.framesPerVariant())) &&
        indexSector(s, w.frame) < pos_) {
      const std::int64_t end = timeline_.lapEnd(k);
      c_.framesLost += end + 1 - k;
      next_[s] = end + 1;
      positioned_[s] = false;
      lost_[static_cast<std::size_t>(s)] = true;
    }
  }
  bool allJump = true;
  std::int64_t target = std::numeric_limits<std::int64_t>::max();
  for (int s = 0; s < 2; ++s) {
    if (!active(s)) continue;
    if (positioned_[s] || followsInFile(s, next_[s])) allJump = false;
    target = std::min(target, indexSector(s, want(s, next_[s]).frame));
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
  Want w = want(s, k);
  if (f != w.frame) {
    // The wanted picture never came (damage) but a later one of the same run did: skip to it.
    const std::optional<std::int64_t> at = keyOfFrame(s, k, f);
    if (!at || *at <= k || *at > timeline_.lapEnd(k) || want(s, *at).frame != f || want(s, *at).skip) {
      ++c_.picturesIgnored;
      co_return;
    }
    c_.framesLost += *at - k;
    lost_[static_cast<std::size_t>(s)] = true;
    k = *at;
    w = want(s, k);
  }
  next_[s] = wanted(s, k + 1);
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
    const std::int64_t ours = out.front().key;
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
  const std::int64_t branchKey = lastBranchKey_[static_cast<std::size_t>(s)];
  if (gen != generation_ && k >= branchKey) co_return;  // a branch dropped this frame meanwhile
  const Tick t0 = s_.now();
  const std::int64_t qwords = (static_cast<std::int64_t>(pic.data.size()) + 15) / 16;
  co_await s_.delay(fromEeCycles(qwords * p_.copy_cycles_per_qword));
  c_.busy += s_.now() - t0;
  if (tracer_ != nullptr) tracer_->span(track_, t0, s_.now(), "copy");
  if (gen != generation_ && k >= lastBranchKey_[static_cast<std::size_t>(s)]) co_return;
  if (pic.damaged) ++c_.picturesDamaged;
  ++c_.picturesLoaded;
  if (!w.shown) ++c_.picturesForReference;
  const streams::PictureType type = order(s).type(f);
  out.push(CompressedPicture{w.seq, f, pic.damaged, std::move(pic.data), k, w.shown, type,
                             std::exchange(lost_[static_cast<std::size_t>(s)], false)});
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
