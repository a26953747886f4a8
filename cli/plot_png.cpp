#include "cli/plot_png.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

namespace vbim::cli::plot {

namespace {

constexpr Color kBlack{0.0f, 0.0f, 0.0f};
constexpr Color kGrid{0.88f, 0.88f, 0.88f};
constexpr Color kAxis{0.25f, 0.25f, 0.25f};
constexpr Color kWhite{1.0f, 1.0f, 1.0f};

// Plot area margins inside a panel, in pixels.
constexpr int kLeft = 78, kRight = 24, kTop = 44, kBottom = 52;
constexpr int kFigureTitle = 40;
constexpr int kFontSize = 14;

// The raster: RGB floats, lines and boxes drawn here directly (fast for thousands of segments);
// text goes through OIIO's render_text on an ImageBuf that wraps the same memory.
class Canvas {
 public:
  Canvas(int w, int h) : w_(w), h_(h), px_(static_cast<std::size_t>(w) * h * 3, 1.0f) {
    OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::FLOAT);
    buf_ = std::make_unique<OIIO::ImageBuf>(spec, px_.data());
  }
  void set(int x, int y, const Color& c) {
    if (x < 0 || y < 0 || x >= w_ || y >= h_) return;
    float* p = &px_[(static_cast<std::size_t>(y) * w_ + x) * 3];
    p[0] = c[0];
    p[1] = c[1];
    p[2] = c[2];
  }
  void line(int x0, int y0, int x1, int y1, const Color& c, int thickness = 1) {
    // Bresenham; a thick line is drawn again above and below (centred).
    for (int k = -(thickness - 1) / 2; k <= thickness / 2; ++k) {
      int ax = x0, ay = y0 + k;
      const int bx = x1, by = y1 + k;
      const int dx = std::abs(bx - ax), sx = ax < bx ? 1 : -1;
      const int dy = -std::abs(by - ay), sy = ay < by ? 1 : -1;
      int err = dx + dy;
      for (;;) {
        set(ax, ay, c);
        if (ax == bx && ay == by) break;
        const int e2 = 2 * err;
        if (e2 >= dy) {
          err += dy;
          ax += sx;
        }
        if (e2 <= dx) {
          err += dx;
          ay += sy;
        }
      }
    }
  }
  void box(int x0, int y0, int x1, int y1, const Color& c, bool fill) {
    if (fill) {
      for (int y = std::min(y0, y1); y <= std::max(y0, y1); ++y) line(x0, y, x1, y, c);
    } else {
      line(x0, y0, x1, y0, c);
      line(x1, y0, x1, y1, c);
      line(x1, y1, x0, y1, c);
      line(x0, y1, x0, y0, c);
    }
  }
  void dashedH(int x0, int x1, int y, const Color& c) {
    for (int x = x0; x <= x1; ++x) {
      if ((x - x0) % 10 < 6) {
        set(x, y, c);
        set(x, y + 1, c);
      }
    }
  }
  enum class Align { left, center, right };
  // Text with its baseline at y. Returns false without a font.
  bool text(int x, int y, const std::string& s, const Color& c, Align align = Align::left, int size = kFontSize) {
    if (s.empty() || font_.empty()) return !font_.empty();
    const auto ax = align == Align::left     ? OIIO::ImageBufAlgo::TextAlignX::Left
                    : align == Align::center ? OIIO::ImageBufAlgo::TextAlignX::Center
                                             : OIIO::ImageBufAlgo::TextAlignX::Right;
    return OIIO::ImageBufAlgo::render_text(*buf_, x, y, s, size, font_, {c.data(), 3}, ax,
                                           OIIO::ImageBufAlgo::TextAlignY::Baseline);
  }
  int textWidth(const std::string& s, int size = kFontSize) const {
    if (font_.empty()) return static_cast<int>(s.size()) * size / 2;
    const OIIO::ROI r = OIIO::ImageBufAlgo::text_size(s, size, font_);
    return r.defined() ? r.width() : static_cast<int>(s.size()) * size / 2;
  }
  bool findFont() {
    for (const char* f : {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "DejaVuSans", "DroidSans", ""}) {
      if (std::string(f).rfind('/', 0) == 0 && !std::filesystem::exists(f)) continue;
      if (OIIO::ImageBufAlgo::text_size("0", kFontSize, f).defined()) {
        font_ = f;
        if (font_.empty()) font_ = " ";  // OIIO's default font ("" is accepted by render_text)
        return true;
      }
    }
    return false;
  }
  void write(const std::filesystem::path& path) {
    if (!buf_->write(path.string(), OIIO::TypeDesc::UINT8, "png")) {
      throw std::runtime_error(path.string() + ": cannot write the plot: " + buf_->geterror());
    }
  }
  int width() const { return w_; }

