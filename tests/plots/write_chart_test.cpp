// Whole picture files from PLplot: the same figure gives the same bytes (PNG and SVG, also within
// one process), the PNG decodes to the figure's size with the series' colour in it, files are
// complete or absent, and failures are vbim::Errors that name the file and what to do.
#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "plots/write_chart.hpp"
#include "runtime/error.hpp"

namespace {

namespace fs = std::filesystem;
using namespace vbim::plots;

fs::path scratch(const std::string& name) {
  fs::path p = fs::path(::testing::TempDir()) / ("vbim_plots_" + std::to_string(getpid()) + "_" + name);
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// Two panels: a step series with a dashed reference line, a series with markers; legends; a '#'
// (PLplot's escape character) in the title.
Figure sampleFigure() {
  Figure f;
  f.title = "Sample figure #1";
  Panel a;
  a.title = "Occupancy";
  a.xLabel = "simulated time (s)";
  a.yLabel = "% readable";
  Series s{"ring 8 sectors", paletteColor(0), {}, {}, true, false, 2};
  for (int i = 0; i <= 40; ++i) {
    s.x.push_back(i * 0.2);
    s.y.push_back((i / 5) % 3 * 25.0);
  }
  a.series.push_back(s);
  a.refLines.push_back(RefLine{"threshold 40", 40});
  Panel b;
  b.title = "Markers";
  b.series.push_back(Series{"points", paletteColor(1), {0, 4, 8}, {1, 3, 2}, false, true, 2});
  f.panels = {a, b};
  return f;
}

struct Rgba {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
};

std::optional<Rgba> decodePng(const std::string& bytes) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size())) return std::nullopt;
  image.format = PNG_FORMAT_RGB;
  Rgba out;
  out.width = static_cast<int>(image.width);
  out.height = static_cast<int>(image.height);
  out.rgb.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, out.rgb.data(), 0, nullptr)) return std::nullopt;
  return out;
}

TEST(PlotFiles, SameFigureSameBytesPngAndSvg) {
  const fs::path a = scratch("a"), b = scratch("b");
  const std::vector<fs::path> first = writeChartFiles(sampleFigure(), a / "chart");
  ASSERT_EQ(first, (std::vector<fs::path>{a / "chart.png", a / "chart.svg"}));
  writeChartFiles(sampleFigure(), b / "chart");  // cairo's process-wide counters have moved on
  for (const char* f : {"chart.png", "chart.svg"}) {
    EXPECT_GT(fs::file_size(a / f), 1000u) << f;
    EXPECT_EQ(slurp(a / f), slurp(b / f)) << f << " differs between two identical draws";
  }
  EXPECT_TRUE(slurp(a / "chart.svg").starts_with("<?xml"));
  // Only the two pictures: no temporary file is left.
  EXPECT_EQ(std::distance(fs::directory_iterator(a), fs::directory_iterator()), 2);
  fs::remove_all(a);
  fs::remove_all(b);
}

TEST(PlotFiles, PngDecodesToTheFigureSizeWithTheSeriesColour) {
  const Figure fig = sampleFigure();
  const std::optional<Rgba> img = decodePng(renderChart(fig, Format::Png, "sample.png"));
  ASSERT_TRUE(img.has_value());
  EXPECT_EQ(img->width, 1200);
  EXPECT_EQ(img->height, 40 + 2 * 320);
  std::size_t white = 0, seriesBlue = 0;
  const Rgb blue = paletteColor(0);
  for (std::size_t i = 0; i + 2 < img->rgb.size(); i += 3) {
    const unsigned char r = img->rgb[i], g = img->rgb[i + 1], b = img->rgb[i + 2];
    white += r == 255 && g == 255 && b == 255;
    seriesBlue += r == blue.r && g == blue.g && b == blue.b;
  }
  const std::size_t pixels = img->rgb.size() / 3;
  EXPECT_GT(white, pixels / 2);         // a white page
  EXPECT_LT(white, pixels * 99 / 100);  // with something drawn on it
  EXPECT_GT(seriesBlue, 200u);          // the step line, 2 pixels wide
}

