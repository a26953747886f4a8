// The contact sheet explains itself: every tile carries its simulated time and state (and the
// drive's faults in its interval) as text, and a legend under the strips names every colour used
// (issue #33). Text comes from the built-in bitmap font, the same pixels on every machine.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "render/bitmap_font.hpp"
#include "render/contact_sheet.hpp"
#include "render/error.hpp"

namespace vbim::render {
namespace {

constexpr std::uint8_t kText[3] = {220, 220, 220};

Rgba8Image solid(int w, int h, std::uint8_t v) {
  Rgba8Image img(w, h);
  std::fill(img.pixels.begin(), img.pixels.end(), v);
  return img;
}

// Pixels of exactly `rgb` in rows [y0, y1) of `img`.
std::size_t countColour(const Rgba8Image& img, int y0, int y1, const std::array<std::uint8_t, 3>& rgb) {
  std::size_t n = 0;
  for (int y = std::max(0, y0); y < std::min(img.height, y1); ++y) {
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* p = img.row(y) + static_cast<std::ptrdiff_t>(x) * 4;
      n += p[0] == rgb[0] && p[1] == rgb[1] && p[2] == rgb[2];
    }
  }
  return n;
}

// The text pixels of `text` drawn at (x, y) are exactly where the font puts them.
void expectText(const Rgba8Image& sheet, int x, int y, const std::string& text, const std::uint8_t rgb[3]) {
  Rgba8Image expected = solid(sheet.width, sheet.height, 0);
  drawText(expected, x, y, text, rgb);
  for (int yy = y; yy < y + kGlyphHeight; ++yy) {
    for (int xx = x; xx < x + textWidth(text); ++xx) {
      const std::uint8_t* e = expected.row(yy) + static_cast<std::ptrdiff_t>(xx) * 4;
      const std::uint8_t* s = sheet.row(yy) + static_cast<std::ptrdiff_t>(xx) * 4;
      const bool ink = e[3] != 0;
      EXPECT_EQ(ink, s[0] == rgb[0] && s[1] == rgb[1] && s[2] == rgb[2])
          << "'" << text << "' at (" << xx << ", " << yy << ")";
    }
  }
}

TEST(BitmapFont, GlyphsAreDrawnPixelForPixelAndOnlyPrintableAscii) {
  Rgba8Image img = solid(12, 7, 0);
  const std::uint8_t white[3] = {255, 255, 255};
  drawText(img, 0, 0, "1.", white);
  // '1': ..#.. on the top row; '.': .##.. on the bottom two rows, from x = 6.
  const auto ink = [&](int x, int y) { return img.row(y)[x * 4] == 255; };
  EXPECT_FALSE(ink(1, 0));
  EXPECT_TRUE(ink(2, 0));
  EXPECT_FALSE(ink(3, 0));
  EXPECT_TRUE(ink(6 + 1, 6));
  EXPECT_TRUE(ink(6 + 2, 6));
  EXPECT_FALSE(ink(6 + 2, 4));
  EXPECT_EQ(textWidth("1."), 11);
  EXPECT_EQ(textWidth("1.", 2), 22);
  EXPECT_THROW(drawText(img, 0, 0, "t\xc2\xb0", white), RenderError);
  drawText(img, -3, -2, "clipped, not an error", white);
}

TEST(ContactSheet, TilesCarryTimeAndStateAndALegendNamesEveryColour) {
  std::vector<SheetTile> tiles;
  tiles.push_back(SheetTile{0, 0.0, solid(120, 54, 40), Moment::OnTime, {}});
  tiles.push_back(SheetTile{60, 1.0, solid(120, 54, 40), Moment::Late, {"stall"}});
  tiles.push_back(SheetTile{120, 12.5, solid(120, 54, 40), Moment::CatchUp, {}});
  SheetRun run;
  run.states.assign(180, Moment::OnTime);
  for (int v = 30; v < 90; ++v) run.states[v] = Moment::Late;
  run.seconds = 3.0;
  run.faults = {{"stall", 0.5, 1.5}, {"read error", 2.0, 2.2}};
  const int thumb = 120;
  const Rgba8Image sheet = contactSheet(tiles, run, 3, thumb);

  // Under each thumbnail (54 pixels high, a 3-pixel border): its time, then its state.
  const int labelY = 4 + 54 + 6 + 2, cellW = thumb + 6 + 4;
  const std::uint8_t red[3] = {220, 20, 20}, orange[3] = {255, 150, 0};
  expectText(sheet, 4, labelY, "t=0.0 s", kText);
  expectText(sheet, 4 + textWidth("t=0.0 s  ") + 1, labelY, "on time", kText);
  expectText(sheet, 4 + cellW, labelY, "t=1.0 s", kText);
  expectText(sheet, 4 + cellW + textWidth("t=1.0 s  ") + 1, labelY, "late", red);
  std::uint8_t stall[3];
  faultColour("stall", stall);
  expectText(sheet, 4 + cellW, labelY + kTextLineHeight, "drive: stall", stall);
  expectText(sheet, 4 + 2 * cellW + textWidth("t=12.5 s  ") + 1, labelY, "catch-up", orange);

  // Below the grid and the strips: a legend with a swatch (12 x 7) of every colour used.
  const int gridBottom = 4 + (54 + 6 + 2 * kTextLineHeight + 2 + 4);
  const int legendTop = gridBottom + 14 + 2 + 8 + 2 + kTextLineHeight + 4;
  std::uint8_t readError[3];
  faultColour("read error", readError);
  for (const std::array<std::uint8_t, 3> c :
       {std::array<std::uint8_t, 3>{90, 90, 90}, std::array<std::uint8_t, 3>{220, 20, 20},
        std::array<std::uint8_t, 3>{255, 150, 0}, std::array<std::uint8_t, 3>{stall[0], stall[1], stall[2]},
        std::array<std::uint8_t, 3>{readError[0], readError[1], readError[2]}}) {
    EXPECT_GE(countColour(sheet, legendTop, sheet.height, c), 12u * 7u)
        << int(c[0]) << "," << int(c[1]) << "," << int(c[2]) << " has no swatch in the legend";
  }
  expectText(sheet, 4 + 12 + 4, legendTop, "on time: the lightmap shows the frame due", kText);
  // The fault strip: the stall from 0.5 to 1.5 s of 3 s across the sheet's inner width.
  EXPECT_GT(countColour(sheet, gridBottom + 14 + 2, gridBottom + 14 + 2 + 8, {stall[0], stall[1], stall[2]}),
            8u * ((sheet.width - 8) / 3 - 2));
  // The same tiles give the same bytes.
  EXPECT_EQ(contactSheet(tiles, run, 3, thumb).pixels, sheet.pixels);
}

// A tile before the first frame has arrived (the GS shows nothing: a black picture) says "waiting"
// in its own colour, with a legend entry; a sheet with no such moment has no such entry.
TEST(ContactSheet, ATileBeforeTheFirstFrameIsWaitingNotOnTime) {
  const std::array<std::uint8_t, 3> green{70, 170, 80};
  std::vector<SheetTile> tiles;
  tiles.push_back(SheetTile{0, 0.0, solid(120, 54, 0), Moment::Waiting, {}});
  tiles.push_back(SheetTile{60, 1.0, solid(120, 54, 40), Moment::OnTime, {}});
  SheetRun run;
  run.states.assign(120, Moment::OnTime);
  for (int v = 0; v < 30; ++v) run.states[v] = Moment::Waiting;
  run.seconds = 2.0;
  const int thumb = 120;
  const Rgba8Image sheet = contactSheet(tiles, run, 2, thumb);
  EXPECT_STREQ(toString(Moment::Waiting), "waiting");

  const int labelY = 4 + 54 + 6 + 2, cellW = thumb + 6 + 4;
  expectText(sheet, 4, labelY, "t=0.0 s", kText);
  expectText(sheet, 4 + textWidth("t=0.0 s  ") + 1, labelY, "waiting", green.data());
  expectText(sheet, 4 + cellW + textWidth("t=1.0 s  ") + 1, labelY, "on time", kText);
  // The first tile's border is green, the second's grey.
  const std::uint8_t* first = sheet.row(4 + 1) + (4 + 1) * 4;
  const std::uint8_t* second = sheet.row(4 + 1) + (4 + cellW + 1) * 4;
  EXPECT_EQ((std::array<std::uint8_t, 3>{first[0], first[1], first[2]}), green);
  EXPECT_EQ((std::array<std::uint8_t, 3>{second[0], second[1], second[2]}), (std::array<std::uint8_t, 3>{90, 90, 90}));
  // The strip's first quarter (30 of 120 vsyncs) is green; the legend has a swatch and says what it means.
  const int gridBottom = 4 + (54 + 6 + 2 * kTextLineHeight + 2 + 4);
  EXPECT_GE(countColour(sheet, gridBottom, gridBottom + 14, green), 14u * ((sheet.width - 8) / 4 - 2));
  const int legendTop = gridBottom + 14 + 2 + kTextLineHeight + 4;
  EXPECT_GE(countColour(sheet, legendTop, sheet.height, green), 12u * 7u);
  // The second entry, after "on time", wrapped as the legend flows (swatch 12, gap 4, entries 18 apart).
  const std::string waiting = "waiting: no frame yet, the GS shows nothing";
  int x = 4 + 12 + 4 + textWidth("on time: the lightmap shows the frame due") + 18, y = legendTop;
  if (x + 12 + 4 + textWidth(waiting) > sheet.width - 4) {
    x = 4;
    y += kTextLineHeight + 2;
  }
  expectText(sheet, x + 12 + 4, y, waiting, kText);

  // No waiting anywhere: no green at all.
  tiles[0].moment = Moment::OnTime;
  run.states.assign(120, Moment::OnTime);
  EXPECT_EQ(countColour(contactSheet(tiles, run, 2, thumb), 0, sheet.height, green), 0u);
}

}  // namespace
}  // namespace vbim::render
