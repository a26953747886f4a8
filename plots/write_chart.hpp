// Figures as picture files, drawn by PLplot (plots/draw_chart.hpp) with its cairo devices: PNG
// (8-bit RGBA) and SVG. The same figure gives the same bytes on every run: cairo's PNG writer
// stores no time, and the SVG's process-wide ids are renumbered (plots/svg_ids.hpp). Fonts come
// from fontconfig ("sans": DejaVu Sans on Debian), so bytes can differ between machines with other
// fonts. Every file is complete or absent (plots/atomic_file.hpp).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "plots/chart.hpp"

namespace vbim::plots {

enum class Format { Png, Svg };

// The picture's bytes; `name` names it in error messages. Throws Error.
std::string renderChart(const Figure& fig, Format format, const std::string& name);

// Writes one picture file. Throws Error naming the file.
void writeChart(const Figure& fig, const std::filesystem::path& file, Format format);

// Writes `stem`.png and `stem`.svg and returns their paths (PNG first). Throws Error.
std::vector<std::filesystem::path> writeChartFiles(const Figure& fig, const std::filesystem::path& stem);

}  // namespace vbim::plots
