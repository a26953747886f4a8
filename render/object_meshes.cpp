#include "render/object_meshes.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "render/terrain_mesh.hpp"

namespace vbim::render {

namespace {

using V3 = std::array<float, 3>;

V3 sub(V3 a, V3 b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
V3 cross(V3 a, V3 b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
V3 normalise(V3 a) {
  const float l = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  return l > 0 ? V3{a[0] / l, a[1] / l, a[2] / l} : V3{0, 1, 0};
}

// One flat-shaded triangle, counter-clockwise from outside.
void tri(Mesh& m, V3 a, V3 b, V3 c) {
  const V3 n = normalise(cross(sub(b, a), sub(c, a)));
  for (const V3& p : {a, b, c}) m.vertices.insert(m.vertices.end(), {p[0], p[1], p[2], n[0], n[1], n[2]});
}

// An axis-aligned box from (x0, y0, z0) to (x1, y1, z1).
void box(Mesh& m, float x0, float y0, float z0, float x1, float y1, float z1) {
  const V3 p[8] = {{x0, y0, z0}, {x1, y0, z0}, {x1, y1, z0}, {x0, y1, z0},
                   {x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}};
  const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 4, 7, 3}, {1, 2, 6, 5}, {3, 7, 6, 2}, {0, 1, 5, 4}};
  for (const auto& f : faces) {
    tri(m, p[f[0]], p[f[1]], p[f[2]]);
    tri(m, p[f[0]], p[f[2]], p[f[3]]);
  }
}

// Integer hash -> [0, 1): deterministic jitter.
float hash01(unsigned a, unsigned b) {
  unsigned long long z = (a * 0x9E3779B97F4A7C15ULL) ^ (b * 0xC2B2AE3D27D4EB4FULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return static_cast<float>(z >> 40) / static_cast<float>(1ULL << 24);
}

}  // namespace

Mesh rockMesh(unsigned seed) {
  // Icosahedron subdivided once (80 faces), radii jittered per vertex, squashed, sunk a little.
  const float t = (1.0f + std::sqrt(5.0f)) / 2;
  std::vector<V3> v = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                       {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  const int f[20][3] = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  auto shaped = [&](V3 p) {
    const V3 n = normalise(p);
    // Jitter keyed by the direction, so shared vertices move together and the rock stays closed.
    const unsigned key = static_cast<unsigned>(std::lround((n[0] + 2) * 1000)) * 7919u +
                         static_cast<unsigned>(std::lround((n[1] + 2) * 1000)) * 104729u +
                         static_cast<unsigned>(std::lround((n[2] + 2) * 1000));
    const float r = 0.8f + 0.35f * hash01(seed, key);
    return V3{n[0] * r * 1.2f, n[1] * r * 0.7f + 0.45f, n[2] * r};
  };
  auto mid = [](V3 a, V3 b) { return V3{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2}; };
  Mesh m;
  for (const auto& face : f) {
    const V3 a = v[face[0]], b = v[face[1]], c = v[face[2]];
    const V3 ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
    tri(m, shaped(a), shaped(ab), shaped(ca));
    tri(m, shaped(ab), shaped(b), shaped(bc));
    tri(m, shaped(ca), shaped(bc), shaped(c));
    tri(m, shaped(ab), shaped(bc), shaped(ca));
  }
  return m;
}

Mesh postMesh() {
  Mesh m;
  box(m, -0.25f, 0.0f, -0.25f, 0.25f, 4.0f, 0.25f);
  box(m, -0.9f, 3.2f, -0.12f, 0.9f, 3.5f, 0.12f);  // a cross-arm
  return m;
}

Mesh vehicleMesh() {
  Mesh m;
  box(m, -2.3f, 0.5f, -1.0f, 2.3f, 1.5f, 1.0f);    // body
  box(m, -2.2f, 1.5f, -0.95f, 0.2f, 2.4f, 0.95f);  // cab
  for (float x : {-1.5f, 1.5f}) {
    for (float z : {-1.15f, 0.85f}) box(m, x - 0.45f, 0.0f, z, x + 0.45f, 0.9f, z + 0.3f);  // wheels
  }
  return m;
}

ObjectSet objectSet(const lighting::Terrain& terrain, float siteX, float siteZ, float eyeX, float eyeZ, float scale) {
  ObjectSet s;
  s.meshes = {rockMesh(1), rockMesh(2), postMesh(), vehicleMesh()};
  // Local frame: forward = from the eye towards the site, right = forward x up.
  float fx = siteX - eyeX, fz = siteZ - eyeZ;
  const float fl = std::sqrt(fx * fx + fz * fz);
  fx = fl > 0 ? fx / fl : 0;
  fz = fl > 0 ? fz / fl : 1;
  const float rx = -fz, rz = fx;
  struct Slot {
    const char* kind;
    int mesh;
    float right, ahead;  // model units
    float size;          // extra scale
    std::array<float, 3> albedo;
  };
  const Slot slots[] = {
      {"rock", 0, -7.0f, 2.0f, 1.6f, {0.35f, 0.33f, 0.30f}},   {"rock", 1, 6.5f, 6.0f, 1.3f, {0.40f, 0.38f, 0.34f}},
      {"rock", 0, -13.0f, 13.0f, 2.0f, {0.33f, 0.31f, 0.29f}}, {"post", 2, -2.5f, -3.0f, 1.0f, {0.45f, 0.30f, 0.18f}},
      {"post", 2, 2.5f, -3.0f, 1.0f, {0.45f, 0.30f, 0.18f}},   {"post", 2, 10.0f, -1.0f, 1.0f, {0.45f, 0.30f, 0.18f}},
      {"vehicle", 3, 0.0f, 3.0f, 1.0f, {0.60f, 0.12f, 0.08f}},
  };
  const float maxX = static_cast<float>((terrain.width - 1) * terrain.cellSize);
  const float maxZ = static_cast<float>((terrain.height - 1) * terrain.cellSize);
  for (const Slot& slot : slots) {
    PlacedObject o;
    o.kind = slot.kind;
    o.mesh = slot.mesh;
    o.scale = scale * slot.size;
    const float x = std::clamp(siteX + (rx * slot.right + fx * slot.ahead) * scale, 0.0f, maxX);
    const float z = std::clamp(siteZ + (rz * slot.right + fz * slot.ahead) * scale, 0.0f, maxZ);
    o.position[0] = x;
    o.position[2] = z;
    o.position[1] = terrainHeightAt(terrain, x, z) - 0.15f * o.scale;  // sunk a little into slopes
    o.yawRad = std::atan2(fx, fz) +
               0.6f * (hash01(static_cast<unsigned>(slot.mesh), static_cast<unsigned>(slot.right * 10 + 100)) - 0.5f);
    for (int c = 0; c < 3; ++c) o.albedo[c] = slot.albedo[static_cast<std::size_t>(c)];
    s.objects.push_back(o);
  }
  return s;
}

}  // namespace vbim::render
