// Two IPUs that decode the same pictures share each decode (issue #31): a run and its fault-free
// reference (player/player.hpp) are given the same picture bytes in the same order as long as the
// run has only been delayed (a stall or a retried read changes when a picture arrives, not its
// bytes). Whichever IPU reaches a picture first decodes it and leaves the result here (report,
// macroblock trace, headers, the RGB32 image); the other takes it instead of decoding the same
// bytes again, and both pipelines then hold the same image (the presenters' source comparison
// becomes a pointer test). Each IPU still plans its own timing from the trace: only the host work
// of the decode is shared.
//
// Exactness: a decode's result is a function of its bytes and the decoder's state before it. A
// side takes an entry only when its decoder's state, had it decoded everything itself, equals the
// state the entry was decoded from:
//   - in step: it took or decoded exactly the inputs the log holds before the entry, or
//   - a fresh start: the bytes begin with a sequence header that parses and no field picture waits
//     for its second field, on both sides. On the IDEC path every decode starts from a mid-grey
//     store (DecoderOptions::freshStorePerDecode), the header replaces every sequence parameter and
//     a picture header every picture parameter, so nothing before such bytes reaches their result
//     or any later one (a run that dropped a picture picks up again at its next one).
// A side that took decodes has a stale decoder. Before it decodes again itself it is brought up to
// date: nothing to do when its next bytes are a fresh start, otherwise the entries it took since
// its last fresh start are decoded again (without the RGB32 output); a side that would have more
// than maxAhead entries to decode again (a stream with one sequence header at its start) decodes
// itself from there on, so neither the log nor a replay grows with the run.
//
// The BDEC flow (P and B pictures; DecoderState::Kept, one log per stream) keeps its frames from
// picture to picture, so nothing is a fresh start there: a side is in step or not, and one that went
// its own way (damaged bytes, or held back) stays its own, and what the other decodes from then on
// is not logged. A stale side is brought up to date by taking the other
// side's decoder state (Decoder::copyStateFrom: its frame stores) when that side's decoder is at the
// same entry and not stale, else by decoding again the entries since its decoder's own last one. So
// that this stays short while one side takes everything, a side whose decoder is maxAhead/2 entries
// stale takes the other's state whenever the two are level.
//
// Memory: the log holds the entries between the two sides: at most `maxAhead` of them, and images
// of at most `maxImageBytes` not yet taken; past that, the side ahead keeps its decodes to itself
// (and the other, once it caught up, offers its own), or one that went its own way (damaged bytes)
// gives up its oldest chances to pick up again.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "ipu/csc.hpp"
#include "ipu/decode_report.hpp"
#include "ipu/headers.hpp"
#include "ipu/picture_decoder.hpp"
#include "ipu/slice_decoder.hpp"
#include "runtime/image.hpp"

namespace vbim::ipu {

// What an IDEC command, or a picture of the BDEC flow, takes from the decode of its picture
// (ipu/ipu_unit.cpp).
struct IdecDecode {
  PictureReport report;
  std::vector<MacroblockBits> trace;
  SequenceHeader sequence;
  PictureHeader picture;
  int mbWidth = 0;  // the frame store's size in macroblocks
  int mbHeight = 0;
  int width = 0;  // display size
  int height = 0;
  // BDEC flow: a frame became due for display (the image); mbWidth/mbHeight and width/height are
  // then that frame's.
  bool shown = true;
};

// Whether a decoder's state carries from picture to picture (the BDEC flow's reference frames) or
// every picture starts afresh (IDEC: a mid-grey store, DecoderOptions::freshStorePerDecode).
enum class DecoderState { FreshPerPicture, Kept };

// The bytes' first start code is a sequence header that parses: the decoder takes every sequence
// parameter from them.
bool startsWithSequenceHeader(std::span<const std::uint8_t> bytes);

class SharedDecodes {
 public:
  // 64 decodes are 32 s of a 1 frame/s stream with a sky; 16 MiB are 64 pictures of 256x256 or
  // 12 of 512x512 with their skies (the bench fault play's run is at most 14 decodes behind, after
  // its 6 s stall).
  static constexpr std::size_t kDefaultMaxAhead = 64;
  static constexpr std::size_t kDefaultMaxImageBytes = std::size_t{16} << 20;

  struct Counters {
    std::int64_t decoded = 0;       // decodes made by a side itself
    std::int64_t taken = 0;         // decodes a side took from the other
    std::int64_t replayed = 0;      // entries decoded again to bring a stale decoder up to date
    std::int64_t divergences = 0;   // a side's bytes were not the ones the other side decoded next
    std::int64_t rejoined = 0;      // taken at a fresh start after a divergence or a skipped picture
    std::int64_t heldBack = 0;      // decodes not offered: the other side was maxAhead behind
    std::int64_t offeredAgain = 0;  // fresh starts offered by a side that was out of step (publish)
    std::int64_t statesCopied = 0;  // DecoderState::Kept: a stale decoder given the other side's state
  };
  // A decode taken from the other side: the image is the other side's and is never written again.
  struct Taken {
    IdecDecode decode;
    std::shared_ptr<Rgba8Image> image;
  };