 private:
  int w_, h_;
  std::vector<float> px_;
  std::unique_ptr<OIIO::ImageBuf> buf_;
  std::string font_;
};

std::string tickLabel(double v, double step) {
  char b[32];
  if (std::abs(v) < step * 1e-6) v = 0;
  if (step >= 1 || std::abs(step - std::round(step)) < 1e-9) {
    std::snprintf(b, sizeof b, "%.0f", v);
  } else {
    const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 1, 4);
    std::snprintf(b, sizeof b, "%.*f", decimals, v);
  }
  return b;
}

struct Range {
  double lo = 0, hi = 1;
};

std::vector<std::pair<std::string, Color>> legendItems(const Panel& p) {
  std::vector<std::pair<std::string, Color>> items;
  for (const Series& s : p.series)
    if (!s.name.empty()) items.emplace_back(s.name, s.color);
  for (const RefLine& r : p.refLines)
    if (!r.name.empty()) items.emplace_back(r.name, r.color);
  return items;
}

// The legend sits right of the plot area, so it never hides data; `legendW` is its width.
void drawPanel(Canvas& cv, const Panel& p, int top, int height, Range xr, int legendW) {
  const int x0 = kLeft, x1 = cv.width() - kRight - legendW;
  const int y0 = top + kTop, y1 = top + height - kBottom;
  auto fx = [&](double x) {
    double u = p.xLog2 ? (std::log2(x) - std::log2(xr.lo)) / (std::log2(xr.hi) - std::log2(xr.lo))
                       : (x - xr.lo) / (xr.hi - xr.lo);
    return x0 + static_cast<int>(std::lround(u * (x1 - x0)));
  };
  // y range: the data (and reference lines), 0 included when all are >= 0, a little headroom.
  double lo = 0, hi = 0;
  bool any = false;
  for (const Series& s : p.series) {
    for (double v : s.y) {
      lo = any ? std::min(lo, v) : v;
      hi = any ? std::max(hi, v) : v;
      any = true;
    }
  }
  for (const RefLine& r : p.refLines) {
    lo = any ? std::min(lo, r.y) : r.y;
    hi = any ? std::max(hi, r.y) : r.y;
    any = true;
  }
  if (lo >= 0) lo = 0;
  if (hi <= lo) hi = lo + 1;
  hi += (hi - lo) * 0.08;
  if (p.yMin) lo = *p.yMin;
  if (p.yMax) hi = *p.yMax;
  const std::vector<double> yt = niceTicks(lo, hi, 6);
  if (!yt.empty() && !p.yMax) hi = std::max(hi, yt.back());
  auto fy = [&](double y) { return y1 - static_cast<int>(std::lround((y - lo) / (hi - lo) * (y1 - y0))); };

  // Grid and ticks.
  const double ystep = yt.size() > 1 ? yt[1] - yt[0] : 1;
  for (double v : yt) {
    if (v < lo - 1e-9 || v > hi + 1e-9) continue;
    const int y = fy(v);
    cv.line(x0 + 1, y, x1, y, kGrid);
    cv.line(x0 - 5, y, x0, y, kAxis);
    cv.text(x0 - 8, y + 5, tickLabel(v, ystep), kBlack, Canvas::Align::right);
  }
  std::vector<double> xt;
  if (p.xLog2) {
    for (double v = std::exp2(std::floor(std::log2(xr.lo))); v <= xr.hi * 1.0001; v *= 2)
      if (v >= xr.lo * 0.9999) xt.push_back(v);
  } else {
    xt = niceTicks(xr.lo, xr.hi, 10);
  }
  const double xstep = xt.size() > 1 ? xt[1] - xt[0] : 1;
  for (double v : xt) {
    const int x = fx(v);
    if (x < x0 || x > x1) continue;
    cv.line(x, y0, x, y1 - 1, kGrid);
    cv.line(x, y1, x, y1 + 5, kAxis);
    cv.text(x, y1 + 20, tickLabel(v, p.xLog2 ? 1 : xstep), kBlack, Canvas::Align::center);
  }
  cv.line(x0, y0, x0, y1, kAxis);
  cv.line(x0, y1, x1, y1, kAxis);
  cv.text(x0, top + 18, p.title, kBlack, Canvas::Align::left, 16);
  cv.text(x0, y0 - 8, p.yLabel, kAxis, Canvas::Align::left, 13);
  cv.text((x0 + x1) / 2, y1 + 42, p.xLabel, kAxis, Canvas::Align::center, 13);

  // Reference lines, then the series.
  for (const RefLine& r : p.refLines) cv.dashedH(x0 + 1, x1, fy(r.y), r.color);
  for (const Series& s : p.series) {
    const std::size_t n = std::min(s.x.size(), s.y.size());
    for (std::size_t i = 0; i < n; ++i) {
      const int px = fx(s.x[i]), py = fy(s.y[i]);
      if (i > 0) {
        const int qx = fx(s.x[i - 1]), qy = fy(s.y[i - 1]);
        if (s.step) {
          cv.line(qx, qy, px, qy, s.color, s.thickness);
          cv.line(px, qy, px, py, s.color, s.thickness);
        } else {
          cv.line(qx, qy, px, py, s.color, s.thickness);
        }
      }
      const int m = 3 + s.thickness / 2;
      if (s.markers) cv.box(px - m, py - m, px + m, py + m, s.color, true);
    }
  }

  // Legend: right of the plot area.
  const auto items = legendItems(p);
  if (items.empty()) return;
  const int lw = legendW - 12, lh = static_cast<int>(items.size()) * 18 + 8;
  const int lx = x1 + 12, ly = y0;
  cv.box(lx, ly, lx + lw, ly + lh, kWhite, true);
  cv.box(lx, ly, lx + lw, ly + lh, kAxis, false);
  for (std::size_t i = 0; i < items.size(); ++i) {
    const int yy = ly + 14 + static_cast<int>(i) * 18;
    cv.box(lx + 8, yy - 6, lx + 30, yy - 3, items[i].second, true);
    cv.text(lx + 36, yy, items[i].first, kBlack, Canvas::Align::left, 13);
  }
}

}  // namespace

