#include "sweep/outputs/demo_profile.hpp"

#include <chrono>
#include <fstream>
#include <memory>

#include "gs/simd/blend_simd.hpp"
#include "ipu/simd/simd_kernels.hpp"
#include "player/fault_spans.hpp"
#include "plots/profile_figures.hpp"
#include "plots/write_chart.hpp"
#include "sweep/outputs/profile_outputs.hpp"

namespace vbim::sweep {

void DemoProfile::onRow(const player::VsyncRow& row) {
  Sample s;
  s.t = toSeconds(row.at);
  s.ringBanks = static_cast<int>(row.ringBanks);
  s.lag = row.lag;
  s.pop = shown_ ? row.lightmap.pop : 0;  // the first frame copied into the empty lightmap is no pop
  shown_ = shown_ || row.lightmap.targetSeq >= 0;
  s.behind = row.lightmap.behind;
  series_.push_back(s);
}

void DemoProfile::write(const std::string& disc, const std::filesystem::path& dir,
                        const std::function<void()>& checkStop) {
  const auto wall0 = std::chrono::steady_clock::now();  // host time: the demo's summary only
  std::filesystem::create_directories(dir / "plots");
  const RingSize demoRing{player::PlatformConfig{}.iop.ring.bankmax, player::PlatformConfig{}.iop.ring.bufmax_sectors};
  const std::vector<plots::profile::RunTrace> runs{
      {"vbim demo (ring 160 sectors, 5 banks)", demoRing.bankmax, tracePoints(series_)}};
  const std::string title = "vbim demo: day_clear with a 6 s stall at 0.2 s, a read error and a loop wrap";
  // The drive's faults as the run wrote them (faults.csv, already in `dir`), shaded in the figures.
  std::vector<plots::profile::FaultInterval> faults;
  for (const player::FaultSpan& f : player::readFaultSpansCsv(dir / "faults.csv"))
    faults.push_back({f.kind, f.beginS, f.endS});
  plots::writeChartFiles(plots::profile::occupancyFigure(title, runs, faults), dir / "plots/occupancy");
  plots::writeChartFiles(plots::profile::lagPopFigure(title, runs, -1, faults), dir / "plots/lag_pop");

  const auto stream = bareStream(disc);
  // The authored file's temporary name carries the process id; the legend names it as it is
  // saved (day.vbim), so that the figure is the same on every run.
  stream->label = "day";
  StallSearch search;
  search.stallAt = fromMs(3'000);
  search.maxStall = fromMs(20'000);
  search.resolution = fromMs(100);
  search.settle = fromMs(5'000);
  std::vector<StallRow> rows;
  for (const RingSize ring : {RingSize{4, 8}, RingSize{4, 16}, RingSize{4, 32}, RingSize{4, 64}, RingSize{5, 160}}) {
    Case c;
    c.stream = stream.get();
    c.config.iop.ring.bankmax = ring.bankmax;
    c.config.iop.ring.bufmax_sectors = ring.bufmax;
    c.kernels = {&gs::simd::kernels(), &ipu::simdKernels()};
    for (Criterion crit : {Criterion::Late, Criterion::Pop}) {
      if (checkStop) checkStop();
      rows.push_back(StallRow{stream->label, ring, c.config.gs.catchup, crit, longestSurvivableStall(c, search, crit)});
    }
  }
  plots::writeChartFiles(plots::profile::stallFigure("vbim demo: survivable drive stall against ring size",
                                                     stallPoints(rows), stallSearchSetup(search)),
                         dir / "plots/survivable_stall");
  std::ofstream csv(dir / "plots/survivable_stall.csv", std::ios::binary);
  writeStallCsv(rows, search, csv);
  seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
}

}  // namespace vbim::sweep
