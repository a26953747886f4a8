// cairo's process-wide SVG ids are renumbered in order of first appearance.
#include <gtest/gtest.h>

#include "plots/svg_ids.hpp"

namespace {

using vbim::plots::renumberCairoIds;

TEST(PlotSvgIds, SurfaceAndImageIdsCountFromOne) {
  EXPECT_EQ(renumberCairoIds(R"(<g id="surface79"><use xlink:href="#image12"/><g id="surface80"></g>)"
                             R"(<use xlink:href="#surface79"/><image id="image12"/>)"),
            R"(<g id="surface1"><use xlink:href="#image1"/><g id="surface2"></g>)"
            R"(<use xlink:href="#surface1"/><image id="image1"/>)");
}

TEST(PlotSvgIds, OtherTextIsUntouched) {
  const std::string svg = R"(<symbol id="glyph0-1"/><clipPath id="clip1"/><g id="surface">"surfaces" #image)";
  EXPECT_EQ(renumberCairoIds(svg), svg);
}

}  // namespace
