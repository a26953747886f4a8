// Where the picture is taken from, and how it is exposed.
//
// `--camera EX,EZ,EH,TX,TZ`: eye at (EX, EZ) metres (x east, z south from the map's north-west
// corner) EH metres above the ground, looking at the ground point (TX, TZ). Without it: the
// automatic view from the valley in the south-east towards the mountains in the north-west.
#pragma once

#include <optional>
#include <string>

#include "lighting/terrain.hpp"

namespace vbim::render {

struct CameraPlacement {
  float eyeX = 0, eyeZ = 0, eyeHeight = 0;  // height above the ground
  float targetX = 0, targetZ = 0;
};

struct RenderSettings {
  int width = 640;
  int height = 360;
  std::optional<CameraPlacement> camera;  // empty: automatic
  float fovDeg = 55;                      // vertical field of view
  float exposure = 8;                     // display scale on stream units before 1 - exp(-x)
  float hazeDistance = 0;                 // metres at which haze covers 63 %; 0: 1.5 x the map's size
  float lodDistance = 0;                  // metres; 0: 1.5 patches
  int patchCells = 32;
  bool objects = true;
  float objectScale = 0;   // metres per model unit; 0: cell size / 4, so objects span lightmap texels
  float groundOffset = 0;  // Hargreaves' offset along the normal, metres; 0: one cell
};

// Parses "EX,EZ,EH,TX,TZ"; throws RenderError naming the text and the expected form.
CameraPlacement parseCamera(const std::string& text);

// The automatic camera for a terrain.
CameraPlacement automaticCamera(const lighting::Terrain& terrain);

// Throws RenderError if the eye or the target lies outside the terrain, or they coincide.
void checkCamera(const CameraPlacement& c, const lighting::Terrain& terrain);

}  // namespace vbim::render
