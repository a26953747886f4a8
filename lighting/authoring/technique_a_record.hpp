// The authoring record of a Technique A stream (streams/record_packs.hpp carries it): how the
// stream was made, as JSON, so that `vbim render` lights the same terrain at the same hours without
// the options being repeated. Written by authorTechniqueAStream; read by `vbim info`, copied by
// `vbim play` into the run directory (authoring.json) and applied by `vbim render`.
//
//   {"record": "vbim-authoring", "record_version": 1, "vbim_version": "0.1.0", "source": "technique-a",
//    "terrain": {"heightfield": "procedural", "cell_size_m": 20, ...},
//    "stream": {"game_fps": [1, 1], "loop_frame": 0, "frames_per_variant": 24, ...},
//    "day": {"start_hour": 0, "end_hour": 24, "frames": 24, "frame_hours": [0, 1, ...]},
//    "variants": [{"name": "clear", "lighting": {"lighting.latitude_deg": 45, ...}}], ...}
//
// The lighting keys are those of `vbim config --defaults` (lighting.*), so a variant's settings read
// back exactly as they were given.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lighting/authoring/technique_a_stream.hpp"

namespace vbim::lighting {

inline constexpr int kAuthoringRecordVersion = 1;

// The record of a stream made from `s` with these variants on `terrain` (as loaded: its size and
// cell size are the ones the frames were lit with).
std::string authoringRecordJson(const TechniqueAStreamSettings& s, const std::vector<WeatherVariant>& variants,
                                const Terrain& terrain);

struct AuthoringRecord {
  std::string source;  // "technique-a"
  std::string vbimVersion;
  TerrainSource terrain;
  bool procedural = true;
  int terrainWidth = 0, terrainHeight = 0;
  std::vector<WeatherVariant> variants;  // their lighting settings, in stream order
  std::vector<double> frameHours;        // per frame of a variant
  std::uint32_t loopFrame = 0;
};

// Parses a record (`origin` names it in messages). Throws LightingError naming the origin and the
// field for a record that is not JSON, is of another kind or a newer version, or has a value out of
// range.
AuthoringRecord parseAuthoringRecord(const std::string& json, const std::string& origin);

}  // namespace vbim::lighting
