#include "render/contact_sheet.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>

#include "render/bitmap_font.hpp"

namespace vbim::render {

namespace {

constexpr int kBorder = 3, kGap = 4, kStrip = 14, kFaultStrip = 8;
// Under each thumbnail: two lines of text (time and state; the drive's faults).
constexpr int kLabel = 2 * kTextLineHeight + 2;
// The legend needs this much across; a narrower grid is widened to it.
constexpr int kMinWidth = 420;

constexpr std::uint8_t kBackground[3] = {24, 24, 24}, kText[3] = {220, 220, 220}, kWhite[3] = {255, 255, 255},
                       kFaultGround[3] = {48, 48, 48};

void fill(Rgba8Image& img, int x0, int y0, int w, int h, const std::uint8_t rgb[3]) {
  for (int y = std::max(0, y0); y < std::min(img.height, y0 + h); ++y) {
    for (int x = std::max(0, x0); x < std::min(img.width, x0 + w); ++x) {
      std::uint8_t* p = img.row(y) + static_cast<std::ptrdiff_t>(x) * 4;
      p[0] = rgb[0];
      p[1] = rgb[1];
      p[2] = rgb[2];
      p[3] = 0x80;
    }
  }
}

const std::uint8_t* colour(Moment m) {
  static const std::uint8_t onTime[3] = {90, 90, 90}, waiting[3] = {70, 170, 80}, catchUp[3] = {255, 150, 0},
                            late[3] = {220, 20, 20};
  switch (m) {
    case Moment::OnTime:
      return onTime;
    case Moment::Waiting:
      return waiting;
    case Moment::CatchUp:
      return catchUp;
    case Moment::Late:
      return late;
  }
  return onTime;
}

// What each colour of the sheet means, as the legend says it.
const char* meaning(Moment m) {
  switch (m) {
    case Moment::OnTime:
      return "on time: the lightmap shows the frame due";
    case Moment::Waiting:
      return "waiting: no frame yet, the GS shows nothing";
    case Moment::CatchUp:
      return "catch-up: blending toward a frame that came late";
    case Moment::Late:
      return "late: the frame due has not arrived (lightmap behind)";
  }
  return "";
}

std::string faultMeaning(const std::string& kind) {
  if (kind == "stall") return "stall: the drive stood still (fault plan)";
  if (kind == "read error") return "read error: the drive retried a sector";
  if (kind == "contention") return "contention: another client shared the drive";
  if (kind == "seek away") return "seek away: the drive read another file";
  if (kind == "random stalls") return "random stalls: seeded stalls may strike";
  if (kind == "random errors") return "random errors: seeded sector errors may strike";
  return kind + ": a drive fault";
}

// Text cut to `width` pixels.
std::string fitted(const std::string& s, int width) {
  const auto chars = static_cast<std::size_t>(std::max(0, (width + 1) / kGlyphAdvance));
  return s.size() <= chars ? s : s.substr(0, chars);
}

std::string timeLabel(double seconds) {
  char b[48];
  std::snprintf(b, sizeof b, "t=%.1f s", seconds);
  return b;
}

// The legend: a swatch and its meaning per entry, flowing left to right and wrapping at `width`.
// Returns the height used.
int legend(Rgba8Image* sheet, int x0, int y0, int width,
           const std::vector<std::pair<std::array<std::uint8_t, 3>, std::string>>& entries) {
  constexpr int kSwatch = 12, kEntryGap = 18;
  int x = x0, y = y0;
  for (const auto& [rgb, text] : entries) {
    const int w = kSwatch + 4 + textWidth(text);
    if (x > x0 && x + w > x0 + width) {
      x = x0;
      y += kTextLineHeight + 2;
    }
    if (sheet != nullptr) {
      fill(*sheet, x, y, kSwatch, kGlyphHeight, rgb.data());
      drawText(*sheet, x + kSwatch + 4, y, fitted(text, x0 + width - x - kSwatch - 4), kText);
    }
    x += w + kEntryGap;
  }
  return y + kTextLineHeight - y0;
}

}  // namespace

const char* toString(Moment m) {
  switch (m) {
    case Moment::OnTime:
      return "on time";
    case Moment::Waiting:
      return "waiting";
    case Moment::CatchUp:
      return "catch-up";
    case Moment::Late:
      return "late";
  }
  return "";
}

void faultColour(const std::string& kind, std::uint8_t rgb[3]) {
  static const struct {
    const char* kind;
    std::uint8_t rgb[3];
  } kColours[] = {{"stall", {170, 70, 230}},    {"read error", {60, 140, 255}},     {"contention", {240, 210, 40}},
                  {"seek away", {0, 190, 170}}, {"random stalls", {210, 130, 240}}, {"random errors", {130, 190, 255}}};
  for (const auto& c : kColours) {
    if (kind == c.kind) {
      std::copy_n(c.rgb, 3, rgb);
      return;
    }
  }
  std::fill_n(rgb, 3, std::uint8_t{160});
}

Rgba8Image downscale(const Rgba8Image& in, int width) {
  width = std::clamp(width, 1, in.width);
  const int height = std::max(1, static_cast<int>(static_cast<long long>(in.height) * width / in.width));
  Rgba8Image out(width, height);
  for (int y = 0; y < height; ++y) {
    const int sy0 = y * in.height / height, sy1 = std::max(sy0 + 1, (y + 1) * in.height / height);
    for (int x = 0; x < width; ++x) {
      const int sx0 = x * in.width / width, sx1 = std::max(sx0 + 1, (x + 1) * in.width / width);
      unsigned sum[3] = {0, 0, 0}, n = 0;
      for (int sy = sy0; sy < sy1; ++sy) {
        for (int sx = sx0; sx < sx1; ++sx) {
          const std::uint8_t* p = in.row(sy) + static_cast<std::ptrdiff_t>(sx) * 4;
          for (int c = 0; c < 3; ++c) sum[c] += p[c];
          ++n;
        }
      }
      std::uint8_t* o = out.row(y) + static_cast<std::ptrdiff_t>(x) * 4;
      for (int c = 0; c < 3; ++c) o[c] = static_cast<std::uint8_t>((sum[c] + n / 2) / n);
      o[3] = 0x80;
    }
  }
  return out;
}

Rgba8Image contactSheet(const std::vector<SheetTile>& tiles, const SheetRun& run, int columns, int thumbWidth) {
  columns = std::max(1, std::min(columns, static_cast<int>(std::max<std::size_t>(1, tiles.size()))));
  const int thumbHeight =
      tiles.empty() ? thumbWidth * 9 / 16
                    : std::max(1, tiles.front().picture.height * thumbWidth / std::max(1, tiles.front().picture.width));
  const int rows = static_cast<int>((tiles.size() + static_cast<std::size_t>(columns) - 1) / columns);
  const int cellW = thumbWidth + 2 * kBorder + kGap, cellH = thumbHeight + 2 * kBorder + kLabel + kGap;
  const int width = std::max(columns * cellW + kGap, kMinWidth);
  const int inner = width - 2 * kGap;

  // The legend: every colour the sheet uses (waiting only when a tile or the strip shows it: most
  // sheets start on a first frame), the fault kinds in order of first appearance.
  const bool waits =
      std::find(run.states.begin(), run.states.end(), Moment::Waiting) != run.states.end() ||
      std::any_of(tiles.begin(), tiles.end(), [](const SheetTile& t) { return t.moment == Moment::Waiting; });
  std::vector<std::pair<std::array<std::uint8_t, 3>, std::string>> entries;
  for (Moment m : {Moment::OnTime, Moment::Waiting, Moment::Late, Moment::CatchUp}) {
    if (m == Moment::Waiting && !waits) continue;
    const std::uint8_t* c = colour(m);
    entries.push_back({{c[0], c[1], c[2]}, meaning(m)});
  }
  if (!run.states.empty()) entries.push_back({{255, 255, 255}, "tick over the strip: a thumbnail's time"});
  std::vector<std::string> kinds;
  const auto note = [&kinds](const std::string& k) {
    if (std::find(kinds.begin(), kinds.end(), k) == kinds.end()) kinds.push_back(k);
  };
  for (const player::FaultSpan& f : run.faults) note(f.kind);
  for (const SheetTile& t : tiles) {
    for (const std::string& k : t.faults) note(k);
  }
  for (const std::string& k : kinds) {
    std::array<std::uint8_t, 3> c{};
    faultColour(k, c.data());
    entries.push_back({c, faultMeaning(k)});
  }

  const int stripsY = rows * cellH + kGap;
  const int stripsH = run.states.empty() ? 0
                                         : kStrip + (run.faults.empty() ? 0 : 2 + kFaultStrip) + 2 + kTextLineHeight +
                                               kGap;  // strips, then their time axis
  const int legendY = stripsY + stripsH;
  const int height = legendY + legend(nullptr, kGap, 0, inner, entries) + kGap;
  Rgba8Image sheet(width, height);
  fill(sheet, 0, 0, width, height, kBackground);

  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const SheetTile& t = tiles[i];
    const int cx = kGap + static_cast<int>(i % columns) * cellW, cy = kGap + static_cast<int>(i / columns) * cellH;
    fill(sheet, cx, cy, thumbWidth + 2 * kBorder, thumbHeight + 2 * kBorder, colour(t.moment));
    const Rgba8Image thumb = downscale(t.picture, thumbWidth);
    for (int y = 0; y < std::min(thumb.height, thumbHeight); ++y) {
      std::copy_n(thumb.row(y), static_cast<std::size_t>(thumb.width) * 4,
                  sheet.row(cy + kBorder + y) + static_cast<std::ptrdiff_t>(cx + kBorder) * 4);
    }
    // Time in grey, the state in its colour (grey reads as "on time" on the dark ground too).
    const int labelW = thumbWidth + 2 * kBorder, ly = cy + thumbHeight + 2 * kBorder + 2;
    const std::string time = timeLabel(t.timeS) + "  ";
    drawText(sheet, cx, ly, fitted(time, labelW), kText);
    const int stateX = cx + textWidth(time) + 1;
    const std::uint8_t* stateColour = t.moment == Moment::OnTime ? kText : colour(t.moment);
    drawText(sheet, stateX, ly, fitted(toString(t.moment), cx + labelW - stateX), stateColour);
    if (!t.faults.empty()) {
      std::string drive = "drive:";
      for (std::size_t k = 0; k < t.faults.size(); ++k) drive += (k == 0 ? " " : ", ") + t.faults[k];
      std::uint8_t c[3];
      faultColour(t.faults.front(), c);
      drawText(sheet, cx, ly + kTextLineHeight, fitted(drive, labelW), c);
    }
  }

