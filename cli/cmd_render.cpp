// vbim render: the frames a `vbim play` run saved, rendered as the terrain lit by the streamed
// lightmap and sky with hemisphere-lit objects (render/), plus a contact sheet of the day and an
// MPEG-4 video of the playback (docs/render.md).
#include <iostream>
#include <memory>

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "cli/progress.hpp"
#include "render/error.hpp"
#include "render/render_run.hpp"
#include "runs/output_dir.hpp"

namespace vbim::cli {

namespace {

struct RenderOptions {
  std::string run, out, camera;
  render::RunRequestOptions request;  // the options a request is made of (render/run_request.hpp)
  bool force = false;
  bool noObjects = false;
  bool noVideo = false;
};

void runRender(RenderOptions& o) {
  using namespace vbim::render;
  if (!o.camera.empty()) o.request.values.settings.camera = parseCamera(o.camera);
  o.request.values.settings.objects = !o.noObjects;
  o.request.values.video = !o.noVideo;
  const player::RunDir run = player::readRunDir(o.run);
  const RunRenderRequest req = requestForRun(
      run, o.request, [](const std::string& note) { std::cerr << "vbim render: note: " << note << "\n"; });
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
  cmd->add_option("run", o->run, "A `vbim play --every N --out RUN_DIR` directory")
      ->required()
      ->check(inputDirectory());
  cmd->add_option("-o,--out", o->out, "Output directory (written complete or not at all)")->required();
  cmd->add_option("--camera", o->camera,
                  "EX,EZ,EH,TX,TZ: eye east/south in metres, eye height above ground, target east/south "
                  "(default: from the south-east valley towards the north-west mountains)");
  cmd->add_option("--width", o->request.values.settings.width, "Picture width")->capture_default_str();
  cmd->add_option("--height", o->request.values.settings.height, "Picture height")->capture_default_str();
  cmd->add_option("--fov", o->request.values.settings.fovDeg, "Vertical field of view, degrees")->capture_default_str();
  cmd->add_option("--exposure", o->request.values.settings.exposure, "Display scale on stream units")
      ->capture_default_str();
  cmd->add_option("--haze", o->request.values.settings.hazeDistance, "Haze distance in metres (0: 1.5 x the map)");
  cmd->add_option("--lod-distance", o->request.values.settings.lodDistance,
                  "Metres to the first LOD step (0: 1.5 patches)");
  cmd->add_option(
      "--terrain", o->request.terrain,
      "Heightfield the stream was authored from (default: the run's authoring.json, else the procedural one)");
  cmd->add_option("--albedo", o->request.albedo, "Colour map of the heightfield's size");
  CLI::Option* cellSize = cmd->add_option("--cell-size", o->request.values.terrain.cellSize,
                                          "Metres between heightfield samples (a DEM's own unless given)")
                              ->capture_default_str();
  CLI::Option* verticalScale =
      cmd->add_option("--vertical-scale", o->request.values.terrain.verticalScale,
                      "Heightfield metres at full scale (integer pictures); a multiplier for float ones and DEMs")
          ->capture_default_str();
  CLI::Option* relief = cmd->add_option("--relief", o->request.values.terrain.procedural.reliefMetres,
                                        "Procedural terrain relief, metres")
                            ->capture_default_str();
  CLI::Option* terrainSeed =
      cmd->add_option("--terrain-seed", o->request.values.terrain.procedural.seed, "Procedural terrain seed")
          ->capture_default_str();
  cmd->add_option(
         "--lighting-config", o->request.lightingConfig,
         "lighting.* TOML over the day (default: the run's authoring.json, else a 24-frame day from 0 to 24 h)")
      ->check(inputFile());
  CLI::Option* loopFrame =
      cmd->add_option("--loop-frame", o->request.values.loopFrame, "The stream's loop frame")->capture_default_str();
  cmd->add_option("--fps", o->request.values.videoFps, "Video frame rate")->capture_default_str();
  cmd->add_flag("--no-objects", o->noObjects, "Terrain and sky only");
  cmd->add_flag("--no-video", o->noVideo, "Skip playback.mp4");
  cmd->add_flag("--force", o->force, "Replace a non-empty output directory");
  cmd->footer(
      "Examples:\n"
      "  vbim render run/ --out pictures/\n"
      "  (run/ written by: vbim play streams/samples/day_clear.vbim --every 300 --out run/)\n");
  cmd->callback([o, cellSize, verticalScale, relief, terrainSeed, loopFrame] {
    // The terrain is read as `vbim author` read it: a DEM's cell size, a float file's heights unless given.
    o->request.values.terrain.cellSizeGiven = cellSize->count() > 0;
    o->request.values.terrain.verticalScaleGiven = verticalScale->count() > 0;
    // Given options win over the run's authoring record.
    o->request.cellSize = cellSize->count() > 0;
    o->request.verticalScale = verticalScale->count() > 0;
    o->request.relief = relief->count() > 0;
    o->request.terrainSeed = terrainSeed->count() > 0;
    o->request.loopFrame = loopFrame->count() > 0;
    runRender(*o);
  });
}

}  // namespace vbim::cli
