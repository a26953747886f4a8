// The sceCdStRead vectors: scripted scenarios run on the IOP ring model (iop/stream_ring.hpp) with
// a drive whose faults are scripted. Each step waits for a state of the ring (not a time), so the
// results depend on the ring's rules (bank-bounded reads, partial counts, the error report, the
// full-ring hold), not on the drive's speed.
#include <cstring>
#include <functional>

#include "iop/drive.hpp"
#include "iop/memory_disc.hpp"
#include "iop/sif.hpp"
#include "iop/stream_ring.hpp"
#include "player/known_answers.hpp"
#include "runtime/rng.hpp"
#include "runtime/scheduler.hpp"

namespace vbim::player {

namespace {

struct Step {
  enum class Kind { WaitStat, WaitFull, WaitMs, Read, Stat };
  Kind kind;
  std::int64_t n = 0;
};

struct Scenario {
  const char* name;
  const char* what;
  std::int64_t discSectors;
  std::int64_t faultLba;  // -1: none; else fails `faultAttempts` read attempts
  std::int64_t faultAttempts;
  std::vector<Step> steps;
};

Step waitStat(std::int64_t sectors) {
  return {Step::Kind::WaitStat, sectors};
}
Step waitFull() {
  return {Step::Kind::WaitFull, 0};
}
Step waitMs(std::int64_t ms) {
  return {Step::Kind::WaitMs, ms};
}
Step read(std::int64_t n) {
  return {Step::Kind::Read, n};
}
Step stat() {
  return {Step::Kind::Stat, 0};
}

std::string hex2(std::uint32_t v) {
  const char* d = "0123456789abcdef";
  std::string s = "0x";
  for (int shift = 8; shift >= 0; shift -= 4) s += d[(v >> shift) & 0xF];
  return s;
}

Task<void> script(Scheduler& s, iop::StreamRing& ring, const Scenario& sc, std::vector<std::string>& out) {
  (void)co_await ring.start(0);
  std::vector<std::uint8_t> buf;
  int k = 0;
  for (const Step& step : sc.steps) {
    switch (step.kind) {
      case Step::Kind::WaitStat:
        while (ring.stat() < static_cast<std::uint32_t>(step.n)) co_await s.delay(fromUs(100));
        break;
      case Step::Kind::WaitFull:
        while (ring.stats().fullPolls == 0) co_await s.delay(fromUs(100));
        break;
      case Step::Kind::WaitMs:
        co_await s.delay(fromMs(step.n));
        break;
      case Step::Kind::Stat:
        out.push_back(std::to_string(k++) + " sceCdStStat=" + std::to_string(ring.stat()));
        break;
      case Step::Kind::Read: {
        buf.assign(static_cast<std::size_t>(step.n) * iop::kSectorBytes, 0);
        const std::uint32_t before = ring.stat();
        const std::uint32_t r = co_await ring.read(static_cast<std::uint32_t>(step.n), buf);
        std::int64_t lsn = -1;  // the pattern disc's sectors start with their LBA, little-endian
        if (iop::stCount(r) > 0) std::memcpy(&lsn, buf.data(), sizeof lsn);
        out.push_back(std::to_string(k++) + " sceCdStRead(" + std::to_string(step.n) +
                      ")=count:" + std::to_string(iop::stCount(r)) + ",error:" + hex2(iop::stError(r)) +
                      ",first_lsn:" + std::to_string(lsn) + ",stat_before:" + std::to_string(before));
        break;
      }
    }
  }
}

std::vector<std::string> run(const Scenario& sc) {
  iop::IopParams p;
  p.drive.spindle = "clv";
  p.drive.initially_spinning = true;
  p.drive.retry_count = 2;  // a drive command gives up after 3 failing attempts of a sector
  Scheduler s;
  iop::MemoryDisc disc(sc.discSectors);
  disc.addPatternFile("/STREAM.PSS", 0, sc.discSectors);
  iop::Drive drive(s, disc, p.drive, Rng(1));
  iop::SifChannel sif(s, p.sif);
  iop::StreamRing ring(s, drive, sif, p.ring);
  if (sc.faultLba >= 0) drive.addSectorFault(sc.faultLba, sc.faultAttempts);
  std::vector<std::string> out;
  s.spawn("ee", script(s, ring, sc, out));
  s.runUntil(fromMs(20'000));
  return out;
}

}  // namespace

VectorFile streamReadVectors() {
  // sceCdStInit(160, 5): 5 banks of 32 sectors; at most 4 banks (128 sectors) visible.
  const std::vector<Scenario> scenarios = {
      {"full_ring",
       "the ring fills to bankmax - 1 banks and holds; reads are bank-bounded",
       100'000,
       -1,
       0,
       {waitStat(128), waitFull(), stat(), read(16), stat(), read(16), stat(), read(40), stat(), read(128), stat()}},
      {"partial_reads",
       "reading more than is visible returns what there is (an underrun), then 0",
       100'000,
       -1,
       0,
       {waitStat(32), read(48), read(16), waitStat(32), read(32), waitStat(64), read(100), stat()}},
      {"read_error",
       "sector 40 fails 3 attempts: the bank is re-read after a run-up, the error reaches the reader",
       100'000,
       40,
       3,
       {waitStat(32), read(32), waitMs(1'000), stat(), read(32), read(32), read(32), stat()}},
      {"end_of_media",
       "a 80-sector disc: the third bank runs past the end",
       80,
       -1,
       0,
       {waitStat(64), read(32), read(32), waitMs(1'000), stat(), read(32), read(32), stat()}},
  };
  std::string t =
      "# vbim known answers: sceCdStRead (STMNBLK) results for scripted ring scenarios (iop/stream_ring.hpp)\n"
      "# sceCdStInit(bufmax 160, bankmax 5, ...): 5 banks of 32 sectors; sceCdStStart(0, mode) on a disc whose\n"
      "# sector L begins with L as 8 little-endian bytes; the drive retries a failing sector twice.\n"
      "# Steps wait for ring states (sceCdStStat >= N, the first full-ring hold) or for 1 s, never for a drive speed.\n"
      "# KEY cdstread/SCENARIO/K  VALUE the K-th call: sceCdStStat=SECTORS, or\n"
      "#   sceCdStRead(N)=count:C,error:E,first_lsn:L,stat_before:S (C = result & 0xffff, E = result >> 16,\n"
      "#   L the first sector delivered or -1, S sceCdStStat just before the call)\n";
  for (const Scenario& sc : scenarios) {
    t += std::string("# ") + sc.name + ": " + sc.what + "\n";
    for (const std::string& line : run(sc)) t += std::string("cdstread/") + sc.name + "/" + line + "\n";
  }
  return VectorFile{"cdstread.txt", t};
}

}  // namespace vbim::player
