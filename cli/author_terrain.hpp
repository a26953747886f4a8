// `vbim author --terrain FILE | --procedural ...`: Technique A (lighting/) straight to a VBIM stream,
// frames rendered one at a time in memory (lighting/authoring/technique_a_stream.hpp): the options
// (shared with `vbim lightmap`'s lighting ones, cli/lighting_options.hpp), read into the request
// runs::authorRun takes (runs/author_run.hpp; its settings are lighting::terrainAuthorSettings).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/lighting_options.hpp"
#include "lighting/authoring/terrain_author.hpp"

namespace vbim::cli {

struct TerrainAuthorOptions {
  lighting::TerrainAuthorRequest request;  // the values; its given flags, overrides and encoder set when run
  bool noMoon = false;
  lighting::DayCycleParams params;             // values given on the command line
  LightingOverrides given;                     // lighting options: each overrides the config file's value when given
  std::vector<CLI::Option*> options;           // every option of this source, to tell whether it was chosen
  CLI::Option* cellSizeOption = nullptr;       // given: overrides a DEM's cell size
  CLI::Option* verticalScaleOption = nullptr;  // given: scales float heights and DEMs too
};

void addTerrainOptions(CLI::App* cmd, const std::shared_ptr<TerrainAuthorOptions>& o);
// The first Technique A option on the command line ("" if none): selects this source.
std::string firstTerrainOptionGiven(const TerrainAuthorOptions& o);
// The request the options make (run by runs::authorRun): the values, which of them were given, and
// the lighting options given over a lighting config's values. Holds a reference to `o`.
lighting::TerrainAuthorRequest terrainRequest(const TerrainAuthorOptions& o);

}  // namespace vbim::cli
