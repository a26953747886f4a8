// The terrain as GL geometry with a level of detail: the heightfield is cut into square patches of
// `patchCells` cells; each patch can be drawn at steps of 1, 2, 4, ... cells, chosen per patch by its
// distance from the camera, so a far mountain costs a few dozen triangles instead of two thousand
// (vertex work is llvmpipe's single-threaded part: docs/dependencies.md#llvmpipe-threads). Every patch
// shares one index list per level (drawn with a base vertex) and carries a skirt hanging below its
// edges that hides the cracks between neighbours drawn at different levels.
//
// World axes: x = east (+column), y = up, z = south (+row), metres; texel (c, r) sits at
// (c * cellSize, height, r * cellSize).
#pragma once

#include <cstdint>
#include <vector>

#include "lighting/terrain.hpp"

namespace vbim::render {

struct TerrainPatch {
  float centre[3] = {0, 0, 0};
  float radius = 0;  // bounding sphere, skirt included
  std::int32_t baseVertex = 0;
};

struct TerrainMesh {
  int patchCells = 32;                              // cells per patch side (a power of two)
  int levels = 0;                                   // step of level k = 2^k cells
  std::vector<float> positions;                     // xyz per vertex
  std::vector<std::vector<std::uint32_t>> indices;  // per level, local to a patch (GL_UNSIGNED_INT)
  std::vector<TerrainPatch> patches;
  float extentX = 0, extentZ = 0;  // metres covered: (width - 1) * cellSize, ...
  float minHeight = 0, maxHeight = 0;

  int verticesPerPatch() const { return (patchCells + 1) * (patchCells + 1) + 4 * (patchCells + 1); }
};

// `patchCells` must be a power of two in [2, 256]. Throws RenderError on an empty terrain.
TerrainMesh buildTerrainMesh(const lighting::Terrain& terrain, int patchCells = 32);

// Which level to draw each patch at: level k while the distance from `eye` to the patch's sphere
// is below lodDistance * 2^k (lodDistance <= 0: always level 0). Patches outside the view frustum
// (`viewProj`, column-major 4x4, null: no culling) get -1.
std::vector<int> selectLevels(const TerrainMesh& mesh, const float eye[3], float lodDistance, const float* viewProj);

// Height in metres at world (x, z), bilinear between texel centres, clamped to the map.
float terrainHeightAt(const lighting::Terrain& terrain, float x, float z);

}  // namespace vbim::render
