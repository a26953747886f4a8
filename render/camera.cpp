#include "render/camera.hpp"

#include <cmath>
#include <sstream>
#include <vector>

#include "render/error.hpp"

namespace vbim::render {

CameraPlacement parseCamera(const std::string& text) {
  std::vector<float> v;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    try {
      std::size_t used = 0;
      const float f = std::stof(item, &used);
      if (used != item.size() || !std::isfinite(f)) throw std::invalid_argument(item);
      v.push_back(f);
    } catch (const std::exception&) {
      throw RenderError("--camera '" + text + "': '" + item + "' is not a number (expected EX,EZ,EH,TX,TZ in metres)");
    }
  }
  if (v.size() != 5) {
    throw RenderError("--camera '" + text + "': expected 5 numbers EX,EZ,EH,TX,TZ (eye east, eye south, eye height " +
                      "above ground, target east, target south; metres), got " + std::to_string(v.size()));
  }
  if (v[2] <= 0) throw RenderError("--camera '" + text + "': the eye height above the ground must be positive");
  return CameraPlacement{v[0], v[1], v[2], v[3], v[4]};
}

CameraPlacement automaticCamera(const lighting::Terrain& t) {
  const float w = static_cast<float>((t.width - 1) * t.cellSize), h = static_cast<float>((t.height - 1) * t.cellSize);
  return CameraPlacement{0.80f * w, 0.84f * h, static_cast<float>(4 * t.cellSize), 0.45f * w, 0.45f * h};
}

void checkCamera(const CameraPlacement& c, const lighting::Terrain& t) {
  const double w = (t.width - 1) * t.cellSize, h = (t.height - 1) * t.cellSize;
  auto inside = [&](float x, float z) { return x >= 0 && z >= 0 && x <= w && z <= h; };
  std::ostringstream range;
  range << "the terrain spans x 0.." << w << " m, z 0.." << h << " m";
  if (!inside(c.eyeX, c.eyeZ)) {
    std::ostringstream s;
    s << "camera eye (" << c.eyeX << ", " << c.eyeZ << ") is outside the terrain: " << range.str();
    throw RenderError(s.str());
  }
  if (!inside(c.targetX, c.targetZ)) {
    std::ostringstream s;
    s << "camera target (" << c.targetX << ", " << c.targetZ << ") is outside the terrain: " << range.str();
    throw RenderError(s.str());
  }
  if (c.eyeX == c.targetX && c.eyeZ == c.targetZ) throw RenderError("camera eye and target are the same ground point");
}

}  // namespace vbim::render
