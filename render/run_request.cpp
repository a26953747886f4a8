#include "render/run_request.hpp"

#include <nlohmann/json.hpp>

#include "config/params_toml.hpp"
#include "lighting/authoring/technique_a_record.hpp"
#include "lighting/error.hpp"
#include "render/error.hpp"
#include "runtime/param_table.hpp"

namespace vbim::render {

RunRenderRequest::RunRenderRequest() {
  terrain.cellSize = 20.0;
  terrain.procedural.cellSize = 20.0;
  terrain.procedural.size = 256;
  day.frames = 24;
  day.startHour = 0;
  day.endHour = 24;
  day.skyWidth = 128;
}

void loadLightingConfig(const std::string& path, lighting::DayCycleParams& day) {
  ParamTable table;
  lighting::describeParams(table, day);
  try {
    config::applyTomlFile(table, path);
  } catch (const ConfigError& e) {
    throw RenderError(e.what());
  }
}

void applyAuthoring(const std::string& text, const std::string& origin, RunRenderRequest& req) {
  lighting::AuthoringRecord r;
  try {
    r = lighting::parseAuthoringRecord(text, origin);
  } catch (const lighting::LightingError& e) {
    throw RenderError(e.what());
  }
  req.terrain = r.terrain;
  req.proceduralSizeFromLightmap = false;
  req.day = r.variants.front().params;
  req.variantDays.clear();
  for (const lighting::WeatherVariant& v : r.variants) req.variantDays.push_back(v.params);
  req.loopFrame = static_cast<int>(r.loopFrame);
  req.settingsFrom = origin;
}

namespace {

constexpr const char* kAssumed =
    "assuming the procedural terrain at the lightmap's size with 20 m cells and a 24-frame day from 0 h to 24 h; "
    "--terrain, --cell-size and --lighting-config set them";

}  // namespace

RunRenderRequest requestForRun(const player::RunDir& run, const RunRequestOptions& o,
                               const std::function<void(const std::string&)>& note) {
  RunRenderRequest req = o.values;  // every option, given or default
  // A record from image files or the synthetic generator (vbim author) holds no terrain to light.
  const auto record = run.authoring ? nlohmann::json::parse(*run.authoring, nullptr, false) : nlohmann::json();
  const std::string source = record.is_object() ? record.value("source", std::string()) : std::string();
  if (run.authoring && (source == "synthetic" || source == "image-sequence") && !record.contains("terrain")) {
    note(run.path.string() + "/authoring.json records a stream made from " + source +
         " frames, with no terrain: " + kAssumed);
  } else if (run.authoring) {
    applyAuthoring(*run.authoring, (run.path / "authoring.json").string(), req);
    if (o.cellSize) req.terrain.cellSize = o.values.terrain.cellSize;
    if (o.verticalScale) req.terrain.verticalScale = o.values.terrain.verticalScale;
    if (o.relief) req.terrain.procedural.reliefMetres = o.values.terrain.procedural.reliefMetres;
    if (o.terrainSeed) req.terrain.procedural.seed = o.values.terrain.procedural.seed;
    if (o.loopFrame) req.loopFrame = o.values.loopFrame;
  } else {
    note(run.path.string() + " has no authoring.json (its stream carried no authoring record): " + kAssumed);
  }
  if (!o.terrain.empty()) req.terrain.heightfield = o.terrain;
  if (!o.albedo.empty()) req.terrain.albedo = o.albedo;
  if (!o.lightingConfig.empty()) {
    // The file's keys over every variant's recorded settings (the weathers keep what it leaves).
    loadLightingConfig(o.lightingConfig, req.day);
    for (lighting::DayCycleParams& day : req.variantDays) loadLightingConfig(o.lightingConfig, day);
  }
  return req;
}

}  // namespace vbim::render
