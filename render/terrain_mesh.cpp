#include "render/terrain_mesh.hpp"

#include <algorithm>
#include <cmath>

#include "render/error.hpp"

namespace vbim::render {

namespace {

// Local vertex numbering of a patch: the (n+1)^2 grid row by row, then the skirt vertices under
// the top, bottom, left and right edges, n+1 each.
struct PatchLayout {
  int n;
  std::uint32_t grid(int r, int c) const { return static_cast<std::uint32_t>(r * (n + 1) + c); }
  std::uint32_t skirt(int edge, int k) const {
    return static_cast<std::uint32_t>((n + 1) * (n + 1) + edge * (n + 1) + k);
  }
};

void quad(std::vector<std::uint32_t>& out, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
  // a b / c d, counter-clockwise seen from above (y up, z south): a, c, b and b, c, d.
  out.insert(out.end(), {a, c, b, b, c, d});
}

std::vector<std::uint32_t> levelIndices(const PatchLayout& p, int step) {
  std::vector<std::uint32_t> idx;
  const int n = p.n;
  for (int r = 0; r < n; r += step) {
    for (int c = 0; c < n; c += step)
      quad(idx, p.grid(r, c), p.grid(r, c + step), p.grid(r + step, c), p.grid(r + step, c + step));
  }
  // Skirts: a vertical strip under each edge, both windings so it shows from either side.
  for (int k = 0; k < n; k += step) {
    const std::uint32_t strips[4][4] = {
        {p.grid(0, k), p.grid(0, k + step), p.skirt(0, k), p.skirt(0, k + step)},
        {p.grid(n, k), p.grid(n, k + step), p.skirt(1, k), p.skirt(1, k + step)},
        {p.grid(k, 0), p.grid(k + step, 0), p.skirt(2, k), p.skirt(2, k + step)},
        {p.grid(k, n), p.grid(k + step, n), p.skirt(3, k), p.skirt(3, k + step)},
    };
    for (const auto& s : strips) {
      quad(idx, s[0], s[1], s[2], s[3]);
      quad(idx, s[1], s[0], s[3], s[2]);
    }
  }
  return idx;
}

}  // namespace

TerrainMesh buildTerrainMesh(const lighting::Terrain& t, int patchCells) {
  if (t.width < 2 || t.height < 2) throw RenderError("terrain mesh: the heightfield needs at least 2x2 samples");
  if (patchCells < 2 || patchCells > 256 || (patchCells & (patchCells - 1)) != 0) {
    throw RenderError("terrain mesh: patch size must be a power of two in 2..256 cells");
  }
  TerrainMesh m;
  m.patchCells = patchCells;
  const int n = patchCells;
  const PatchLayout layout{n};
  for (int step = 1; step <= n; step *= 2) m.indices.push_back(levelIndices(layout, step));
  m.levels = static_cast<int>(m.indices.size());
  const float cell = static_cast<float>(t.cellSize);
  m.extentX = static_cast<float>(t.width - 1) * cell;
  m.extentZ = static_cast<float>(t.height - 1) * cell;
  m.minHeight = m.maxHeight = static_cast<float>(t.metresAt(0, 0));
  for (int y = 0; y < t.height; ++y) {
    for (int x = 0; x < t.width; ++x) {
      const float h = static_cast<float>(t.metresAt(x, y));
      m.minHeight = std::min(m.minHeight, h);
      m.maxHeight = std::max(m.maxHeight, h);
    }
  }
  const int px = (t.width - 1 + n - 1) / n, pz = (t.height - 1 + n - 1) / n;
  m.positions.reserve(static_cast<std::size_t>(px) * pz * m.verticesPerPatch() * 3);
  for (int prow = 0; prow < pz; ++prow) {
    for (int pcol = 0; pcol < px; ++pcol) {
      TerrainPatch patch;
      patch.baseVertex = static_cast<std::int32_t>(m.positions.size() / 3);
      const int c0 = pcol * n, r0 = prow * n;
      // Samples past the map's edge repeat the last row/column (zero-area triangles).
      auto sample = [&](int r, int c, float& x, float& y, float& z) {
        const int cc = std::min(c0 + c, t.width - 1), rr = std::min(r0 + r, t.height - 1);
        x = static_cast<float>(cc) * cell;
        z = static_cast<float>(rr) * cell;
        y = static_cast<float>(t.metresAt(cc, rr));
      };
      float lo = 1e30f, hi = -1e30f;
      for (int r = 0; r <= n; ++r) {
        for (int c = 0; c <= n; ++c) {
          float x, y, z;
          sample(r, c, x, y, z);
          m.positions.insert(m.positions.end(), {x, y, z});
          lo = std::min(lo, y);
          hi = std::max(hi, y);
        }
      }
      // Deep enough to cover any neighbour's coarser edge: the patch's own relief plus two cells.
      const float skirt = (hi - lo) + 2 * cell;
      for (int edge = 0; edge < 4; ++edge) {
        for (int k = 0; k <= n; ++k) {
          const int r = edge == 0 ? 0 : edge == 1 ? n : k;
          const int c = edge == 2 ? 0 : edge == 3 ? n : k;
          float x, y, z;
          sample(r, c, x, y, z);
          m.positions.insert(m.positions.end(), {x, y - skirt, z});
        }
      }
      const float x0 = static_cast<float>(c0) * cell, x1 = static_cast<float>(std::min(c0 + n, t.width - 1)) * cell;
      const float z0 = static_cast<float>(r0) * cell, z1 = static_cast<float>(std::min(r0 + n, t.height - 1)) * cell;
      patch.centre[0] = (x0 + x1) / 2;
      patch.centre[1] = (lo - skirt + hi) / 2;
      patch.centre[2] = (z0 + z1) / 2;
      const float dx = (x1 - x0) / 2, dy = (hi - lo + skirt) / 2, dz = (z1 - z0) / 2;
      patch.radius = std::sqrt(dx * dx + dy * dy + dz * dz);
      m.patches.push_back(patch);
    }
  }
  return m;
}

std::vector<int> selectLevels(const TerrainMesh& m, const float eye[3], float lodDistance, const float* vp) {
  std::vector<int> out(m.patches.size(), 0);
  // Frustum planes from the rows of the column-major view-projection matrix (Gribb & Hartmann).
  float planes[6][4];
  if (vp != nullptr) {
    auto row = [vp](int i, int j) { return vp[j * 4 + i]; };
    for (int p = 0; p < 6; ++p) {
      const int axis = p / 2;
      const float sign = (p % 2 == 0) ? 1.0f : -1.0f;
      for (int j = 0; j < 4; ++j) planes[p][j] = row(3, j) + sign * row(axis, j);
      const float len =
          std::sqrt(planes[p][0] * planes[p][0] + planes[p][1] * planes[p][1] + planes[p][2] * planes[p][2]);
      for (float& v : planes[p]) v /= len;
    }
  }
  for (std::size_t i = 0; i < m.patches.size(); ++i) {
    const TerrainPatch& p = m.patches[i];
    if (vp != nullptr) {
      bool outside = false;
      for (const auto& pl : planes) {
        if (pl[0] * p.centre[0] + pl[1] * p.centre[1] + pl[2] * p.centre[2] + pl[3] < -p.radius) outside = true;
      }
      if (outside) {
        out[i] = -1;
        continue;
      }
    }
    if (lodDistance <= 0) continue;
    const float dx = p.centre[0] - eye[0], dy = p.centre[1] - eye[1], dz = p.centre[2] - eye[2];
    const float d = std::max(0.0f, std::sqrt(dx * dx + dy * dy + dz * dz) - p.radius);
    int level = 0;
    while (level + 1 < m.levels && d >= lodDistance * static_cast<float>(1 << level)) ++level;
    out[i] = level;
  }
  return out;
}

float terrainHeightAt(const lighting::Terrain& t, float x, float z) {
  const float cx = std::clamp(x / static_cast<float>(t.cellSize), 0.0f, static_cast<float>(t.width - 1));
  const float cz = std::clamp(z / static_cast<float>(t.cellSize), 0.0f, static_cast<float>(t.height - 1));
  const int x0 = std::min(static_cast<int>(cx), t.width - 2), z0 = std::min(static_cast<int>(cz), t.height - 2);
  const float fx = cx - static_cast<float>(x0), fz = cz - static_cast<float>(z0);
  const auto h = [&](int a, int b) { return static_cast<float>(t.metresAt(a, b)); };
  const float top = h(x0, z0) + (h(x0 + 1, z0) - h(x0, z0)) * fx;
  const float bottom = h(x0, z0 + 1) + (h(x0 + 1, z0 + 1) - h(x0, z0 + 1)) * fx;
  return top + (bottom - top) * fz;
}

}  // namespace vbim::render
