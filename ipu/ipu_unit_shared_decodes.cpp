#include "ipu/ipu_unit_shared_decodes.hpp"

#include <algorithm>
#include <cstring>
#include <utility>

#include "ipu/bit_reader.hpp"
#include "ipu/start_code.hpp"

namespace vbim::ipu {

bool startsWithSequenceHeader(std::span<const std::uint8_t> bytes) {
  const std::uint8_t* d = bytes.data();
  const std::size_t n = bytes.size();
  const std::size_t pos = findStartCode(d, n, 0);
  if (pos + 3 >= n || d[pos + 3] != kSequenceHeaderCode) return false;
  // As Decoder::decode reads it: from after the start code to the next one.
  const std::size_t payload = pos + 4;
  BitReader br(d + payload, d + findStartCode(d, n, payload));
  SequenceHeader seq;
  return parseSequenceHeader(br, seq);
}

bool SharedDecodes::same(const Entry& e, std::span<const std::uint8_t> bytes, CscThresholds th) {
  return e.result && e.th.th0 == th.th0 && e.th.th1 == th.th1 && e.bytes.size() == bytes.size() &&
         (bytes.empty() || std::memcmp(e.bytes.data(), bytes.data(), bytes.size()) == 0);
}

std::optional<SharedDecodes::Taken> SharedDecodes::take(int side, std::span<const std::uint8_t> bytes,
                                                        CscThresholds th) {
  Side& me = sides_.at(static_cast<std::size_t>(side));
  if (me.left || sides_.at(1 - static_cast<std::size_t>(side)).left) return std::nullopt;
  if (!me.diverged && me.cursor < end() && same(at(me.cursor), bytes, th)) {
    // Unless its decoder would have more than maxAhead pictures to read again (a stream with one
    // sequence header at its start): then it decodes from here on itself, and the log stays short.
    if (!me.stale || at(me.cursor).freshStart || me.cursor - me.replayFrom < maxAhead_) return takeAt(me, me.cursor);
  }
  // A fresh start may be one the other side decoded further on (this side dropped a picture, or
  // went its own way on damaged bytes): it picks up there.
  if (freshStart(me.pendingAfter, bytes)) {
    for (std::size_t i = std::max(me.cursor, base_); i < end(); ++i) {
      if (at(i).freshStart && same(at(i), bytes, th)) {
        ++counters_.rejoined;
        return takeAt(me, i);
      }
    }
  }
  if (me.cursor < end() && !me.diverged) {
    ++counters_.divergences;
    me.diverged = true;
  }
  return std::nullopt;
}

std::optional<SharedDecodes::Taken> SharedDecodes::takeAt(Side& me, std::size_t index) {
  Entry& e = at(index);
  // What its decoder must decode again before it decodes itself: from this entry if it is a fresh
  // start, else from the first entry it did not decode (its decoder's state is the one before it).
  if (e.freshStart) {
    me.replayFrom = index;
    me.replayFresh = true;
  } else if (!me.stale) {
    me.replayFrom = index;
    me.replayFresh = false;
  }
  me.stale = true;
  me.cursor = index + 1;
  me.diverged = false;
  me.pendingAfter = e.pendingAfter;
  me.previous.clear();  // its last picture is in the log now
  Taken taken = std::move(*e.result);
  e.result.reset();
  imageBytes_ -= taken.image ? taken.image->pixels.size() : 0;
  ++counters_.taken;
  // Kept state: a decoder far behind what its side took catches up while the other's is level, so
  // that neither a replay nor the log grows while one side takes everything.
  if (farBehind(me)) copyFromLevel(static_cast<int>(&me - sides_.data()));
  trim();
  return taken;
}

bool SharedDecodes::copyFromLevel(int side) {
  const auto s = static_cast<std::size_t>(side);
  Side& me = sides_.at(s);
  const Side& other = sides_.at(1 - s);
  const std::unique_ptr<Decoder>* mine = decoders_.at(s);
  const std::unique_ptr<Decoder>* theirs = decoders_.at(1 - s);
  if (!kept_ || !me.stale || me.diverged || other.stale || other.diverged || other.left || other.cursor != me.cursor ||
      mine == nullptr || theirs == nullptr || !*mine || !*theirs || (*theirs)->fieldPending()) {
    return false;
  }
  (*mine)->copyStateFrom(**theirs);
  me.stale = false;
  ++counters_.statesCopied;
  return true;
}

void SharedDecodes::prepare(int side, std::unique_ptr<Decoder>& decoder, const DecoderOptions& options,
                            std::span<const std::uint8_t> bytes) {
  const auto s = static_cast<std::size_t>(side);
  Side& me = sides_.at(s);
  if (!me.stale) {
    // About to change its decoder: a stale other side level with it takes its state first, if that
    // side's decoder is far behind (as in takeAt).
    const Side& other = sides_.at(1 - s);
    if (farBehind(other)) copyFromLevel(1 - side);
    return;
  }
  if (copyFromLevel(side)) {
    trim();
    return;
  }
  me.stale = false;
  const bool fresh = freshStart(me.pendingAfter, bytes);
  // A decoder with a field pending would take the next field picture as its second: a new one has none.
  if ((fresh || me.replayFresh) && decoder->fieldPending()) decoder = std::make_unique<Decoder>(options);
  if (!fresh) {
    for (std::size_t i = me.replayFrom; i < me.cursor; ++i) {
      decoder->decode(at(i).bytes);
      ++counters_.replayed;
    }
  }
  trim();
}

void SharedDecodes::publish(int side, std::span<const std::uint8_t> bytes, CscThresholds th, bool pendingBefore,
                            const Decoder& decoder, IdecDecode decode, std::shared_ptr<Rgba8Image> image) {
  const auto s = static_cast<std::size_t>(side);
  Side& me = sides_.at(s);
  Side& other = sides_.at(1 - s);
  ++counters_.decoded;
  me.pendingAfter = decoder.fieldPending();
  // No one would take it: kept in the log it would only hold its image (16 MiB of them at most)
  // for as long as the play lasts.
  if (me.left || gone(other)) return;
  // A side that went its own way, or fell behind, offers its decode again when it is a fresh start
  // for both sides (the other has read the whole log and waits for no second field): whatever either
  // side decoded before, the other's decode of these bytes would give this result (see the header),
  // so the other can take it as its next entry, and both are in step from here on. Without this a
  // side that is always first at a tick (the reference, in the scheduler's first lane) and once went
  // its own way would never pick up again: it looks for the other's decode before the other made it.
  // Only when the two are level: the log's last entry is the picture this side had before this one
  // (the other decoded it after this side did). A side behind the other picks up again in take().
  // The byte comparisons last, so a side in step compares nothing.
  const bool rejoin = (me.diverged || me.cursor != end()) && other.cursor == end() && !other.pendingAfter &&
                      end() > base_ && at(end() - 1).bytes == me.previous && freshStart(pendingBefore, bytes);
  if (rejoin) {
    ++counters_.offeredAgain;
    me.diverged = false;
    me.stale = false;
    me.cursor = end();
  }
  if (me.diverged || me.cursor != end()) {                       // not in step with the log's last entry
    if (!kept_) me.previous.assign(bytes.begin(), bytes.end());  // for the next publish's level test
    return;
  }
  me.previous.clear();
  const std::size_t bytesNeeded = image ? image->pixels.size() : 0;
  while (end() - other.cursor >= maxAhead_ || imageBytes_ + bytesNeeded > maxImageBytes_) {
    if (!other.diverged || other.cursor >= end()) {
      // The other side is in step but far behind: this side keeps its decodes, and is no longer
      // in step with the log (the other side offers its own once it reached the end).
      me.diverged = true;
      ++counters_.heldBack;
      if (!kept_) me.previous.assign(bytes.begin(), bytes.end());
      return;
    }
    // The other side went its own way: it gives up its oldest chance to pick up again.
    Entry& oldest = at(other.cursor);
    if (oldest.result) {
      imageBytes_ -= oldest.result->image ? oldest.result->image->pixels.size() : 0;
      oldest.result.reset();
    }
    ++other.cursor;
    trim();
  }
  Entry e;
  e.bytes.assign(bytes.begin(), bytes.end());
  e.th = th;
  e.freshStart = freshStart(pendingBefore, bytes);
  e.pendingAfter = me.pendingAfter;
  imageBytes_ += bytesNeeded;
  e.result = Taken{std::move(decode), std::move(image)};
  log_.push_back(std::move(e));
  me.cursor = end();
  trim();
}

void SharedDecodes::leave(int side, std::unique_ptr<Decoder>& decoder, const DecoderOptions& options) {
  Side& me = sides_.at(static_cast<std::size_t>(side));
  if (me.left) return;
  prepare(side, decoder, options, {});
  me.left = true;
  me.diverged = true;  // its decoder is no longer the log's: the other never takes its state
  trim();
}

// Drops the entries neither side can still take or decode again (a side that is gone needs none).
void SharedDecodes::trim() {
  std::size_t keep = end();
  for (const Side& s : sides_) {
    if (!gone(s)) keep = std::min(keep, s.stale ? s.replayFrom : s.cursor);
  }
  while (base_ < keep) {
    if (log_.front().result && log_.front().result->image) imageBytes_ -= log_.front().result->image->pixels.size();
    log_.pop_front();
    ++base_;
  }
}

}  // namespace vbim::ipu
