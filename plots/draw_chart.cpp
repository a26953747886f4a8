#include "plots/draw_chart.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <plplot/plplot.h>

#include "plots/axes.hpp"
#include "plots/plplot_page.hpp"

namespace vbim::plots {

namespace {

// Margins of a panel's plot area, in pixels.
constexpr int kLeft = 78, kRight = 24, kTop = 44, kBottom = 52;
constexpr int kFigureTitle = 40;
// Text heights in pixels.
constexpr double kTitleText = 18, kPanelTitleText = 16, kTickText = 14, kLabelText = 13;
// Legend: gap to the plot area, line sample length, padding around the text (pixels); the gap
// between sample and text and the distance between rows (PLplot character widths and heights).
constexpr double kLegendGap = 12, kLegendSample = 22, kLegendPadding = 22;
constexpr double kLegendTextOffset = 0.5, kLegendRowSpacing = 1.9;
// Major ticks outward from the axes (pixels).
constexpr double kTickLength = 5;
// Longer text is cut: PLplot's cairo devices build a fixed-size markup buffer per string.
constexpr std::size_t kMaxText = 200;

constexpr Rgb kBlack{0, 0, 0}, kAxisGrey{64, 64, 64}, kGridGrey{224, 224, 224}, kWhite{255, 255, 255};

// PLplot sizes characters in millimetres. Its cairo devices turn them into a font size in points
// (72 per inch), which pango renders at 96 dots per inch, one dot being one pixel of the PNG.
PLFLT mm(double px) {
  return px * 25.4 / 96.0;
}

// PLplot reads '#' as the start of an escape sequence ("#u" superscript, ...): "##" is a '#'.
std::string plainText(const std::string& s) {
  std::string out;
  for (char c : s.substr(0, kMaxText)) out += c == '#' ? std::string("##") : std::string(1, c);
  return out;
}

// cmap0 slots of the colours used so far (slot 0 is the white background).
class Colours {
 public:
  PLINT slot(Rgb c) {
    if (c == kWhite) return 0;
    const auto it = std::find(used_.begin(), used_.end(), c);
    if (it != used_.end()) return static_cast<PLINT>(it - used_.begin()) + 1;
    if (used_.size() + 1 >= static_cast<std::size_t>(PlplotPage::kColourSlots)) return 1;  // out of slots: reuse
    used_.push_back(c);
    const PLINT s = static_cast<PLINT>(used_.size());
    plscol0(s, c.r, c.g, c.b);
    return s;
  }
  void use(Rgb c) { plcol0(slot(c)); }

 private:
  std::vector<Rgb> used_;
};

struct PanelAxes {
  Axis x, y;
};

// PLplot's custom tick labels ("o" in plbox): the same labels as axes.hpp gives.
void labelTick(PLINT axis, PLFLT value, char* label, PLINT length, PLPointer data) {
  try {
    const auto* a = static_cast<const PanelAxes*>(data);
    std::snprintf(label, static_cast<std::size_t>(length), "%s",
                  tickLabel(axis == PL_X_AXIS ? a->x : a->y, value).c_str());
  } catch (...) {  // called from C: nothing may escape
    if (length > 0) label[0] = '\0';
  }
}

// Where things go, in pixels from the top left corner.
struct Box {
  double x0, x1, y0, y1;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
};

class Drawer {
 public:
  Drawer(const Figure& fig) : fig_(fig), w_(fig.width), h_(figureHeight(fig)) {}

  void draw() {
    const Axis x = xAxis(fig_);
    const double legend = legendWidth();
    for (std::size_t i = 0; i < fig_.panels.size(); ++i) {
      const double top = titleHeight() + static_cast<double>(i) * fig_.panelHeight;
      const Box plot{kLeft, w_ - kRight - legend, top + kTop, top + fig_.panelHeight - kBottom};
      drawPanel(fig_.panels[i], x, plot, top);
    }
    if (!fig_.title.empty()) {
      overlay();
      text(w_ / 2.0, 28, fig_.title, kBlack, 0.5, kTitleText);
    }
  }

 private:
  double titleHeight() const { return fig_.title.empty() ? 0 : kFigureTitle; }

