// The CDVD drive as a cooperating process on the Scheduler. It serves one command at a time:
// spin-up, seek (contiguous / fast / full by distance), rotational latency drawn from the run's
// seed, sector reads at the CAV or CLV rate of the sector's position, per-sector read errors with
// drive retries (one revolution each), end of media (0x32), and the DMA of each sector into IOP
// RAM, which overlaps the next sector's read. While idle it reads ahead up to 16 sectors.
// Sources: P-CDVD and P-CDVDi, summarised in docs/hardware.md#dvd-drive; assumed values in
// docs/hardware.md#model-defaults.
//
// Faults act only on the simulated clock: a stall freezes the mechanism (every piece of drive work
// that overlaps it is pushed back by the overlap); sector faults fail a number of read attempts;
// other IOP clients' commands (seek-away, contention) queue behind the running command.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "iop/params.hpp"
#include "iop/sector_source.hpp"
#include "runtime/event.hpp"
#include "runtime/rng.hpp"
#include "runtime/scheduler.hpp"
#include "runtime/trace.hpp"

namespace vbim::iop {

enum class SeekClass { Buffered, Contiguous, Fast, Full };
const char* toString(SeekClass c);

struct DriveCommand {
  enum class Kind { Read, Hold };
  Kind kind = Kind::Read;
  std::int64_t lsn = 0;
  std::int64_t sectors = 0;
  std::uint8_t* dest = nullptr;  // sectors x 2048 bytes of IOP RAM, or null: the data goes elsewhere
  Tick holdFor = 0;              // hold: the drive is taken this long (another client's work)
  bool foreign = false;          // issued by another IOP client (fault plan), not by the stream
  Event* notify = nullptr;       // notified when the command completes (or is aborted)
  // Results.
  bool done = false;
  bool aborted = false;
  std::uint32_t error = 0;
  std::int64_t sectorsDone = 0;
  Tick issuedAt = 0;
  Tick finishedAt = 0;
  SeekClass seek = SeekClass::Contiguous;
};

struct DriveStats {
  std::int64_t commands = 0;
  std::int64_t sectorsRead = 0;          // sectors that passed under the head (not buffered hits)
  std::int64_t bufferedHits = 0;         // sectors served from the read-ahead buffer
  std::int64_t seeks[4] = {0, 0, 0, 0};  // by SeekClass
  std::int64_t retries = 0;              // drive retries (revolutions spent on failed attempts)
  std::int64_t errors = 0;               // commands ended with an error
  std::int64_t spinUps = 0;
  Tick stalled = 0;  // time frozen by stalls while working
};

class Drive {
 public:
  Drive(Scheduler& s, SectorSource& disc, const DriveParams& p, Rng rng, Tracer* tracer = nullptr);
  Drive(const Drive&) = delete;
  Drive& operator=(const Drive&) = delete;

  // sceCdRead: issues the command if the drive is free; false when busy (the caller retries).
  bool tryIssue(std::shared_ptr<DriveCommand> c);
  // Another client waiting for the drive (sceCdSync, then issue): queued behind the running command.
  void enqueue(std::shared_ptr<DriveCommand> c);
  // sceCdBreak: the command ends now with error 0x01; the mechanism stops at its next step.
  void abort(DriveCommand& c);
  bool busy() const { return running_ != nullptr || !queue_.empty(); }
  // sceCdSync(0): resumes when the drive has nothing running or queued.
  Task<void> sync();

  // Fault hooks (see iop/fault_plan.hpp). Stalls may overlap; they are merged (log time each).
  void addStall(Tick begin, Tick end);
  // A series of stalls generated as the clock reaches them (random_stall): `next` returns them in
  // increasing begin order, or nothing when the series ends. The drive asks for the next one once
  // the clock has reached the begin of the last it got, so it always knows the next stall ahead
  // of it and memory stays bounded by what is still ahead.
  struct StallSpan {
    Tick begin;
    Tick end;
  };
  void addStallSeries(std::function<std::optional<StallSpan>()> next);
  // The sector at `lba` fails its next `attempts` read attempts, counted from time `from`.
  void addSectorFault(std::int64_t lba, std::int64_t attempts, Tick from = 0);
  // Between from and to, each sector read fails with probability ppm / 1e6, for `attempts` attempts.
  void addRandomErrors(Tick from, Tick to, std::int64_t ppm, std::int64_t attempts);

