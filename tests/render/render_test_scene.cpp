#include "render_test_scene.hpp"

#include "lighting/authoring/technique_a_stream.hpp"
#include "lighting/procedural_terrain.hpp"

namespace vbim::render::test {

lighting::Terrain smallTerrain() {
  lighting::ProceduralTerrainParams p;
  p.size = 64;
  p.cellSize = 20;
  lighting::Terrain t = lighting::proceduralTerrain(p);
  lighting::setAlbedo(t, lighting::proceduralAlbedo(t), "test albedo");
  return t;
}

lighting::DayCycleParams smallDay() {
  lighting::DayCycleParams d;
  d.frames = 24;
  d.startHour = 0;
  d.endHour = 24;
  d.skyWidth = 32;
  return d;
}

RenderSettings smallSettings() {
  RenderSettings s;
  s.width = 96;
  s.height = 64;
  s.patchCells = 16;
  return s;
}

StreamedFrame streamedFrame(int frame) {
  lighting::DayCycleGenerator gen(smallTerrain(), smallDay());
  lighting::FloatImage lm, sky;
  StreamedFrame f;
  gen.renderFrame(frame, lm, sky, &f.shadowMask);
  streams::ToneMapping tone;
  tone.exposure = -1;  // as the samples
  f.lightmap = lighting::streamFrame(lm, tone);
  f.sky = lighting::streamFrame(sky, tone);
  return f;
}

std::uint64_t hashImage(const Rgba8Image& img) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (std::uint8_t b : img.pixels) h = (h ^ b) * 0x100000001b3ULL;
  return h;
}

}  // namespace vbim::render::test
