// A handful of simple meshes to stand on the terrain and show how the hemisphere lighting ties them
// in: rocks (jittered icospheres), posts (tall boxes), a vehicle (a body and a cab on four wheels).
// Flat-shaded: every triangle has its own three vertices, so normals are the faces'.
#pragma once

#include <string>
#include <vector>

#include "lighting/terrain.hpp"

namespace vbim::render {

struct Mesh {
  std::vector<float> vertices;  // position xyz, normal xyz per vertex; model units, y up, base at y = 0
};

Mesh rockMesh(unsigned seed);
Mesh postMesh();
Mesh vehicleMesh();

struct PlacedObject {
  std::string kind;               // "rock", "post", "vehicle"
  int mesh = 0;                   // index into the mesh list of objectSet()
  float position[3] = {0, 0, 0};  // world metres, base on the ground
  float yawRad = 0;
  float scale = 1;                       // metres per model unit
  float albedo[3] = {0.5f, 0.5f, 0.5f};  // linear
};

struct ObjectSet {
  std::vector<Mesh> meshes;
  std::vector<PlacedObject> objects;
};

// Objects in a loose group around ground point (siteX, siteZ), facing the viewer at (eyeX, eyeZ),
// spread over a few lightmap texels so some can stand in shadow while others are lit. Deterministic.
ObjectSet objectSet(const lighting::Terrain& terrain, float siteX, float siteZ, float eyeX, float eyeZ, float scale);

}  // namespace vbim::render
