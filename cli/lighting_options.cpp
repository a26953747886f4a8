#include "cli/lighting_options.hpp"

namespace vbim::cli {

using lighting::DayCycleParams;

void addLightingOptions(CLI::App* cmd, DayCycleParams& cli, bool& noMoon, LightingOverrides& overrides,
                        const LightingOptionNames& names, const std::function<void(CLI::Option*)>& added) {
  const DayCycleParams defaults;  // shown in --help
  // `field` names the member in any DayCycleParams: the option writes cli's, the override copies
  // it into the params being built. Pointers, not owners: the options object owns these functions.
  DayCycleParams* source = &cli;
  auto bind = [&](CLI::Option* opt, auto field) {
    added(opt);
    overrides.push_back({opt, [source, field](DayCycleParams& dst) { field(dst) = field(*source); }});
    return opt;
  };
  auto param = [&](const std::string& flags, auto field, const std::string& help) {
    return bind(cmd->add_option(flags, field(cli), help), field);
  };
  auto flag = [&](const std::string& flags, auto field, const std::string& help) {
    bind(cmd->add_flag(flags, field(cli), help), field);
  };
#define VBIM_FIELD(member) ([](DayCycleParams & q) -> auto& { return q.member; })
  param("--latitude", VBIM_FIELD(latitudeDeg), "Latitude in degrees, -90..90")->default_val(defaults.latitudeDeg);
  param("--day", VBIM_FIELD(dayOfYear), "Day of the year, 1..366")->default_val(defaults.dayOfYear);
  param("--start-hour", VBIM_FIELD(startHour), "Local solar time of the first frame")->default_val(defaults.startHour);
  param("--end-hour", VBIM_FIELD(endHour), "Local solar time of the last frame (0 to 24 loops a day)")
      ->default_val(defaults.endHour);
  param(names.frames, VBIM_FIELD(frames), "Frames (per variant)")->default_val(defaults.frames);
  // The sun given directly: either option switches to a fixed sun (the other keeps its value).
  auto sun = [&](const std::string& flags, auto field, const std::string& help) {
    CLI::Option* opt = param(flags, field, help);
    overrides.push_back({opt, [](DayCycleParams& dst) { dst.fixedSun = true; }});
    return opt;
  };
  sun("--sun-azimuth", VBIM_FIELD(sunAzimuthDeg),
      "Sun's compass azimuth in degrees (0 = north, 90 = east, clockwise), instead of place and time")
      ->default_val(defaults.sunAzimuthDeg);
  sun("--sun-elevation", VBIM_FIELD(sunElevationDeg), "Sun's elevation in degrees above the horizontal, -90..90")
      ->default_val(defaults.sunElevationDeg);
  param("--sun-diameter", VBIM_FIELD(sunDiameterDeg), "Sun's angular diameter in degrees (larger = softer shadows)")
      ->default_val(defaults.sunDiameterDeg);
  flag("--shadow-rays", VBIM_FIELD(shadowRays),
       "Shadows along each texel's own ray, right at every azimuth (the default)");
  bind(cmd->add_flag_callback(
           "--no-shadow-rays", [source] { source->shadowRays = false; },
           "Shadows along each texel's sheared sweep line instead (cheaper; over-shadows at oblique azimuths)"),
       VBIM_FIELD(shadowRays));
  flag("--exact-disc", VBIM_FIELD(exactDisc),
       "Occlude the sun by visible disc area instead of the article's linear ramp");
  param("--turbidity", VBIM_FIELD(turbidity), "Atmospheric turbidity (Preetham; 2-6)")->default_val(defaults.turbidity);
  param("--sky-patches", VBIM_FIELD(skyPatches), "Sky patches, 1..8")->default_val(defaults.skyPatches);
  param("--sky-directions", VBIM_FIELD(skyDirections), "Sky-factor directions: 8 (the article's), 16 or 32")
      ->default_val(defaults.skyDirections);
  param(names.exposure, VBIM_FIELD(exposureKlux), "Irradiance in klux that maps to 1.0")
      ->default_val(defaults.exposureKlux);
  flag("--multiply-albedo", VBIM_FIELD(multiplyAlbedo),
       "Multiply the lightmap by the colour map (as the article does)");
  param("--sky-width", VBIM_FIELD(skyWidth), "Sky dome width, multiple of 32 (height = width / 2)")
      ->default_val(defaults.skyWidth);
  flag("--clouds", VBIM_FIELD(clouds.enabled), "Moving procedural cloud shadows");
  param("--cloud-coverage", VBIM_FIELD(clouds.coverage), "Cloud coverage 0..1")->default_val(defaults.clouds.coverage);
  param("--moon-irradiance", VBIM_FIELD(moonIrradiance), "Moonlight, normalised (1.0 = " + names.exposure + ")")
      ->default_val(defaults.moonIrradiance);
#undef VBIM_FIELD
  CLI::Option* moon = cmd->add_flag("--no-moon", noMoon, "No moonlight at night");
  added(moon);
  bool* off = &noMoon;
  overrides.push_back({moon, [off](DayCycleParams& dst) { dst.moon = !*off; }});
}

void applyGivenLightingOptions(const LightingOverrides& overrides, DayCycleParams& params) {
  for (const auto& [opt, apply] : overrides)
    if (opt->count() > 0) apply(params);
}

}  // namespace vbim::cli
