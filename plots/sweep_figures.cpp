#include "plots/sweep_figures.hpp"

#include "plots/write_chart.hpp"

namespace vbim::plots::sweep {

Figure probabilityFigure(const std::string& title, const std::string& interval,
                         const std::vector<ProbabilityLine>& lines) {
  Figure f;
  f.title = title;
  Panel p;
  p.title = "estimate (thick, markers) and " + interval + " (thin)";
  p.xLabel = "ring size (sectors)";
  p.yLabel = "probability";
  p.yMin = 0.0;
  p.yMax = 1.0;
  p.xLog2 = true;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const ProbabilityLine& l = lines[i];
    Series est{l.name, paletteColor(i), l.ringSectors, l.p, false, true, 3};
    Series low{"", paletteColor(i), l.ringSectors, l.low, false, false, 1};
    Series high{"", paletteColor(i), l.ringSectors, l.high, false, false, 1};
    p.series.push_back(std::move(est));
    p.series.push_back(std::move(low));
    p.series.push_back(std::move(high));
  }
  f.panels.push_back(std::move(p));
  return f;
}

std::vector<std::string> writeProbabilityFigure(const Figure& fig, const std::filesystem::path& dir,
                                                const std::string& stem) {
  std::filesystem::create_directories((dir / stem).parent_path());
  std::vector<std::string> written;
  for (const std::filesystem::path& file : writeChartFiles(fig, dir / stem))
    written.push_back(stem + file.extension().string());
  return written;
}

}  // namespace vbim::plots::sweep