  // The same for every panel, so that their x axes line up. PLplot measures text only while
  // drawing it, so the width is estimated from the longest name (about 0.6 em per character).
  double legendWidth() const {
    std::size_t chars = 0;
    bool any = false;
    for (const Panel& p : fig_.panels) {
      for (const Series& s : p.series)
        if (!s.name.empty()) chars = std::max(chars, std::min(s.name.size(), kMaxText)), any = true;
      for (const RefLine& r : p.refLines)
        if (!r.name.empty()) chars = std::max(chars, std::min(r.name.size(), kMaxText)), any = true;
      for (const Band& b : p.bands)
        if (!b.name.empty()) chars = std::max(chars, std::min(b.name.size(), kMaxText)), any = true;
    }
    if (!any) return 0;
    const double w = kLegendGap + kLegendSample + kLegendPadding + 0.6 * kLabelText * static_cast<double>(chars);
    return std::min(w, w_ / 3.0);
  }

  // World coordinates = the axes, inside `b`.
  void viewport(const Box& b, const Axis& x, const Axis& y) const {
    plvpor(b.x0 / w_, b.x1 / w_, 1.0 - b.y1 / h_, 1.0 - b.y0 / h_);
    plwind(x.lo, x.hi, y.lo, y.hi);
  }
  // World coordinates = pixels of the whole page (y up).
  void overlay() const {
    plvpor(0, 1, 0, 1);
    plwind(0, w_, 0, h_);
  }
  // Text with its baseline at y (pixels from the top); PLplot places the middle of a capital letter.
  void text(double x, double baseline, const std::string& s, Rgb c, double just, double size) {
    if (s.empty()) return;
    plschr(mm(size), 1.0);
    colours_.use(c);
    plptex(x, h_ - (baseline - 0.36 * size), 1, 0, just, plainText(s).c_str());
  }

  void drawPanel(const Panel& p, const Axis& xa, const Box& plot, double top) {
    PanelAxes axes{xa, yAxis(p)};
    const Axis& ya = axes.y;
    viewport(plot, xa, ya);
    plwidth(1);
    pllsty(1);
    // Bands first, so the grid and the lines stay visible over them.
    for (const Band& b : p.bands) {
      const double x0 = std::max(xa.toDrawing(b.x0), xa.lo), x1 = std::min(xa.toDrawing(b.x1), xa.hi);
      if (!(x1 > x0)) continue;
      const PLFLT xs[4] = {x0, x1, x1, x0}, ys[4] = {ya.lo, ya.lo, ya.hi, ya.hi};
      colours_.use(b.color);
      plfill(4, xs, ys);
    }
    colours_.use(kGridGrey);
    plbox("g", xa.step, 0, "g", ya.step, 0);
    // Left and bottom axes with outward ticks, then the tick labels in black.
    plslabelfunc(labelTick, &axes);
    plschr(mm(kTickText), 1.0);
    plsmaj(kTickLength * 25.4 / 72.0, 1.0);  // lengths in millimetres at the devices' 72 per inch
    colours_.use(kAxisGrey);
    plbox("bti", xa.step, 0, "bti", ya.step, 0);
    colours_.use(kBlack);
    plbox("noxi", xa.step, 0, "noxiv", ya.step, 0);  // x: tick positions without drawing the ticks
    plslabelfunc(nullptr, nullptr);

    pllsty(2);  // dashed
    plwidth(2);
    for (const RefLine& r : p.refLines) {
      const PLFLT xs[2] = {xa.lo, xa.hi}, ys[2] = {r.y, r.y};
      colours_.use(r.color);
      plline(2, xs, ys);
    }
    pllsty(1);
    for (const Series& s : p.series) drawSeries(s, xa, ya, plot);
    plwidth(1);

    overlay();
    text(plot.x0, top + 18, p.title, kBlack, 0, kPanelTitleText);
    text(plot.x0, plot.y0 - 8, p.yLabel, kAxisGrey, 0, kLabelText);
    text((plot.x0 + plot.x1) / 2, plot.y1 + 42, p.xLabel, kAxisGrey, 0.5, kLabelText);

    drawLegend(p, Box{plot.x1 + kLegendGap, w_ - kRight, plot.y0, plot.y1});
  }