// A band (a drive stall) is shaded across the panel between its x values, behind the line, and
// named in the legend by a box of its colour; the picture without it has none of that colour.
TEST(PlotFiles, BandsAreShadedAndNamedInTheLegend) {
  Figure fig = sampleFigure();
  const Rgb pale{226, 204, 246};
  fig.panels[0].bands.push_back(Band{"drive stall (fault plan)", 2.0, 4.0, pale});
  const std::optional<Rgba> img = decodePng(renderChart(fig, Format::Png, "bands.png"));
  const std::optional<Rgba> plain = decodePng(renderChart(sampleFigure(), Format::Png, "plain.png"));
  ASSERT_TRUE(img.has_value() && plain.has_value());
  // Columns holding the colour, in the plot area (left of the legend) and in the legend.
  const auto count = [&](const Rgba& im, int x0, int x1) {
    std::size_t n = 0;
    for (int y = 40; y < 40 + 320; ++y) {
      for (int x = x0; x < x1; ++x) {
        const unsigned char* p = &im.rgb[(static_cast<std::size_t>(y) * im.width + x) * 3];
        n += p[0] == pale.r && p[1] == pale.g && p[2] == pale.b;
      }
    }
    return n;
  };
  EXPECT_EQ(count(*plain, 0, img->width), 0u);
  EXPECT_GT(count(*img, 0, 800), 100u * 100u) << "the band: 2 of 8 s across a panel about 220 pixels high";
  EXPECT_GT(count(*img, 900, img->width), 50u) << "its box in the legend";
  // Drawn again: the same bytes.
  EXPECT_EQ(renderChart(fig, Format::Png, "bands.png"), renderChart(fig, Format::Png, "bands.png"));
}

TEST(PlotFiles, UnwritableDirectoryIsAnErrorNamingTheFile) {
  const fs::path missing = fs::path(::testing::TempDir()) / ("vbim_plots_missing_" + std::to_string(getpid()));
  fs::remove_all(missing);
  try {
    writeChartFiles(sampleFigure(), missing / "chart");
    FAIL() << "no error";
  } catch (const vbim::Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find((missing / "chart.png").string()), std::string::npos) << what;
    EXPECT_NE(what.find("cannot write"), std::string::npos) << what;
  }
  // A "directory" that is a regular file (fails for root too).
  const fs::path dir = scratch("file");
  std::ofstream(dir / "not_a_dir") << "x";
  EXPECT_THROW(writeChart(sampleFigure(), dir / "not_a_dir" / "chart.svg", Format::Svg), vbim::Error);
  EXPECT_FALSE(fs::exists(missing));
  fs::remove_all(dir);
}

TEST(PlotFiles, MissingCairoDriverNamesThePackage) {
  const fs::path empty = scratch("drivers");
  const char* before = std::getenv("PLPLOT_DRV_DIR");
  const std::optional<std::string> saved = before ? std::optional<std::string>(before) : std::nullopt;
  setenv("PLPLOT_DRV_DIR", empty.c_str(), 1);
  try {
    renderChart(sampleFigure(), Format::Png, "chart.png");
    ADD_FAILURE() << "no error";
  } catch (const vbim::Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("chart.png"), std::string::npos) << what;
    EXPECT_NE(what.find("apt-get install plplot-driver-cairo"), std::string::npos) << what;
  }
  if (saved) {
    setenv("PLPLOT_DRV_DIR", saved->c_str(), 1);
  } else {
    unsetenv("PLPLOT_DRV_DIR");
  }
  // Plotting works again afterwards.
  EXPECT_FALSE(renderChart(sampleFigure(), Format::Svg, "chart.svg").empty());
  fs::remove_all(empty);
}

}  // namespace
