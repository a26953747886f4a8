#include "render/contact_sheet.hpp"

#include <algorithm>

namespace vbim::render {

namespace {

constexpr int kBorder = 3, kGap = 4, kStrip = 14;

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
  static const std::uint8_t onTime[3] = {90, 90, 90}, catchUp[3] = {255, 150, 0}, stall[3] = {220, 20, 20};
  return m == Moment::Stall ? stall : m == Moment::CatchUp ? catchUp : onTime;
}

}  // namespace

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

Rgba8Image contactSheet(const std::vector<SheetTile>& tiles, const std::vector<Moment>& states, int columns,
                        int thumbWidth) {
  columns = std::max(1, std::min(columns, static_cast<int>(std::max<std::size_t>(1, tiles.size()))));
  const int thumbHeight =
      tiles.empty() ? thumbWidth * 9 / 16
                    : std::max(1, tiles.front().picture.height * thumbWidth / std::max(1, tiles.front().picture.width));
  const int rows = static_cast<int>((tiles.size() + static_cast<std::size_t>(columns) - 1) / columns);
  const int cellW = thumbWidth + 2 * kBorder + kGap, cellH = thumbHeight + 2 * kBorder + kGap;
  const int width = columns * cellW + kGap;
  const int height = rows * cellH + kGap + (states.empty() ? 0 : kStrip + kGap);
  Rgba8Image sheet(width, height);
  const std::uint8_t background[3] = {24, 24, 24};
  fill(sheet, 0, 0, width, height, background);
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const int cx = kGap + static_cast<int>(i % columns) * cellW, cy = kGap + static_cast<int>(i / columns) * cellH;
    fill(sheet, cx, cy, thumbWidth + 2 * kBorder, thumbHeight + 2 * kBorder, colour(tiles[i].moment));
    const Rgba8Image thumb = downscale(tiles[i].picture, thumbWidth);
    for (int y = 0; y < std::min(thumb.height, thumbHeight); ++y) {
      std::copy_n(thumb.row(y), static_cast<std::size_t>(thumb.width) * 4,
                  sheet.row(cy + kBorder + y) + static_cast<std::ptrdiff_t>(cx + kBorder) * 4);
    }
  }
  if (!states.empty()) {
    const int y0 = rows * cellH + kGap, w = width - 2 * kGap;
    const auto n = static_cast<std::int64_t>(states.size());
    for (int x = 0; x < w; ++x) {
      const std::int64_t v0 = x * n / w, v1 = std::max(v0 + 1, (x + 1) * n / w);
      Moment worst = Moment::OnTime;
      for (std::int64_t v = v0; v < v1 && v < n; ++v) worst = std::max(worst, states[static_cast<std::size_t>(v)]);
      fill(sheet, kGap + x, y0, 1, kStrip, colour(worst));
    }
    const std::uint8_t white[3] = {255, 255, 255};
    for (const SheetTile& t : tiles) {
      const int x = static_cast<int>(t.vsync * w / n);
      fill(sheet, kGap + x, y0, 1, kStrip / 2, white);
    }
  }
  return sheet;
}

}  // namespace vbim::render
