// Draws a Figure on the current PLplot page (plots/plplot_page.hpp) with PLplot's plotting calls:
// per panel a grid, the axes with their tick labels, dashed reference lines, the series, the
// titles and a legend right of the plot area. Layout in pixels (points in SVG), as the figure says.
#pragma once

#include "plots/chart.hpp"

namespace vbim::plots {

// The page height the figure needs: a title row and one row per panel.
int figureHeight(const Figure& fig);

void drawChart(const Figure& fig);

}  // namespace vbim::plots
