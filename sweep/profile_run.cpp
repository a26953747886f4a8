#include "sweep/profile_run.hpp"

#include <filesystem>

#include "iop/file_disc.hpp"
#include "iop/memory_disc.hpp"
#include "player/scenario.hpp"

namespace vbim::sweep {

using namespace player;

std::shared_ptr<Stream> bareStream(const std::string& path) {
  auto s = std::make_shared<Stream>();
  s->label = std::filesystem::path(path).stem().string();
  auto disc = iop::bareFileDisc(path);
  s->file = disc->file();
  s->disc = std::move(disc);
  return s;
}

std::shared_ptr<Stream> memoryStream(const std::string& label, std::vector<std::uint8_t> bytes) {
  auto s = std::make_shared<Stream>();
  s->label = label;
  const auto sectors = static_cast<std::int64_t>(bytes.size() / iop::kSectorBytes);
  auto disc = std::make_shared<iop::MemoryDisc>(iop::kBareFileLba + sectors + iop::kBareFilePadSectors,
                                                label + " (re-encoded in memory)");
  disc->addFile(label + ".vbim", iop::kBareFileLba, std::move(bytes));
  s->file = *disc->find(label + ".vbim");
  s->disc = std::move(disc);
  return s;
}

CaseResult runCase(const Case& c, bool keepSeries) {
  PlayerOptions o;
  o.config = c.config;
  o.faults = c.faults;
  o.seed = c.seed;
  o.duration = c.duration;
  o.trace = false;
  o.reference = c.reference;
  o.kernels = c.kernels;
  Player p(*c.stream->disc, c.stream->file, o);
  CaseResult r;
  if (keepSeries) r.series.reserve(static_cast<std::size_t>(toSeconds(c.duration) * 60.0) + 2);
  bool shown = false, skyShown = false;  // a frame was in the lightmap (sky) before this vsync
  player::ReadErrorSpans readErrors;
  p.setSink([&](const VsyncRow& row, const Rgba8Image&, const Rgba8Image*) {
    const int pop = shown ? row.lightmap.pop : 0;
    const int skyPop = skyShown && row.sky ? row.sky->pop : 0;
    shown = shown || row.lightmap.targetSeq >= 0;
    skyShown = skyShown || (row.sky && row.sky->targetSeq >= 0);
    r.pop.offer(pop, row.vsync, row.at);
    if (!keepSeries) return;
    Sample s;
    s.t = toSeconds(row.at);
    s.ringBanks = static_cast<int>(row.ringBanks);
    s.lag = row.lag;
    s.pop = pop;
    s.skyPop = skyPop;
    s.behind = row.lightmap.behind;
    r.series.push_back(s);
    readErrors.onVsync(row.at, p.pipeline().drive().stats().retries);
  });
  p.runToEnd();
  if (keepSeries)
    r.faults = player::mergeFaultSpans(player::plannedFaultSpans(c.faults, c.duration), readErrors.spans());
  r.lightmap = p.pipeline().lightmap().counters();
  r.totals = p.totals();
  r.ringUnderruns = p.pipeline().ring().stats().underruns;
  r.driveRetries = p.pipeline().drive().stats().retries;
  r.framesLost = p.pipeline().demux().counters().framesLost;
  r.streamBytes = c.stream->file.bytes;
  const streams::Descriptor& d = p.stream().descriptor;
  r.streamFrames = d.totalFrames();
  r.gameFpsNum = d.gameFps.num;
  r.gameFpsDen = d.gameFps.den;
  r.quality = c.stream->quality;
  r.elapsed = p.now();
  r.ipuBusy = p.pipeline().decode().busy;
  r.eeBusy = p.pipeline().decode().eeBusy;
  return r;
}

const char* toString(Criterion c) {
  return c == Criterion::Late ? "no-late-frame" : "pop";
}

namespace {

bool survives(const Case& base, const StallSearch& s, Criterion criterion, Tick stall) {
  Case c = base;
  c.reference = false;
  if (stall > 0) {
    iop::Fault f;
    f.kind = iop::Fault::Kind::Stall;
    f.at = s.stallAt;
    f.duration = stall;
    c.faults.faults.push_back(f);
  }
  c.duration = s.stallAt + stall + s.settle;
  const CaseResult r = runCase(c, false);
  if (criterion == Criterion::Late) return r.lightmap.framesLate == 0 && r.lightmap.behindVsyncs == 0;
  return r.pop.value <= s.popThreshold;
}

}  // namespace

StallResult longestSurvivableStall(const Case& base, const StallSearch& search, Criterion criterion) {
  StallResult out;
  StallSearch s = search;
  if (criterion == Criterion::Pop && s.popThreshold < 0) {
    Case c = base;
    c.reference = false;
    c.duration = s.stallAt + s.maxStall + s.settle;
    ++out.runs;
    s.popThreshold = runCase(c, false).pop.value;
  }
  out.popThreshold = criterion == Criterion::Pop ? s.popThreshold : -1;
  ++out.runs;
  if (!survives(base, s, criterion, 0)) return out;
  ++out.runs;
  if (survives(base, s, criterion, s.maxStall)) {
    out.longest = s.maxStall;
    out.saturated = true;
    return out;
  }
  // Invariant: lo survives, hi fails. Integer ticks: the same midpoints on every machine.
  Tick lo = 0, hi = s.maxStall;
  while (hi - lo > s.resolution) {
    const Tick mid = lo + (hi - lo) / 2;
    ++out.runs;
    if (survives(base, s, criterion, mid)) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  out.longest = lo;
  return out;
}

}  // namespace vbim::sweep
