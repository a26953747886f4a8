// vbim render: the frames a `vbim play` run saved, rendered as the terrain lit by the streamed
// lightmap and sky with hemisphere-lit objects (render/), plus a contact sheet of the day and an
// MPEG-4 video of the playback (docs/render.md): runs::renderPlayRun (runs/render_play_run.hpp).
#include <iostream>
#include <memory>

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "cli/progress.hpp"
#include "runs/render_play_run.hpp"

namespace vbim::cli {

namespace {

struct RenderOptions {
  runs::RenderPlayRequest request;
  bool noObjects = false;
  bool noVideo = false;
};

void runRender(RenderOptions& o) {
  o.request.options.values.settings.objects = !o.noObjects;
  o.request.options.values.video = !o.noVideo;
  runs::RenderPlayObserver observer;
  observer.onNote = [](const std::string& note) { std::cerr << "vbim render: note: " << note << "\n"; };
  Progress progress("vbim render", "frames");
  observer.onProgress = [&progress](int done, int total) { progress.show(done, total); };
  const std::string summary = runs::renderPlayRun(o.request, observer);
  progress.finish();
  std::cout << summary;
}

}  // namespace

void addRender(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  auto* cmd = app.add_subcommand(kRenderCommand.name, kRenderCommand.summary);
  render::RunRequestOptions& options = o->request.options;  // lives in `o`, as long as the app
  render::RenderSettings& view = options.values.settings;
  cmd->add_option("run", o->request.run, "A `vbim play --every N --out RUN_DIR` directory")
      ->required()
      ->check(inputDirectory());
  cmd->add_option("-o,--out", o->request.out, "Output directory (written complete or not at all)")->required();
  cmd->add_option("--camera", o->request.camera,
                  "EX,EZ,EH,TX,TZ: eye east/south in metres, eye height above ground, target east/south "
                  "(default: from the south-east valley towards the north-west mountains)");
  cmd->add_option("--width", view.width, "Picture width")->capture_default_str();
  cmd->add_option("--height", view.height, "Picture height")->capture_default_str();
  cmd->add_option("--fov", view.fovDeg, "Vertical field of view, degrees")->capture_default_str();
  cmd->add_option("--exposure", view.exposure, "Display scale on stream units")->capture_default_str();
  cmd->add_option("--haze", view.hazeDistance, "Haze distance in metres (0: 1.5 x the map)");
  cmd->add_option("--lod-distance", view.lodDistance, "Metres to the first LOD step (0: 1.5 patches)");
  cmd->add_option(
      "--terrain", options.terrain,
      "Heightfield the stream was authored from (default: the run's authoring.json, else the procedural one)");
  cmd->add_option("--albedo", options.albedo, "Colour map of the heightfield's size");
  CLI::Option* cellSize = cmd->add_option("--cell-size", options.values.terrain.cellSize,
                                          "Metres between heightfield samples (a DEM's own unless given)")
                              ->capture_default_str();
  CLI::Option* verticalScale =
      cmd->add_option("--vertical-scale", options.values.terrain.verticalScale,
                      "Heightfield metres at full scale (integer pictures); a multiplier for float ones and DEMs")
          ->capture_default_str();
  CLI::Option* relief =
      cmd->add_option("--relief", options.values.terrain.procedural.reliefMetres, "Procedural terrain relief, metres")
          ->capture_default_str();
  CLI::Option* terrainSeed =
      cmd->add_option("--terrain-seed", options.values.terrain.procedural.seed, "Procedural terrain seed")
          ->capture_default_str();
  cmd->add_option(
         "--lighting-config", options.lightingConfig,
         "lighting.* TOML over the day (default: the run's authoring.json, else a 24-frame day from 0 to 24 h)")
      ->check(inputFile());
  CLI::Option* loopFrame =
      cmd->add_option("--loop-frame", options.values.loopFrame, "The stream's loop frame")->capture_default_str();
  cmd->add_option("--fps", options.values.videoFps, "Video frame rate")->capture_default_str();
  cmd->add_flag("--no-objects", o->noObjects, "Terrain and sky only");
  cmd->add_flag("--no-video", o->noVideo, "Skip playback.mp4");
  cmd->add_flag("--force", o->request.force, "Replace a non-empty output directory");
  cmd->footer(
      "Examples:\n"
      "  vbim render run/ --out pictures/\n"
      "  (run/ written by: vbim play streams/samples/day_clear.vbim --every 300 --out run/)\n");
  cmd->callback([o, cellSize, verticalScale, relief, terrainSeed, loopFrame] {
    render::RunRequestOptions& options = o->request.options;
    // The terrain is read as `vbim author` read it: a DEM's cell size, a float file's heights unless given.
    options.values.terrain.cellSizeGiven = cellSize->count() > 0;
    options.values.terrain.verticalScaleGiven = verticalScale->count() > 0;
    // Given options win over the run's authoring record.
    options.cellSize = cellSize->count() > 0;
    options.verticalScale = verticalScale->count() > 0;
    options.relief = relief->count() > 0;
    options.terrainSeed = terrainSeed->count() > 0;
    options.loopFrame = loopFrame->count() > 0;
    runRender(*o);
  });
}

}  // namespace vbim::cli