Color paletteColor(std::size_t i) {
  static constexpr std::array<Color, 8> k{{{0.00f, 0.45f, 0.70f},
                                           {0.90f, 0.62f, 0.00f},
                                           {0.00f, 0.62f, 0.45f},
                                           {0.84f, 0.37f, 0.00f},
                                           {0.80f, 0.47f, 0.65f},
                                           {0.34f, 0.71f, 0.91f},
                                           {0.45f, 0.45f, 0.45f},
                                           {0.20f, 0.20f, 0.20f}}};
  return k[i % k.size()];
}

std::vector<double> niceTicks(double lo, double hi, int target) {
  std::vector<double> t;
  if (!(hi > lo) || target < 1) return t;
  const double raw = (hi - lo) / target;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * mag;
    if (step >= raw) break;
  }
  const double first = std::ceil(lo / step - 1e-9) * step;
  for (double v = first; v <= hi + step * 1e-9 && t.size() < 100; v += step) t.push_back(v);
  return t;
}

bool writePng(const Figure& fig, const std::filesystem::path& path) {
  const int titleH = fig.title.empty() ? 0 : kFigureTitle;
  const int h = titleH + fig.panelHeight * static_cast<int>(std::max<std::size_t>(fig.panels.size(), 1));
  Canvas cv(fig.width, h);
  const bool font = cv.findFont();
  if (!fig.title.empty()) cv.text(fig.width / 2, 28, fig.title, kBlack, Canvas::Align::center, 18);
  // All panels share the x range of all their data.
  Range xr{0, 0};
  bool any = false;
  bool log2 = false;
  for (const Panel& p : fig.panels) {
    log2 = log2 || p.xLog2;
    for (const Series& s : p.series) {
      for (double v : s.x) {
        xr.lo = any ? std::min(xr.lo, v) : v;
        xr.hi = any ? std::max(xr.hi, v) : v;
        any = true;
      }
    }
  }
  if (log2) {
    xr.lo = std::max(xr.lo, 1e-9) / 1.25;
    xr.hi = std::max(xr.hi, xr.lo * 2) * 1.25;
  } else if (xr.hi <= xr.lo) {
    xr.hi = xr.lo + 1;
  }
  int legendW = 0;  // the same for every panel, so their x axes line up
  for (const Panel& p : fig.panels) {
    for (const auto& it : legendItems(p)) legendW = std::max(legendW, cv.textWidth(it.first, 13) + 44 + 12);
  }
  legendW = std::min(legendW, fig.width / 3);
  for (std::size_t i = 0; i < fig.panels.size(); ++i)
    drawPanel(cv, fig.panels[i], titleH + static_cast<int>(i) * fig.panelHeight, fig.panelHeight, xr, legendW);
  cv.write(path);
  return font;
}

}  // namespace vbim::cli::plot
