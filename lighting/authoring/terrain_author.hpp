// `vbim author --terrain FILE | --procedural ...` as a library call: the command's values (the
// terrain, a lighting.* TOML file, the options given over it, the weathers, the encoder's options)
// into Technique A's stream settings (technique_a_stream.hpp), and the line printed about the
// stream written. Not model code; no simulated time (the stream's cost is the player's).
#pragma once

#include <functional>
#include <string>

#include "lighting/authoring/technique_a_stream.hpp"
#include "streams/authoring/encode_options.hpp"

namespace vbim::lighting {

struct TerrainAuthorRequest {
  TerrainSource terrain;  // its cellSizeGiven / verticalScaleGiven set by the caller
  bool procedural = false;
  std::string lightingConfig;                       // lighting.* TOML over the defaults, or empty
  std::function<void(DayCycleParams&)> applyGiven;  // the options given, over the file's values
  std::string weather = "clear";                    // weatherVariants' list
  unsigned threads = 2;
  streams::EncodeOptions encode;
};

// Throws streams::AuthoringError (--procedural with --terrain, a bad encoder option, an unknown
// weather) and ConfigError (the lighting config file).
TechniqueAStreamSettings terrainAuthorSettings(const TerrainAuthorRequest& r);

// What `vbim author` (and `vbim demo`) prints about a Technique A stream written to `out`.
std::string authoredSummary(const std::string& out, const AuthoredStream& stream, streams::Rational containerFps);

}  // namespace vbim::lighting
