#include "lighting/authoring/technique_a_record.hpp"

#include <variant>

#include <nlohmann/json.hpp>

#include "lighting/error.hpp"
#include "runtime/param_table.hpp"

namespace vbim::lighting {

namespace {

using Json = nlohmann::ordered_json;

const char* curveName(streams::ToneMapping::Curve c) {
  switch (c) {
    case streams::ToneMapping::Curve::Reinhard:
      return "reinhard";
    case streams::ToneMapping::Curve::Filmic:
      return "filmic";
    case streams::ToneMapping::Curve::Clamp:
      break;
  }
  return "clamp";
}

std::string transferName(const streams::ToneMapping& t) {
  switch (t.transfer) {
    case streams::ToneMapping::Transfer::Linear:
      return "linear";
    case streams::ToneMapping::Transfer::Gamma:
      return "gamma:" + Json(t.gamma).dump();
    case streams::ToneMapping::Transfer::Srgb:
      break;
  }
  return "srgb";
}

// Every lighting.* parameter with its value, in the table's order.
Json lightingJson(DayCycleParams p) {
  ParamTable table;
  describeParams(table, p);
  Json j = Json::object();
  for (const ParamTable::Param& param : table.params()) {
    std::visit([&](auto* field) { j[param.key] = *field; }, param.field);
  }
  return j;
}

// Sets the lighting.* keys of `j` on `p`, each checked against its range.
void applyLighting(const Json& j, DayCycleParams& p, const std::string& where) {
  ParamTable table;
  describeParams(table, p);
  for (const auto& item : j.items()) {
    const std::string& key = item.key();
    const Json& value = item.value();
    const ParamTable::Param* param = table.find(key);
    if (param == nullptr) throw LightingError(where + ": unknown key '" + key + "'");
    const auto bad = [&](const std::string& expected) {
      return LightingError(where + ": '" + key + "' is " + value.dump() + ", expected " + expected);
    };
    if (auto* b = std::get_if<bool*>(&param->field)) {
      if (!value.is_boolean()) throw bad("true or false");
      **b = value.get<bool>();
    } else if (auto* s = std::get_if<std::string*>(&param->field)) {
      if (!value.is_string()) throw bad("a string");
      **s = value.get<std::string>();
    } else {
      if (!value.is_number()) throw bad("a number");
      const double v = value.get<double>();
      if (v < param->min || v > param->max) {
        throw bad("a value in [" + Json(param->min).dump() + ", " + Json(param->max).dump() + "]");
      }
      if (auto* i = std::get_if<std::int64_t*>(&param->field)) {
        if (!value.is_number_integer()) throw bad("an integer");
        **i = value.get<std::int64_t>();
      } else {
        **std::get_if<double*>(&param->field) = v;
      }
    }
  }
}

}  // namespace

std::string authoringRecordJson(const TechniqueAStreamSettings& s, const std::vector<WeatherVariant>& variants,
                                const Terrain& terrain) {
  const DayCycleParams& day = variants.front().params;
  Json j;
  j["record"] = "vbim-authoring";
  j["record_version"] = kAuthoringRecordVersion;
  j["vbim_version"] = VBIM_VERSION_STRING;
  j["source"] = "technique-a";
  const bool procedural = s.terrain.heightfield.empty();
  Json t;
  t["heightfield"] = procedural ? "procedural" : s.terrain.heightfield;
  t["albedo"] = s.terrain.albedo;
  t["cloud_texture"] = s.terrain.cloudTexture;
  t["cell_size_m"] = terrain.cellSize;
  t["vertical_scale_m"] = s.terrain.verticalScale;
  if (s.terrain.fit != TerrainFit::Crop) t["fit"] = terrainFitName(s.terrain.fit);  // only when not the default
  if (procedural) {
    t["procedural_size"] = s.terrain.procedural.size;
    t["procedural_seed"] = s.terrain.procedural.seed;
    t["procedural_relief_m"] = s.terrain.procedural.reliefMetres;
  }
  t["width"] = terrain.width;
  t["height"] = terrain.height;
  j["terrain"] = t;
  j["stream"] = {{"game_fps", {s.stream.gameFps.num, s.stream.gameFps.den}},
                 {"loop_frame", s.stream.loopFrame},
                 {"frames_per_variant", day.frames},
                 {"qscale", s.stream.encoder.qscale},
                 {"bitrate", s.stream.encoder.bitrate}};
  if (s.stream.encoder.gop > 1) {  // intra-only records keep their bytes
    j["stream"]["gop"] = s.stream.encoder.gop;
    j["stream"]["b_frames"] = s.stream.encoder.bFrames;
    j["stream"]["closed_gop"] = !s.stream.encoder.openGop;
  }
  j["tone"] = {{"exposure_ev", s.tone.exposure},
               {"curve", curveName(s.tone.curve)},
               {"transfer", transferName(s.tone)},
               {"white", s.tone.white}};
  Json hours = Json::array();
  for (int f = 0; f < static_cast<int>(day.frames); ++f) hours.push_back(frameHour(day, f));
  j["day"] = {{"start_hour", day.startHour}, {"end_hour", day.endHour}, {"frames", day.frames}, {"frame_hours", hours}};
  for (const WeatherVariant& v : variants)
    j["variants"].push_back({{"name", v.name}, {"lighting", lightingJson(v.params)}});
  return j.dump();
}

AuthoringRecord parseAuthoringRecord(const std::string& text, const std::string& origin) {
  Json j;
  try {
    j = Json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw LightingError(origin + ": the authoring record is not JSON: " + e.what());
  }
  AuthoringRecord r;
  std::string at = "record";
  try {
    if (!j.is_object() || j.value("record", "") != "vbim-authoring") {
      throw LightingError(origin + ": not a vbim authoring record (no \"record\": \"vbim-authoring\")");
    }
    const int version = j.at("record_version").get<int>();
    if (version > kAuthoringRecordVersion) {
      throw LightingError(origin + ": authoring record version " + std::to_string(version) + " is newer than this " +
                          "vbim reads (" + std::to_string(kAuthoringRecordVersion) + ")");
    }
    r.vbimVersion = j.value("vbim_version", "");
    r.source = j.at("source").get<std::string>();
    at = "terrain";
    const Json& t = j.at("terrain");
    const std::string heightfield = t.at("heightfield").get<std::string>();
    r.procedural = heightfield == "procedural";
    if (!r.procedural) r.terrain.heightfield = heightfield;
    r.terrain.albedo = t.value("albedo", "");
    r.terrain.cloudTexture = t.value("cloud_texture", "");
    r.terrain.cellSize = t.at("cell_size_m").get<double>();
    r.terrain.verticalScale = t.at("vertical_scale_m").get<double>();
    r.terrain.fit = parseTerrainFit(t.value("fit", "crop"), origin + ": terrain.fit");
    r.terrainWidth = t.at("width").get<int>();
    r.terrainHeight = t.at("height").get<int>();
    if (r.procedural) {
      r.terrain.procedural.cellSize = r.terrain.cellSize;
      r.terrain.procedural.size = t.at("procedural_size").get<std::int64_t>();
      r.terrain.procedural.seed = t.at("procedural_seed").get<std::int64_t>();
      r.terrain.procedural.reliefMetres = t.at("procedural_relief_m").get<double>();
    }
    at = "stream";
    r.loopFrame = j.at("stream").at("loop_frame").get<std::uint32_t>();
    at = "day";
    r.frameHours = j.at("day").at("frame_hours").get<std::vector<double>>();
    at = "variants";
    for (const Json& v : j.at("variants")) {
      WeatherVariant w;
      w.name = v.at("name").get<std::string>();
      applyLighting(v.at("lighting"), w.params, origin + ": variant '" + w.name + "'");
      r.variants.push_back(std::move(w));
    }
    if (r.variants.empty()) throw LightingError(origin + ": the authoring record lists no variant");
  } catch (const nlohmann::json::exception& e) {
    throw LightingError(origin + ": authoring record, '" + at + "': " + e.what());
  }
  return r;
}

}  // namespace vbim::lighting
