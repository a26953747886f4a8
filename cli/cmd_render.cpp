// vbim render: the frames a `vbim play` run saved, rendered as the terrain lit by the streamed
// lightmap and sky with hemisphere-lit objects (render/), plus a contact sheet of the day and an
// MPEG-4 video of the playback (docs/render.md).
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "cli/progress.hpp"
#include "render/error.hpp"
#include "render/render_run.hpp"
#include "runs/output_dir.hpp"

namespace vbim::cli {

namespace {

struct RenderOptions {
  std::string run, out, camera, terrain, albedo, lightingConfig;
  render::RunRenderRequest req;
  bool force = false;
  bool noObjects = false;
  bool noVideo = false;
  CLI::App* cmd = nullptr;  // to tell options given from defaults
};

// The request: the run's authoring record when it has one, else the defaults; options given on the
// command line win either way.
render::RunRenderRequest requestFor(const RenderOptions& o, const player::RunDir& run) {
  using namespace vbim::render;
  RunRenderRequest req = o.req;  // every option, given or default
  // A record from image files or the synthetic generator (cmd_author.cpp) holds no terrain to light.
  const auto record = run.authoring ? nlohmann::json::parse(*run.authoring, nullptr, false) : nlohmann::json();
  const std::string source = record.is_object() ? record.value("source", std::string()) : std::string();
  if (run.authoring && (source == "synthetic" || source == "image-sequence") && !record.contains("terrain")) {
    std::cerr << "vbim render: note: " << run.path.string() << "/authoring.json records a stream made from " << source
              << " frames, with no terrain: assuming the procedural "
              << "terrain at the lightmap's size with 20 m cells and a 24-frame day from 0 h to 24 h; --terrain, "
              << "--cell-size and --lighting-config set them\n";
  } else if (run.authoring) {
    applyAuthoring(*run.authoring, (run.path / "authoring.json").string(), req);
    const auto given = [&](const char* name) { return o.cmd->get_option(name)->count() > 0; };
    if (given("--cell-size")) req.terrain.cellSize = o.req.terrain.cellSize;
    if (given("--vertical-scale")) req.terrain.verticalScale = o.req.terrain.verticalScale;
    if (given("--relief")) req.terrain.procedural.reliefMetres = o.req.terrain.procedural.reliefMetres;
    if (given("--terrain-seed")) req.terrain.procedural.seed = o.req.terrain.procedural.seed;
    if (given("--loop-frame")) req.loopFrame = o.req.loopFrame;
  } else {
    std::cerr << "vbim render: note: " << run.path.string() << " has no authoring.json (its stream carried no "
              << "authoring record): assuming the procedural terrain at the lightmap's size with 20 m cells and a "
              << "24-frame day from 0 h to 24 h; --terrain, --cell-size and --lighting-config set them\n";
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

void runRender(RenderOptions& o) {
  using namespace vbim::render;
  if (!o.camera.empty()) o.req.settings.camera = parseCamera(o.camera);
  o.req.settings.objects = !o.noObjects;
  o.req.video = !o.noVideo;
  const player::RunDir run = player::readRunDir(o.run);
  const RunRenderRequest req = requestFor(o, run);
  runs::OutputDir dir(o.out, o.force);
  Progress progress("vbim render", "frames");
  const RunRenderResult r =
      renderRun(run, req, dir.path(""), [&progress](int done, int total) { progress.show(done, total); });
  progress.finish();
  dir.commit();
  std::cout << "rendered " << r.frames << " frame(s) of " << o.run << " with " << r.context << " ("
            << static_cast<int>(r.secondsPerFrame * 1000) << " ms/frame)\n"
            << "  " << dir.finalPath().string() << "/frames/render_NNNNNN.png\n"
            << "  " << dir.finalPath().string() << "/contact_sheet.png   (red frame: stall, orange: catch-up)\n";
  if (req.video) std::cout << "  " << dir.finalPath().string() << "/playback.mp4\n";
}

}  // namespace

void addRender(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  auto* cmd = app.add_subcommand(kRenderCommand.name, kRenderCommand.summary);
  o->cmd = cmd;
  cmd->add_option("run", o->run, "A `vbim play --every N --out RUN_DIR` directory")
      ->required()
      ->check(inputDirectory());
  cmd->add_option("-o,--out", o->out, "Output directory (written complete or not at all)")->required();
  cmd->add_option("--camera", o->camera,
                  "EX,EZ,EH,TX,TZ: eye east/south in metres, eye height above ground, target east/south "
                  "(default: from the south-east valley towards the north-west mountains)");
  cmd->add_option("--width", o->req.settings.width, "Picture width")->capture_default_str();
  cmd->add_option("--height", o->req.settings.height, "Picture height")->capture_default_str();
  cmd->add_option("--fov", o->req.settings.fovDeg, "Vertical field of view, degrees")->capture_default_str();
  cmd->add_option("--exposure", o->req.settings.exposure, "Display scale on stream units")->capture_default_str();
  cmd->add_option("--haze", o->req.settings.hazeDistance, "Haze distance in metres (0: 1.5 x the map)");
  cmd->add_option("--lod-distance", o->req.settings.lodDistance, "Metres to the first LOD step (0: 1.5 patches)");
  cmd->add_option(
      "--terrain", o->terrain,
      "Heightfield the stream was authored from (default: the run's authoring.json, else the procedural one)");
  cmd->add_option("--albedo", o->albedo, "Colour map of the heightfield's size");
  CLI::Option* cellSize = cmd->add_option("--cell-size", o->req.terrain.cellSize,
                                          "Metres between heightfield samples (a DEM's own unless given)")
                              ->capture_default_str();
  CLI::Option* verticalScale =
      cmd->add_option("--vertical-scale", o->req.terrain.verticalScale,
                      "Heightfield metres at full scale (integer pictures); a multiplier for float ones and DEMs")
          ->capture_default_str();
  cmd->add_option("--relief", o->req.terrain.procedural.reliefMetres, "Procedural terrain relief, metres")
      ->capture_default_str();
  cmd->add_option("--terrain-seed", o->req.terrain.procedural.seed, "Procedural terrain seed")->capture_default_str();
  cmd->add_option(
         "--lighting-config", o->lightingConfig,
         "lighting.* TOML over the day (default: the run's authoring.json, else a 24-frame day from 0 to 24 h)")
      ->check(inputFile());
  cmd->add_option("--loop-frame", o->req.loopFrame, "The stream's loop frame")->capture_default_str();
  cmd->add_option("--fps", o->req.videoFps, "Video frame rate")->capture_default_str();
  cmd->add_flag("--no-objects", o->noObjects, "Terrain and sky only");
  cmd->add_flag("--no-video", o->noVideo, "Skip playback.mp4");
  cmd->add_flag("--force", o->force, "Replace a non-empty output directory");
  cmd->footer(
      "Examples:\n"
      "  vbim render run/ --out pictures/\n"
      "  (run/ written by: vbim play streams/samples/day_clear.vbim --every 300 --out run/)\n");
  cmd->callback([o, cellSize, verticalScale] {
    // The terrain is read as `vbim author` read it: a DEM's cell size, a float file's heights unless given.
    o->req.terrain.cellSizeGiven = cellSize->count() > 0;
    o->req.terrain.verticalScaleGiven = verticalScale->count() > 0;
    runRender(*o);
  });
}

}  // namespace vbim::cli