  explicit SharedDecodes(std::size_t maxAhead = kDefaultMaxAhead, std::size_t maxImageBytes = kDefaultMaxImageBytes,
                         DecoderState state = DecoderState::FreshPerPicture)
      : maxAhead_(maxAhead), maxImageBytes_(maxImageBytes), kept_(state == DecoderState::Kept) {}
  SharedDecodes(const SharedDecodes&) = delete;
  SharedDecodes& operator=(const SharedDecodes&) = delete;

  // DecoderState::Kept: side `side`'s decoder (the IPU's stream holds it; it must outlive this), so
  // that the other side can take its state. Without both, a stale side always decodes again.
  void attach(int side, const std::unique_ptr<Decoder>* decoder) {
    decoders_.at(static_cast<std::size_t>(side)) = decoder;
  }
  // `side` stops sharing: from now on it neither takes nor offers a decode, and the other side offers
  // none. Its decoder is brought up to date first: it may be changed outside the log next (the end
  // of a BDEC stream, Decoder::flushDisplay) or be needed whole (a command log reads it).
  void leave(int side, std::unique_ptr<Decoder>& decoder, const DecoderOptions& options);

  // Side `side` (0 or 1) is about to decode `bytes` with thresholds `th`: the other side's decode of
  // them when it may take it (see above), else nothing (then: prepare, decode, publish).
  std::optional<Taken> take(int side, std::span<const std::uint8_t> bytes, CscThresholds th);
  // Before `side` decodes `bytes` itself: brings its decoder up to date if it took decodes (it may
  // be replaced by a new one made with `options`).
  void prepare(int side, std::unique_ptr<Decoder>& decoder, const DecoderOptions& options,
               std::span<const std::uint8_t> bytes);
  // After `side` decoded `bytes` itself (`pendingBefore`: a field was pending before): offers the
  // result and `image` (which no one may write again) to the other side.
  void publish(int side, std::span<const std::uint8_t> bytes, CscThresholds th, bool pendingBefore,
               const Decoder& decoder, IdecDecode decode, std::shared_ptr<Rgba8Image> image);

  const Counters& counters() const { return counters_; }
  std::size_t held() const { return log_.size(); }  // entries kept (tests)
  std::size_t heldImageBytes() const { return imageBytes_; }

 private:
  struct Entry {
    std::vector<std::uint8_t> bytes;
    CscThresholds th;
    bool freshStart = false;      // startsWithSequenceHeader and no field pending before
    bool pendingAfter = false;    // a field pending after the decode
    std::optional<Taken> result;  // until taken; later only the bytes are kept (for replays)
  };
  struct Side {
    std::size_t cursor = 0;              // log index of the entry after the last one decoded or taken in step
    bool diverged = false;               // its state is not the one after entry cursor - 1
    bool pendingAfter = false;           // after its last decode (taken or made), a field was pending
    bool stale = false;                  // took decodes its decoder did not make
    std::size_t replayFrom = 0;          // with stale: the first entry its decoder must decode again
    bool replayFresh = false;            // that entry is a fresh start
    std::vector<std::uint8_t> previous;  // its last picture's bytes if decoded out of step (publish)
    bool left = false;                   // shares nothing any more (leave)
  };
  static bool same(const Entry& e, std::span<const std::uint8_t> bytes, CscThresholds th);
  Entry& at(std::size_t index) { return log_[index - base_]; }
  std::size_t end() const { return base_ + log_.size(); }
  std::optional<Taken> takeAt(Side& me, std::size_t index);
  // `bytes` start afresh for a decoder with (pendingField) or without a field pending: its state
  // before does not matter. Never with DecoderState::Kept (the reference frames carry over).
  bool freshStart(bool pendingField, std::span<const std::uint8_t> bytes) const {
    return !kept_ && !pendingField && startsWithSequenceHeader(bytes);
  }
  // Whether `s` can never take an entry again: it left, or (DecoderState::Kept, where nothing is a
  // fresh start) it went its own way and its decoder has read again what it took.
  bool gone(const Side& s) const { return s.left || (kept_ && s.diverged && !s.stale); }
  // DecoderState::Kept: `s`'s decoder is stale by half the log's limit or more (takes the other
  // side's state whenever the two are level, so that its replay stays short).
  bool farBehind(const Side& s) const { return kept_ && s.stale && s.cursor - s.replayFrom >= maxAhead_ / 2; }
  // DecoderState::Kept: `side`'s stale decoder takes the other side's state if the two are level
  // (the other's decoder, not stale, has read the same entries); whether it did.
  bool copyFromLevel(int side);
  void trim();

  std::size_t maxAhead_;
  std::size_t maxImageBytes_;
  std::size_t imageBytes_ = 0;  // of the entries not yet taken
  std::deque<Entry> log_;
  std::size_t base_ = 0;  // log index of log_.front()
  std::array<Side, 2> sides_{};
  bool kept_ = false;
  std::array<const std::unique_ptr<Decoder>*, 2> decoders_{};
  Counters counters_;
};

}  // namespace vbim::ipu