  void drawSeries(const Series& s, const Axis& xa, const Axis& ya, const Box& plot) {
    const std::size_t n = std::min(s.x.size(), s.y.size());
    std::vector<PLFLT> xs, ys;
    for (std::size_t i = 0; i < n; ++i) {
      const double x = xa.toDrawing(s.x[i]);
      if (s.step && i > 0) {  // along at the previous value, then up or down
        xs.push_back(x);
        ys.push_back(s.y[i - 1]);
      }
      xs.push_back(x);
      ys.push_back(s.y[i]);
    }
    colours_.use(s.color);
    plwidth(s.thickness);
    if (xs.size() > 1) plline(static_cast<PLINT>(xs.size()), xs.data(), ys.data());
    if (!s.markers) return;
    // Filled squares, 3 pixels plus half the line width from the point to each side (outlined
    // with a thin pen: PLplot's cairo fill also strokes the edge with the current width).
    plwidth(1);
    const int half = 3 + s.thickness / 2;  // whole pixels
    const double dx = half * (xa.hi - xa.lo) / plot.width(), dy = half * (ya.hi - ya.lo) / plot.height();
    for (std::size_t i = 0; i < n; ++i) {
      const double x = xa.toDrawing(s.x[i]), y = s.y[i];
      const PLFLT sx[4] = {x - dx, x + dx, x + dx, x - dx}, sy[4] = {y - dy, y - dy, y + dy, y + dy};
      plfill(4, sx, sy);
    }
  }

  // The legend in its own viewport `area` right of the plot area, at its top left.
  void drawLegend(const Panel& p, const Box& area) {
    std::vector<std::string> names;
    std::vector<PLINT> opts, textColours, lineColours, lineStyles;
    std::vector<PLFLT> lineWidths;
    std::vector<PLINT> boxColours, boxPatterns;
    std::vector<PLFLT> boxScales, boxLineWidths;
    const auto add = [&](const std::string& name, Rgb colour, PLINT style, bool box) {
      names.push_back(plainText(name));
      opts.push_back(box ? PL_LEGEND_COLOR_BOX : PL_LEGEND_LINE);
      textColours.push_back(colours_.slot(kBlack));
      lineColours.push_back(colours_.slot(colour));
      lineStyles.push_back(style);
      lineWidths.push_back(3);
      boxColours.push_back(colours_.slot(colour));
      boxPatterns.push_back(0);
      boxScales.push_back(0.8);
      boxLineWidths.push_back(1);
    };
    for (const Series& s : p.series)
      if (!s.name.empty()) add(s.name, s.color, 1, false);
    for (const RefLine& r : p.refLines)
      if (!r.name.empty()) add(r.name, r.color, 2, false);
    bool anyBox = false;
    for (const Band& b : p.bands) {
      if (b.name.empty() || std::find(names.begin(), names.end(), plainText(b.name)) != names.end()) continue;
      add(b.name, b.color, 1, true);
      anyBox = true;
    }
    if (names.empty()) return;
    std::vector<const char*> texts;
    texts.reserve(names.size());
    for (const std::string& n : names) texts.push_back(n.c_str());
    plvpor(area.x0 / w_, area.x1 / w_, 1.0 - area.y1 / h_, 1.0 - area.y0 / h_);
    plwind(0, 1, 0, 1);
    plschr(mm(kLabelText), 1.0);
    PLFLT width = 0, height = 0;
    pllegend(&width, &height, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX,
             PL_POSITION_LEFT | PL_POSITION_TOP | PL_POSITION_INSIDE, 0, 0, kLegendSample / area.width(),
             colours_.slot(kWhite), colours_.slot(kAxisGrey), 1, 0, 0, static_cast<PLINT>(names.size()), opts.data(),
             kLegendTextOffset, 1.0, kLegendRowSpacing, 0, textColours.data(), texts.data(),
             anyBox ? boxColours.data() : nullptr, anyBox ? boxPatterns.data() : nullptr,
             anyBox ? boxScales.data() : nullptr, anyBox ? boxLineWidths.data() : nullptr, lineColours.data(),
             lineStyles.data(), lineWidths.data(), nullptr, nullptr, nullptr, nullptr);
  }

  const Figure& fig_;
  double w_, h_;
  Colours colours_;
};

}  // namespace

int figureHeight(const Figure& fig) {
  const int title = fig.title.empty() ? 0 : kFigureTitle;
  return title + fig.panelHeight * static_cast<int>(std::max<std::size_t>(fig.panels.size(), 1));
}

void drawChart(const Figure& fig) {
  Drawer(fig).draw();
}

}  // namespace vbim::plots
