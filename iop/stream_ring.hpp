// The IOP stream ring with the semantics of the sceCdSt* API as the rebuilt cdvdstm driver shows
// them (SDK-ST; docs/hardware.md#stream-ring). Our own code, not a translation; the behaviour it reproduces:
// - init: bufmax sectors in bankmax banks of floor(bufmax / bankmax) sectors.
// - the producer reads one whole bank per drive command and advances by a bank. When the next
//   bank is full or is the reader's, the just-read bank is held back (not yet visible), the drive
//   idles and the producer re-polls every 8 ms. So at most bankmax - 1 banks are visible.
// - read(n) copies bank-bounded chunks to EE memory over SIF0; on underrun it returns the partial
//   count (possibly 0). The result packs the count in bits 0-15 and an error in bits 16-31.
// - a read error (0x30) or an abort (0x01, also a timed-out read) starts the run-up retries: the
//   bank is re-read from 32, then 16, then 0 sectors before the target (another error restarts
//   the run-up); other errors retry once at the target. The error reaches the reader.
// - reads time out after 5 s (15 s for the first read after start, an error or during retries):
//   the driver breaks the command, which is an abort.
// - a failed sceCdRE (drive busy with another client) is retried after 200 ms.
// - stat in bank granularity; seek (immediate: waits for the drive) and seekDeferred (marks the
//   stream "repositioning": other calls return 0 until the producer restarts); pause/resume; stop.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "iop/cd_errors.hpp"
#include "iop/drive.hpp"
#include "iop/params.hpp"
#include "iop/sif.hpp"
#include "runtime/event.hpp"
#include "runtime/scheduler.hpp"
#include "runtime/trace.hpp"

namespace vbim::iop {

// Splits a sceCdStRead result word.
inline std::uint32_t stCount(std::uint32_t result) {
  return result & 0xFFFF;
}
inline std::uint32_t stError(std::uint32_t result) {
  return result >> 16;
}

struct RingStats {
  std::int64_t bankReads = 0;      // drive commands issued for banks (including retries)
  std::int64_t banksFilled = 0;    // banks made visible to the reader
  std::int64_t fullPolls = 0;      // "read Full" re-polls (drive idle)
  std::int64_t issueFailures = 0;  // sceCdRE refused (drive busy)
  std::int64_t timeouts = 0;
  std::int64_t errors = 0;     // drive errors seen by the producer
  std::int64_t underruns = 0;  // reads that returned fewer sectors than asked (startupPolls included)
  // Of those, the reads made after sceCdStStart and before its first bank was visible: the EE
  // polling while the drive spins up and seeks, not a stream running dry during playback.
  std::int64_t startupPolls = 0;
  // And those made after a sceCdStSeek (the player's loop wrap or branch) before a bank from the new
  // position was visible: the ring refilling as it must, not the drive falling behind.
  std::int64_t seekPolls = 0;
  // The rest: the ring ran dry while streaming on from where it was.
  std::int64_t playbackUnderruns() const { return underruns - startupPolls - seekPolls; }
  Tick firstUnderrunAt = -1;
};

class StreamRing {
 public:
  StreamRing(Scheduler& s, Drive& drive, SifChannel& sif, const RingParams& p, Tracer* tracer = nullptr);
  StreamRing(const StreamRing&) = delete;
  StreamRing& operator=(const StreamRing&) = delete;

  // sceCdStInit. False when the sizes make no bank (bufmax < bankmax) or the stream is running.
  bool init(std::int64_t bufmax, std::int64_t bankmax);
  // sceCdStStart: waits for the drive (sceCdSync), clears the banks, starts the producer at lbn.
  Task<bool> start(std::int64_t lbn);
  // sceCdStRead, STMNBLK: up to n sectors into dest (n x 2048 bytes); count | error << 16.
  Task<std::uint32_t> read(std::uint32_t n, std::span<std::uint8_t> dest);
  // sceCdStRead, STMBLK: re-reads until n sectors arrived or an error came with no progress.
  // Returns the count; the last error code goes to `error`.
  Task<std::uint32_t> readBlocking(std::uint32_t n, std::span<std::uint8_t> dest, std::uint32_t& error);
  // sceCdStStat: sectors readable now, in whole banks.
  std::uint32_t stat() const;
  // sceCdStSeek: waits for the drive, clears, restarts at lbn.
  Task<bool> seek(std::int64_t lbn);
  // sceCdStSeekF: deferred; the producer restarts at lbn when its current read ends.
  bool seekDeferred(std::int64_t lbn);
  // sceCdStPause / sceCdStResume / sceCdStStop.
  Task<bool> pause();
  bool resume();
  Task<bool> stop();

  std::int64_t bankSectors() const { return bankSectors_; }
  std::int64_t bankmax() const { return bankmax_; }
  std::int64_t visibleBanks() const;
  bool repositioning() const { return stmstart_ == 2; }
  const RingStats& stats() const { return stats_; }
  // Every bank read issued: (time, LSN). Retries show their run-up LSNs.
  const std::vector<std::pair<Tick, std::int64_t>>& readLog() const { return readLog_; }
  Process& producer() { return *proc_; }

 private:
  enum class Wait { None, Drive, Alarm };

  Task<void> produce();
  void callback(std::uint32_t err);
  bool issueRead(std::int64_t lba, Tick timeout);
  void armAlarm(Tick delay);
  void clearBanks();
  std::int64_t next(std::int64_t bank) const { return bank + 1 >= bankmax_ ? 0 : bank + 1; }
  void publish();

  Scheduler& s_;
  Drive& drive_;
  SifChannel& sif_;
  RingParams p_;
  Tracer* tracer_;
  Tracer::TrackId track_ = 0;
  Tracer::CounterId banksCounter_ = 0;
  Process* proc_ = nullptr;
  Event kick_;     // wakes the producer: drive completion, alarm, timeout
  Event changed_;  // wakes blocking readers: a bank became visible, or the stream changed state

  std::int64_t bankmax_ = 0;
  std::int64_t bankSectors_ = 0;
  std::vector<std::uint8_t> buffer_;
  std::vector<bool> used_;
  std::int64_t gp_ = 0;    // bank the producer fills
  std::int64_t cur_ = 0;   // bank the reader reads
  std::int64_t offs_ = 0;  // sectors already read from cur_
  std::int64_t lsn_ = 0;   // next bank's LSN
  std::int64_t tgt_ = 0;   // LSN of the bank being read (retry target)
  int stmstart_ = 0;       // 0 streaming, 1 just started, 2 repositioning (seekDeferred)
  std::int64_t retrycnt_ = 0;
  std::uint32_t retryerr_ = 0;
  bool bankSinceStart_ = false;  // a bank became visible since sceCdStStart (startupPolls)
  bool bankSinceSeek_ = true;    // a bank became visible since sceCdStSeek (seekPolls)
  bool owner_ = false;           // the stream owns the drive (sceCdSC(2)); false before start, when paused/stopped

  Wait wait_ = Wait::None;
  std::shared_ptr<DriveCommand> cmd_;
  Tick timeoutAt_ = 0;
  Tick alarmAt_ = 0;

  RingStats stats_;
  std::vector<std::pair<Tick, std::int64_t>> readLog_;
};

}  // namespace vbim::iop
