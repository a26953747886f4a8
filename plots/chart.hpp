// A line chart as plain data: one or more panels stacked vertically that share one x range, each
// with a title, axis labels, named series (listed in a legend right of the panel), optional
// horizontal reference lines (a threshold, a search limit) and shaded x intervals (faults). plots/write_chart.hpp draws
// it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vbim::plots {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

// Distinguishable colours (colour-blind friendly, Okabe and Ito's palette), cycled by index.
Rgb paletteColor(std::size_t i);

struct Series {
  std::string name;  // empty: not in the legend
  Rgb color{0, 114, 178};
  std::vector<double> x, y;
  bool step = false;     // hold each value until the next x (occupancy, counts)
  bool markers = false;  // a small filled square at every point (sparse data: the survivable-stall curve)
  int thickness = 1;     // line width in pixels
};

struct RefLine {
  std::string name;  // shown in the legend (dashed)
  double y = 0;
  Rgb color{204, 26, 26};
};

// A shaded interval of x across the whole panel, behind the grid and the lines (a drive stall, a
// read error), named in the legend by a colour box (one entry per name).
struct Band {
  std::string name;
  double x0 = 0, x1 = 0;
  Rgb color{230, 230, 230};
};

struct Panel {
  std::string title;
  std::string xLabel;
  std::string yLabel;
  std::vector<Series> series;
  std::vector<RefLine> refLines;
  std::vector<Band> bands;
  std::optional<double> yMin, yMax;  // default: from the data (yMin 0 when all data are >= 0)
  bool xLog2 = false;                // x axis in powers of two (ring sizes)
};

struct Figure {
  std::string title;
  int width = 1200;       // pixels (PNG) or points (SVG)
  int panelHeight = 320;  // the figure is the title's 40 plus this per panel high
  std::vector<Panel> panels;
};

}  // namespace vbim::plots
