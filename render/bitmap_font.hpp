// Text in pictures (the contact sheet's times, states and legend): a 5x7 bitmap font of our own
// for printable ASCII, drawn pixel for pixel without anti-aliasing. Built in rather than a TrueType
// font through OpenImageIO's render_text: the picture's bytes then depend on nothing installed
// (FreeType's anti-aliased glyphs change with the font's and FreeType's versions), and 5x7 pixels
// stay legible on a 200-pixel thumbnail (docs/render.md, "Contact sheet").
#pragma once

#include <cstdint>
#include <string_view>

#include "runtime/image.hpp"

namespace vbim::render {

// A glyph's pixels, and the step to the next character and to the next line, at scale 1.
inline constexpr int kGlyphWidth = 5, kGlyphHeight = 7, kGlyphAdvance = 6, kTextLineHeight = 10;

// Pixels `text` covers across at `scale` (each font pixel scale x scale image pixels).
int textWidth(std::string_view text, int scale = 1);

// Draws `text` with its top left corner at (x, y) in colour `rgb` (alpha 0x80, as the sheet's other
// pixels), clipped to the image. Throws RenderError naming the character for one outside
// printable ASCII (32 to 126).
void drawText(Rgba8Image& image, int x, int y, std::string_view text, const std::uint8_t rgb[3], int scale = 1);

}  // namespace vbim::render
