// Technique A straight to a VBIM stream: the day-cycle generator (lighting/day_cycle.hpp) renders
// each frame in memory, the tone mapping turns it into 8-bit RGB, and the StreamWriter
// (streams/authoring/stream_writer.hpp) encodes and muxes it. No image files in between.
//
// In-process use (e.g. `vbim demo` authoring its own day cycle before playing it):
//
//   vbim::lighting::TechniqueAStreamSettings s;        // procedural terrain, one "clear" day
//   s.terrain.procedural.size = 256;                    // lightmap size (a multiple of 16)
//   s.base.frames = 48; s.base.startHour = 0; s.base.endHour = 24; s.base.skyWidth = 128;
//   s.variants = {weatherVariant("clear", s.base), weatherVariant("overcast", s.base)};  // optional
//   s.stream.gameFps = {1, 1};                          // one stream frame per game second
//   vbim::lighting::authorTechniqueA(s, "day.vbim",
//       [](const TechniqueAProgress& p) { /* p.done of p.total frames */ });
//
// Every problem (a bad heightfield, a setting out of range, a frame size the encoder cannot take,
// an unwritable output) is thrown as streams::AuthoringError, whose message names the input and
// what was expected; the output file is then left as it was (written under a temporary name and
// renamed only when complete).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "lighting/day_cycle.hpp"
#include "lighting/procedural_terrain.hpp"
#include "lighting/terrain_file.hpp"
#include "runtime/image.hpp"
#include "streams/authoring/stream_writer.hpp"
#include "streams/authoring/tone_map.hpp"

namespace vbim::lighting {

// One weather of the stream: its name (1..23 bytes) and the generator's settings.
struct WeatherVariant {
  std::string name;
  DayCycleParams params;
};

// The built-in weathers, derived from `base`:
//   "clear":    `base` unchanged.
//   "overcast": moving cloud shadows (coverage 0.85, opacity 0.8), a hazier atmosphere (turbidity 6,
//               the top of Preetham's fitted range), 0.4x the direct sun (sun_klux) and the whole
//               frame dimmer (exposure_klux x 1.6): dim, soft direct light, relatively more skylight.
// Throws streams::AuthoringError for another name.
WeatherVariant weatherVariant(const std::string& name, const DayCycleParams& base);
// A list of variants, comma-separated: preset names (weatherVariant) or NAME=FILE, a TOML file of
// lighting.* keys applied over `base` (`vbim author --weather clear,overcast,storm=storm.toml`).
// Throws streams::AuthoringError, or ConfigError for a file.
std::vector<WeatherVariant> weatherVariants(const std::string& list, const DayCycleParams& base);
// The names weatherVariant accepts.
const std::vector<std::string>& weatherPresetNames();

struct TechniqueAStreamSettings {
  TerrainSource terrain;
  // The settings of a single-variant stream; also what weatherVariant() presets start from.
  DayCycleParams base;
  // The variants in stream order; empty means one variant "clear" with `base`. All must have the
  // same frame count and sky width (the player branches between variants frame by frame).
  std::vector<WeatherVariant> variants;
  // Linear normalised irradiance -> 8-bit codes (docs/stream-format.md): default clamp + sRGB, 1.0 = 255.
  streams::ToneMapping tone;
  // Game-time frame rate, loop frame, quantiser or bitrate. withSky is ignored (always true: every
  // frame carries its sky dome).
  streams::AuthorSettings stream;
  unsigned threads = 1;  // host threads for the generator (the output does not depend on it)
};

struct TechniqueAProgress {
  int done = 0;   // frames encoded so far, all variants
  int total = 0;  // frames in the stream
  std::string variant;
  int frame = 0;  // index of the frame just encoded within its variant
};
using TechniqueAProgressFn = std::function<void(const TechniqueAProgress&)>;

struct AuthoredStream {
  std::vector<std::uint8_t> bytes;  // the whole stream, 2048-byte packs
  streams::Descriptor descriptor;
  int maxQscaleUsed = 0;
  std::uint32_t containerStretch = 1;     // StreamWriter::containerStretch()
  std::vector<std::string> terrainNotes;  // what a terrain file said and what was overridden (for the user)
};

// Loads (or builds) the terrain, with its albedo. Throws streams::AuthoringError. `notes`
// (optional) receives what the terrain file said (a DEM's cell size, units...) and any override.
Terrain loadTerrain(const TerrainSource& source, std::vector<std::string>* notes = nullptr);

// Checks everything that can be checked before any heavy work: every variant's settings in range,
// equal frame counts and sky widths, frame sizes the encoder takes (multiples of 16, at most 4080),
// unique variant names. `terrainWidth/Height` are the loaded terrain's. Throws streams::AuthoringError.
void checkStreamSettings(const TechniqueAStreamSettings& s, int terrainWidth, int terrainHeight,
                         const std::string& terrainOrigin);

// The 8-bit frame the encoder receives for one generator image (lightmap or sky), exactly.
Rgba8Image streamFrame(const FloatImage& image, const streams::ToneMapping& tone);

// Renders every frame of every variant and returns the finished stream.
AuthoredStream authorTechniqueAStream(const TechniqueAStreamSettings& s, const TechniqueAProgressFn& progress = {});
// The same, written to `out` (complete or left as it was).
AuthoredStream authorTechniqueA(const TechniqueAStreamSettings& s, const std::filesystem::path& out,
                                const TechniqueAProgressFn& progress = {});

}  // namespace vbim::lighting
