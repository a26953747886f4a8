#include "plots/write_chart.hpp"

#include "plots/atomic_file.hpp"
#include "plots/draw_chart.hpp"
#include "plots/plplot_page.hpp"
#include "plots/svg_ids.hpp"

namespace vbim::plots {

std::string renderChart(const Figure& fig, Format format, const std::string& name) {
  PlplotPage page(format == Format::Png ? Device::Png : Device::Svg, fig.width, figureHeight(fig), name);
  drawChart(fig);
  page.check();
  std::string bytes = page.finish();
  return format == Format::Svg ? renumberCairoIds(bytes) : bytes;
}

void writeChart(const Figure& fig, const std::filesystem::path& file, Format format) {
  writeFileAtomically(file, renderChart(fig, format, file.string()));
}

std::vector<std::filesystem::path> writeChartFiles(const Figure& fig, const std::filesystem::path& stem) {
  std::vector<std::filesystem::path> files;
  for (const Format f : {Format::Png, Format::Svg}) {
    std::filesystem::path file = stem;
    file += f == Format::Png ? ".png" : ".svg";
    writeChart(fig, file, f);
    files.push_back(std::move(file));
  }
  return files;
}

}  // namespace vbim::plots
