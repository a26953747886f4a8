// The figure of a sweep plan's summary (`vbim profile --plan`, docs/sweeps.md): an estimated
// probability against ring size with its confidence interval, one line per group of the other
// axes. Plain inputs; the estimates are made by the command.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "plots/chart.hpp"

namespace vbim::plots::sweep {

// One group's estimates: p and its interval at each ring size (sectors), in ring order.
struct ProbabilityLine {
  std::string name;
  std::vector<double> ringSectors, p, low, high;
};

// p against ring size (log2 axis), the interval drawn as thin lines of the same colour.
Figure probabilityFigure(const std::string& title, const std::string& interval,
                         const std::vector<ProbabilityLine>& lines);

// Writes `stem`.png and .svg under `dir`; returns the names written relative to `dir`.
std::vector<std::string> writeProbabilityFigure(const Figure& fig, const std::filesystem::path& dir,
                                                const std::string& stem);

}  // namespace vbim::plots::sweep
