#include "iop/stream_ring.hpp"

#include <algorithm>
#include <cstring>

namespace vbim::iop {

StreamRing::StreamRing(Scheduler& s, Drive& drive, SifChannel& sif, const RingParams& p, Tracer* tracer)
    : s_(s), drive_(drive), sif_(sif), p_(p), tracer_(tracer), kick_(s), changed_(s) {
  if (tracer_ != nullptr) {
    track_ = tracer_->track("ring");
    banksCounter_ = tracer_->counter("ring.banks_full");
  }
  if (!init(p_.bufmax_sectors, p_.bankmax)) {
    throw ConfigError("ring.bufmax_sectors (" + std::to_string(p_.bufmax_sectors) + ") and ring.bankmax (" +
                      std::to_string(p_.bankmax) + ") make no bank: bufmax must be at least bankmax >= 1");
  }
  proc_ = &s_.spawn("ring.producer", produce());
}

bool StreamRing::init(std::int64_t bufmax, std::int64_t bankmax) {
  if (bankmax < 1 || bufmax < bankmax || wait_ != Wait::None || owner_) return false;
  bankmax_ = bankmax;
  bankSectors_ = bufmax / bankmax;
  buffer_.assign(static_cast<std::size_t>(bankSectors_ * bankmax_) * kSectorBytes, 0);
  used_.assign(static_cast<std::size_t>(bankmax_), false);
  gp_ = cur_ = offs_ = 0;
  return true;
}

void StreamRing::clearBanks() {
  std::fill(used_.begin(), used_.end(), false);
  publish();
}

std::int64_t StreamRing::visibleBanks() const {
  std::int64_t n = 0;
  for (bool u : used_) n += u ? 1 : 0;
  return n;
}

void StreamRing::publish() {
  if (tracer_ != nullptr) tracer_->value(banksCounter_, s_.now(), visibleBanks());
  changed_.notify();
}

void StreamRing::armAlarm(Tick delay) {
  wait_ = Wait::Alarm;
  alarmAt_ = s_.now() + delay;
  kick_.notifyAt(alarmAt_);
}

bool StreamRing::issueRead(std::int64_t lba, Tick timeout) {
  auto c = std::make_shared<DriveCommand>();
  c->lsn = lba;
  c->sectors = bankSectors_;
  c->dest = buffer_.data() + static_cast<std::size_t>(gp_ * bankSectors_) * kSectorBytes;
  c->notify = &kick_;
  if (!drive_.tryIssue(c)) {
    ++stats_.issueFailures;
    if (tracer_ != nullptr) tracer_->instant(track_, s_.now(), "drive busy");
    return false;
  }
  ++stats_.bankReads;
  readLog_.emplace_back(s_.now(), lba);
  cmd_ = std::move(c);
  wait_ = Wait::Drive;
  timeoutAt_ = s_.now() + timeout;
  kick_.notifyAt(timeoutAt_);
  return true;
}

// The producer: one cooperating thread that runs the driver's completion callback whenever its
// drive command ends, its alarm rings, or its read times out. Stale wake-ups are ignored.
Task<void> StreamRing::produce() {
  for (;;) {
    co_await kick_.wait();
    if (wait_ == Wait::Drive) {
      if (cmd_->done) {
        wait_ = Wait::None;
        callback(cmd_->error);
      } else if (s_.now() >= timeoutAt_) {
        ++stats_.timeouts;
        if (tracer_ != nullptr) tracer_->instant(track_, s_.now(), "timeout");
        drive_.abort(*cmd_);  // sceCdBreak: the read ends at once with 0x01, an abort
        wait_ = Wait::None;
        callback(cmd_->error);
      }
    } else if (wait_ == Wait::Alarm && s_.now() >= alarmAt_) {
      wait_ = Wait::None;
      callback(kCdErNone);
    }
  }
}

void StreamRing::callback(std::uint32_t err) {
  if (stmstart_ != 0) retrycnt_ = 0;
  const Tick timeout =
      fromMs((stmstart_ != 0 || err != 0 || retrycnt_ != 0) ? p_.first_read_timeout_ms : p_.read_timeout_ms);
  if (err != 0) {
    ++stats_.errors;
    if (tracer_ != nullptr) tracer_->instant(track_, s_.now(), "read error");
    retrycnt_ = (err == kCdErRead || err == kCdErAbort) ? p_.read_error_retries : 1;
    retryerr_ = err;
  }
  if (retrycnt_ != 0) {
    // Run-up retry: start step x (retries left) sectors before the target (after it near LBN 0).
    --retrycnt_;
    const std::int64_t back = p_.runup_step_sectors * retrycnt_;
    const std::int64_t lba = tgt_ >= back ? tgt_ - back : tgt_ + back;
    if (!issueRead(lba, timeout)) {
      armAlarm(fromMs(p_.issue_retry_ms));
      ++retrycnt_;
    }
    return;
  }
  std::int64_t filled = -1;
  if (stmstart_ == 0) {
    used_[gp_] = true;
    filled = gp_;
    gp_ = next(gp_);
  }
  if (stmstart_ == 0 && (used_[gp_] || cur_ == gp_)) {
    // "read Full": hold the bank back, let the drive idle, look again in 8 ms.
    gp_ = filled;
    used_[filled] = false;
    ++stats_.fullPolls;
    armAlarm(fromMs(p_.repoll_ms));
    if (tracer_ != nullptr) tracer_->instant(track_, s_.now(), "full");
    return;
  }
  if (filled >= 0) {
    ++stats_.banksFilled;
    bankSinceStart_ = true;
    bankSinceSeek_ = true;
    publish();
  }
  if (stmstart_ == 2) {
    offs_ = cur_ = gp_ = 0;
    clearBanks();
  }
  stmstart_ = 0;
  tgt_ = lsn_;
  if (!issueRead(lsn_, timeout)) {
    armAlarm(fromMs(p_.issue_retry_ms));
    retrycnt_ = 1;
  }
  lsn_ += bankSectors_;
}

Task<bool> StreamRing::start(std::int64_t lbn) {
  wait_ = Wait::None;  // cancel alarm and timeout
  owner_ = false;
  clearBanks();
  lsn_ = lbn;
  offs_ = cur_ = gp_ = 0;
  retryerr_ = 0;
  bankSinceStart_ = false;
  co_await drive_.sync();
  stmstart_ = 1;
  owner_ = true;
  armAlarm(0);  // sceCdNop: completes at once and runs the callback
  co_return true;
}

Task<bool> StreamRing::seek(std::int64_t lbn) {
  if (stmstart_ == 2) co_return false;
  wait_ = Wait::None;
  owner_ = false;
  lsn_ = lbn;
  offs_ = cur_ = gp_ = 0;
  co_await drive_.sync();
  clearBanks();
  bankSinceSeek_ = false;
  stmstart_ = 1;
  owner_ = true;
  armAlarm(0);
  co_return true;
}

bool StreamRing::seekDeferred(std::int64_t lbn) {
  if (!owner_) return false;
  lsn_ = lbn;
  clearBanks();
  bankSinceSeek_ = false;
  stmstart_ = 2;
  return true;
}

Task<bool> StreamRing::pause() {
  if (stmstart_ == 2) co_return false;
  wait_ = Wait::None;
  owner_ = false;
  co_await drive_.sync();
  changed_.notify();
  co_return true;
}

bool StreamRing::resume() {
  if (stmstart_ == 2) return false;
  if (wait_ != Wait::None || drive_.busy()) return false;  // sceCdNop refused while busy
  owner_ = true;
  armAlarm(0);
  return true;
}

Task<bool> StreamRing::stop() {
  stmstart_ = 0;
  wait_ = Wait::None;
  owner_ = false;
  if (cmd_ && !cmd_->done) drive_.abort(*cmd_);
  offs_ = cur_ = gp_ = 0;
  clearBanks();
  co_await drive_.sync();
  retryerr_ = 0;
  changed_.notify();
  co_return true;
}

std::uint32_t StreamRing::stat() const {
  if (stmstart_ == 2) return 0;
  std::int64_t b = cur_;
  if (!used_[b]) {
    b = next(b);
    if (!used_[b]) b = cur_;
  }
  std::int64_t i = 0;
  while (i < bankmax_ && used_[b] && gp_ != b) {
    b = next(b);
    ++i;
  }
  return static_cast<std::uint32_t>(i * bankSectors_);
}

Task<std::uint32_t> StreamRing::read(std::uint32_t n, std::span<std::uint8_t> dest) {
  if (stmstart_ == 2) co_return 0;
  // The count travels in 16 bits; a larger request is served in part, like any short read.
  n = std::min<std::uint32_t>({n, static_cast<std::uint32_t>(dest.size() / kSectorBytes), 0xFFFFu});
  std::uint32_t count = 0;
  while (count < n) {
    if (!used_[cur_]) {
      // Nothing in the reader's bank: step to the next if it is full, but return what we have.
      const std::int64_t prev = cur_;
      cur_ = next(cur_);
      if (!used_[cur_]) cur_ = prev;
      break;
    }
    const auto chunk = static_cast<std::uint32_t>(std::min<std::int64_t>(bankSectors_ - offs_, n - count));
    if (chunk != 0) {
      const std::size_t from = static_cast<std::size_t>(cur_ * bankSectors_ + offs_) * kSectorBytes;
      std::memcpy(dest.data() + static_cast<std::size_t>(count) * kSectorBytes, buffer_.data() + from,
                  static_cast<std::size_t>(chunk) * kSectorBytes);
      offs_ += chunk;
      co_await sif_.transfer(static_cast<std::size_t>(chunk) * kSectorBytes);  // one sceSifSetDma, waited for
      count += chunk;
    }
    if (offs_ >= bankSectors_) {
      offs_ = 0;
      used_[cur_] = false;
      publish();
      const std::int64_t prev = cur_;
      cur_ = next(cur_);
      if (!(used_[cur_] && gp_ != cur_)) {
        cur_ = prev;  // the next bank is not ready: stay, and stop here
        break;
      }
    }
  }
  if (count < n && owner_) {
    ++stats_.underruns;
    if (!bankSinceStart_) {
      ++stats_.startupPolls;
    } else if (!bankSinceSeek_) {
      ++stats_.seekPolls;
    }
    if (stats_.firstUnderrunAt < 0) stats_.firstUnderrunAt = s_.now();
    if (tracer_ != nullptr) tracer_->instant(track_, s_.now(), "underrun");
  }
  std::uint32_t err = retryerr_;
  if (!owner_ && count == 0 && err == 0) err = kCdErStreamIdle;
  retryerr_ = 0;
  co_return (count & 0xFFFF) | (err << 16);
}

Task<std::uint32_t> StreamRing::readBlocking(std::uint32_t n, std::span<std::uint8_t> dest, std::uint32_t& error) {
  error = 0;
  std::uint32_t got = 0;
  for (;;) {
    const std::uint32_t r = co_await read(n - got, dest.subspan(static_cast<std::size_t>(got) * kSectorBytes));
    got += stCount(r);
    if (stError(r) != 0) error = stError(r);
    if (got >= n) break;
    if (stError(r) != 0 && stCount(r) == 0) break;
    // Nothing came: wait for a bank to become visible instead of spinning (a 0 with data already
    // visible is the driver stepping to the next bank; call again at once).
    if (stCount(r) == 0 && stat() == 0) co_await changed_.wait();
  }
  co_return got;
}

}  // namespace vbim::iop
