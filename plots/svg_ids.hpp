// cairo's SVG writer names each drawing surface and image after a counter that runs over the whole
// process (`<g id="surface79">`, cairo-svg-surface.c: the surface's unique id), so the same figure
// drawn twice in one process gives different bytes. Renumbering those ids in order of first
// appearance makes the SVG depend on the figure only.
#pragma once

#include <string>
#include <string_view>

namespace vbim::plots {

// Replaces every `surface<N>` and `image<N>` that follows `"` or `#` (an id or a reference to one)
// with `surface<k>` / `image<k>`, k counting from 1 per prefix in order of first appearance.
std::string renumberCairoIds(std::string_view svg);

}  // namespace vbim::plots