  // The model's arithmetic, exposed for tests and reports.
  Tick sectorTicks(std::int64_t lsn) const;  // time for one sector to pass under the head
  Tick revolutionTicks() const;
  Tick seekTicks(SeekClass c) const;
  Tick dmaTicks() const;
  SeekClass classify(std::int64_t from, std::int64_t to) const;  // head at `from`, target `to`

  std::int64_t head() const { return head_; }
  bool spinning() const { return spinning_; }
  const DriveStats& stats() const { return stats_; }
  // Busy time up to `at` (at or after the last event): the sum of the spans on the drive's own
  // trace track ("drive": spin-up, seeks, latency, reads, retries, stalls, other clients' holds),
  // counted with or without a tracer so the busy share does not depend on tracing. A read's span
  // stops where a retry or a stall inside it begins and goes on after it, so no time counts twice
  // and the trace's drive_busy wire stays high through the whole read.
  Tick busyTime(Tick at) const;
  const DriveParams& params() const { return p_; }
  SectorSource& disc() { return disc_; }
  Process& process() { return *proc_; }

 private:
  struct StallSeries {
    std::function<std::optional<StallSpan>()> next;
    Tick lastBegin = std::numeric_limits<Tick>::min();
    bool ended = false;
  };
  struct RandomErrors {
    Tick from;
    Tick to;
    std::int64_t ppm;
    std::int64_t attempts;
  };
  struct SectorFault {
    std::int64_t attempts;
    Tick from;
  };

  Task<void> run();
  Task<void> execute(DriveCommand& c);
  Task<void> executeRead(DriveCommand& c);
  Task<void> work(Tick d, std::string_view what);
  Task<void> waitOutStall();
  void finish(DriveCommand& c);
  void busySpan(Tick begin, Tick end, std::string_view what);  // a span on the drive track, counted
  std::int64_t readAheadSectors(Tick idle) const;
  Tick stallOverlap(Tick from, Tick to);
  void refreshStalls();  // pulls the series up to the clock, forgets stalls no query can reach
  bool attemptFails(std::int64_t lba);
  std::int64_t maxRetries() const { return p_.retry_count == 0 ? 256 : p_.retry_count; }

  Scheduler& s_;
  SectorSource& disc_;
  DriveParams p_;
  Rng latencyRng_;
  Rng errorRng_;
  Tracer* tracer_;
  Tracer::TrackId track_ = 0;
  Tracer::TrackId dmaTrack_ = 0;
  Process* proc_ = nullptr;
  Event wake_;
  Event idle_;
  std::deque<std::shared_ptr<DriveCommand>> queue_;
  std::shared_ptr<DriveCommand> running_;
  bool spinning_;
  std::int64_t head_ = 0;        // next sector under the head after the last read
  bool headValid_ = false;       // read-ahead continues from head_ only after a read
  Tick lastEnd_ = 0;             // when the drive last went idle
  std::map<Tick, Tick> stalls_;  // begin -> end: disjoint, touching ones merged
  std::vector<StallSeries> stallSeries_;
  std::map<std::int64_t, SectorFault> sectorFaults_;
  std::vector<RandomErrors> randomErrors_;
  DriveStats stats_;
  Tick busy_ = 0;                               // spans recorded so far, each counted whole
  Tick openStallBegin_ = 0, openStallEnd_ = 0;  // the stall being waited out (may end after `at`)
  // The read under way: the start of its span not yet recorded, and its label (null: none).
  Tick readStretchBegin_ = 0;
  const char* readLabel_ = nullptr;
  void closeReadStretch();  // records the read's span up to now (before a retry or a stall)
};

}  // namespace vbim::iop
