#include "lighting/authoring/terrain_author.hpp"

#include <sstream>

#include "config/params_toml.hpp"
#include "runtime/param_table.hpp"
#include "streams/authoring/error.hpp"
#include "streams/authoring/frame_stream.hpp"

namespace vbim::lighting {

TechniqueAStreamSettings terrainAuthorSettings(const TerrainAuthorRequest& r) {
  if (r.procedural && !r.terrain.heightfield.empty()) {
    throw streams::AuthoringError("--procedural and --terrain exclude each other");
  }
  TechniqueAStreamSettings s;
  s.terrain = r.terrain;
  s.terrain.procedural.cellSize = s.terrain.cellSize;  // --cell-size sizes the procedural terrain's cells too
  s.stream = streams::streamSettings(r.encode);
  s.tone = streams::toneMapping(r.encode);
  s.threads = r.threads;
  // The generator's defaults, then the lighting config file, then the options given.
  if (!r.lightingConfig.empty()) {
    ParamTable table;
    describeParams(table, s.base);
    config::applyTomlFile(table, r.lightingConfig);
  }
  if (r.applyGiven) r.applyGiven(s.base);
  s.variants = weatherVariants(r.weather, s.base);
  return s;
}

std::string authoredSummary(const std::string& out, const AuthoredStream& stream, streams::Rational containerFps) {
  const streams::Descriptor& d = stream.descriptor;
  std::ostringstream o;
  o << out << ": " << stream.bytes.size() / 2048 << " sectors (" << stream.bytes.size() << " bytes), "
    << d.variants.size() << " variant(s) x " << d.framesPerVariant << " frames, lightmap " << d.streams[0].width << "x"
    << d.streams[0].height << ", sky " << d.streams[1].width << "x" << d.streams[1].height << "\n"
    << streams::containerStretchNote(stream.containerStretch, containerFps);
  return o.str();
}

}  // namespace vbim::lighting
