// Line charts drawn into an RGB image buffer and written as PNG through OpenImageIO: one or more
// panels stacked vertically (sharing the x range), each with axes, "nice" ticks (1, 2, 5 x 10^k),
// tick labels, axis labels, a title, a legend and optional horizontal reference lines (a
// threshold). Used by `vbim profile` and `vbim demo`; text needs a TrueType font (DejaVu Sans is
// looked up first); without one the chart is still drawn and a warning says the labels are missing.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vbim::cli::plot {

using Color = std::array<float, 3>;

// A palette of distinguishable colours (colour-blind friendly, Okabe-Ito), cycled by index.
Color paletteColor(std::size_t i);

struct Series {
  std::string name;
  Color color{0.0f, 0.45f, 0.70f};
  std::vector<double> x, y;
  bool step = false;     // hold each value until the next x (occupancy, counts)
  bool markers = false;  // draw a small box at every point (sparse data: the survivable-stall curve)
  int thickness = 1;     // pixels, centred on the line
};

struct RefLine {
  std::string name;  // shown in the legend
  double y = 0;
  Color color{0.8f, 0.1f, 0.1f};
};

struct Panel {
  std::string title;
  std::string xLabel;
  std::string yLabel;
  std::vector<Series> series;
  std::vector<RefLine> refLines;
  std::optional<double> yMin, yMax;  // default: from the data (yMin 0 when all data are >= 0)
  bool xLog2 = false;                // x axis in powers of two (ring sizes)
};

struct Figure {
  std::string title;
  int width = 1200;
  int panelHeight = 320;
  std::vector<Panel> panels;
};

// Draws the figure and writes it to `path` (PNG). Throws std::runtime_error naming the file on failure.
// Returns false when text could not be rendered (no font found); the image is written anyway.
bool writePng(const Figure& fig, const std::filesystem::path& path);

// Ticks between lo and hi: about `target` round values (1, 2, 5 x 10^k), inclusive of the range.
std::vector<double> niceTicks(double lo, double hi, int target);

}  // namespace vbim::cli::plot
