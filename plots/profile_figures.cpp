#include "plots/profile_figures.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <map>

#include "plots/write_chart.hpp"

namespace vbim::plots::profile {

namespace {

std::string fixed(double v, int decimals) {
  char b[48];
  std::snprintf(b, sizeof b, "%.*f", decimals, v);
  return b;
}

// A file-name-safe version of a label.
std::string safe(const std::string& s) {
  std::string o;
  for (char c : s) o += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
  return o;
}

std::string ringLabel(std::int64_t bankmax, std::int64_t bufmax) {
  return std::to_string(bufmax) + " sectors (" + std::to_string(bankmax) + " banks)";
}

}  // namespace

std::vector<Band> faultBands(const std::vector<FaultInterval>& faults) {
  static const struct {
    const char* kind;
    const char* name;
    Rgb colour;
  } kKinds[] = {{"stall", "drive stall (fault plan)", Rgb{226, 204, 246}},
                {"read error", "read error (drive retries)", Rgb{196, 220, 255}},
                {"contention", "contention (another client)", Rgb{250, 236, 170}},
                {"seek away", "seek away (another file)", Rgb{186, 234, 228}},
                {"random stalls", "random stalls may strike", Rgb{238, 220, 250}},
                {"random errors", "random errors may strike", Rgb{216, 234, 255}}};
  std::vector<Band> bands;
  for (const FaultInterval& f : faults) {
    Band b{f.kind + " (drive)", f.beginS, f.endS, Rgb{224, 224, 224}};
    for (const auto& k : kKinds) {
      if (f.kind == k.kind) b = Band{k.name, f.beginS, f.endS, k.colour};
    }
    bands.push_back(std::move(b));
  }
  return bands;
}

Figure occupancyFigure(const std::string& title, const std::vector<RunTrace>& runs,
                       const std::vector<FaultInterval>& faults) {
  Figure f;
  f.title = title;
  f.panelHeight = 360;
  Panel p;
  p.title = "Stream ring occupancy";
  p.yLabel = "% of the ring readable";
  p.xLabel = "simulated time (s)";
  p.yMin = 0;
  p.yMax = 105;
  p.bands = faultBands(faults);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    Series s;
    s.name = runs[i].name;
    s.color = paletteColor(i);
    s.step = true;
    s.thickness = 2;
    const double banks = static_cast<double>(std::max<std::int64_t>(runs[i].bankmax, 1));
    for (const TracePoint& v : runs[i].points) {
      s.x.push_back(v.t);
      s.y.push_back(100.0 * v.ringBanks / banks);
    }
    p.series.push_back(std::move(s));
  }
  f.panels.push_back(std::move(p));
  return f;
}

Figure lagPopFigure(const std::string& title, const std::vector<RunTrace>& runs, int popThreshold,
                    const std::vector<FaultInterval>& faults) {
  Figure f;
  f.title = title;
  Panel lag, pop;
  lag.title = "Lag: largest per-byte difference from the fault-free run";
  lag.yLabel = "lag (8-bit levels)";
  lag.xLabel = "simulated time (s)";
  pop.title = "Pop: largest per-byte change of the lightmap in one vsync";
  pop.yLabel = "pop (8-bit levels)";
  pop.xLabel = "simulated time (s)";
  lag.bands = pop.bands = faultBands(faults);
  if (popThreshold >= 0)
    pop.refLines.push_back(RefLine{"threshold " + std::to_string(popThreshold), static_cast<double>(popThreshold)});
  for (std::size_t i = 0; i < runs.size(); ++i) {
    Series l, p;
    l.name = p.name = runs[i].name;
    l.color = p.color = paletteColor(i);
    l.thickness = 2;
    for (const TracePoint& v : runs[i].points) {
      l.x.push_back(v.t);
      l.y.push_back(v.lag);
      p.x.push_back(v.t);
      p.y.push_back(v.pop);
    }
    lag.series.push_back(std::move(l));
    pop.series.push_back(std::move(p));
  }
  f.panels.push_back(std::move(lag));
  f.panels.push_back(std::move(pop));
  return f;
}

Figure stallFigure(const std::string& title, const std::vector<StallPoint>& points, const StallSearchSetup& setup) {
  Figure f;
  f.title = title;
  f.panelHeight = 420;
  Panel p;
  p.title = "Longest drive stall survived (stall at " + fixed(setup.stallAtS, 1) + " s; pop threshold " +
            (setup.popThreshold >= 0 ? std::to_string(setup.popThreshold) : std::string("auto")) + ")";
  p.yLabel = "longest stall (s)";
  p.xLabel = "stream ring size (sectors of 2 KiB, log scale)";
  p.xLog2 = true;
  p.refLines.push_back(
      RefLine{"search limit " + fixed(setup.maxStallS, 0) + " s", setup.maxStallS, Rgb{153, 153, 153}});
  std::vector<Series> lines;  // in order of first appearance
  for (const StallPoint& pt : points) {
    auto it = std::find_if(lines.begin(), lines.end(), [&](const Series& s) { return s.name == pt.line; });
    if (it == lines.end()) {
      Series s;
      s.name = pt.line;
      s.color = paletteColor(lines.size());
      s.markers = true;
      lines.push_back(std::move(s));
      it = lines.end() - 1;
    }
    if (!pt.longestS) continue;  // fails without a stall: no point
    it->x.push_back(pt.ringSectors);
    it->y.push_back(*pt.longestS);
  }
  // Lines that coincide (common: criteria and policies often agree) stay visible as nested
  // stripes: the first drawn is the widest.
  for (std::size_t i = 0; i < lines.size(); ++i) {
    lines[i].thickness = 2 + 3 * static_cast<int>(lines.size() - 1 - i);
    p.series.push_back(std::move(lines[i]));
  }
  f.panels.push_back(std::move(p));
  return f;
}

std::vector<std::string> writeProfileFigures(const std::vector<SweepTrace>& sweep,
                                             const std::vector<StallPoint>& stalls, const StallSearchSetup& setup,
                                             const std::filesystem::path& dir) {
  std::vector<std::string> written;
  std::filesystem::create_directories(dir / "plots");
  const auto write = [&](const Figure& fig, const std::string& stem) {
    for (const std::filesystem::path& file : writeChartFiles(fig, dir / stem))
      written.push_back(stem + file.extension().string());
  };
  // One occupancy and one lag/pop figure per (stream, faults, policy), a line per ring size.
  std::map<std::string, std::vector<const SweepTrace*>> groups;
  std::vector<std::string> order;
  for (const SweepTrace& s : sweep) {
    const std::string key = s.stream + "_" + s.faults + "_" + s.policy;
    if (!groups.count(key)) order.push_back(key);
    groups[key].push_back(&s);
  }
  for (const std::string& key : order) {
    std::vector<RunTrace> runs;
    for (const SweepTrace* s : groups[key])
      runs.push_back(RunTrace{"ring " + ringLabel(s->bankmax, s->bufmax), s->bankmax, s->points});
    const SweepTrace& first = *groups[key].front();
    const std::string what = first.stream + ", faults: " + first.faults + ", catch-up: " + first.policy;
    write(occupancyFigure(what, runs, first.faultSpans), "plots/occupancy_" + safe(key));
    write(lagPopFigure(what, runs, setup.popThreshold, first.faultSpans), "plots/lag_pop_" + safe(key));
  }
  if (!stalls.empty())
    write(stallFigure("Survivable drive stall against ring size", stalls, setup), "plots/survivable_stall");
  return written;
}

}  // namespace vbim::plots::profile
