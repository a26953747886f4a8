#include <gtest/gtest.h>

#include "render/error.hpp"
#include "render/terrain_mesh.hpp"
#include "render_test_scene.hpp"

namespace vbim::render {
namespace {

TEST(TerrainMesh, LevelsHalveTheTrianglesAndFarPatchesAreCoarser) {
  const lighting::Terrain t = test::smallTerrain();
  const TerrainMesh m = buildTerrainMesh(t, 16);
  ASSERT_EQ(m.levels, 5);            // steps 1, 2, 4, 8, 16
  EXPECT_EQ(m.patches.size(), 16u);  // 63 cells -> 4 x 4 patches of 16
  // Level 0: 16 x 16 quads + 4 edges x 16 skirt quads x 2 sides, 2 triangles each.
  EXPECT_EQ(m.indices[0].size(), (16u * 16 * 2 + 4 * 16 * 2 * 2) * 3);
  EXPECT_EQ(m.indices[4].size(), (1u * 2 + 4 * 1 * 2 * 2) * 3);
  for (const auto& level : m.indices)
    for (std::uint32_t i : level) ASSERT_LT(i, static_cast<std::uint32_t>(m.verticesPerPatch()));
  const float eye[3] = {0, 500, 0};
  const std::vector<int> lv = selectLevels(m, eye, 100, nullptr);
  EXPECT_EQ(lv.front(), 0);          // the patch under the eye
  EXPECT_GT(lv.back(), lv.front());  // the far corner
  EXPECT_FLOAT_EQ(terrainHeightAt(t, 0, 0), static_cast<float>(t.metresAt(0, 0)));
}

TEST(TerrainMesh, RejectsBadPatchSizes) {
  const lighting::Terrain t = test::smallTerrain();
  EXPECT_THROW(buildTerrainMesh(t, 12), RenderError);
  EXPECT_THROW(buildTerrainMesh(t, 1), RenderError);
}

}  // namespace
}  // namespace vbim::render