  if (!run.states.empty()) {
    const int y0 = stripsY;
    const auto n = static_cast<std::int64_t>(run.states.size());
    for (int x = 0; x < inner; ++x) {
      const std::int64_t v0 = x * n / inner, v1 = std::max(v0 + 1, (x + 1) * n / inner);
      Moment worst = Moment::OnTime;
      for (std::int64_t v = v0; v < v1 && v < n; ++v) worst = std::max(worst, run.states[static_cast<std::size_t>(v)]);
      fill(sheet, kGap + x, y0, 1, kStrip, colour(worst));
    }
    for (const SheetTile& t : tiles) {
      const int x = static_cast<int>(t.vsync * inner / n);
      fill(sheet, kGap + x, y0, 1, kStrip / 2, kWhite);
    }
    int axisY = y0 + kStrip + 2;
    if (!run.faults.empty()) {
      fill(sheet, kGap, axisY, inner, kFaultStrip, kFaultGround);
      const double seconds = std::max(run.seconds, 1e-9);
      for (const player::FaultSpan& f : run.faults) {
        const int x0 = static_cast<int>(std::clamp(f.beginS / seconds, 0.0, 1.0) * inner);
        const int x1 = static_cast<int>(std::clamp(f.endS / seconds, 0.0, 1.0) * inner);
        std::uint8_t c[3];
        faultColour(f.kind, c);
        fill(sheet, kGap + std::min(x0, inner - 1), axisY, std::max(1, x1 - x0), kFaultStrip, c);
      }
      axisY += kFaultStrip + 2;
    }
    // The strips' time axis: its two ends.
    drawText(sheet, kGap, axisY, "0 s", kText);
    char end[48];
    std::snprintf(end, sizeof end, "%.1f s", run.seconds);
    drawText(sheet, kGap + inner - textWidth(end), axisY, end, kText);
  }
  legend(&sheet, kGap, legendY, inner, entries);
  return sheet;
}

}  // namespace vbim::render
