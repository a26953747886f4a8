#include "render/render_run.hpp"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <memory>

#include <nlohmann/json.hpp>

#include "imageio/error.hpp"
#include "imageio/image_reader.hpp"
#include "imageio/png_writer.hpp"
#include "imageio/rgba8.hpp"
#include "lighting/authoring/technique_a_stream.hpp"
#include "render/contact_sheet.hpp"
#include "render/error.hpp"
#include "render/renderer.hpp"
#include "render/scene_lighting.hpp"
#include "render/video_writer.hpp"
#include "streams/authoring/error.hpp"

namespace vbim::render {

namespace {

// Picture files through imageio, their errors as the renderer's.
Rgba8Image readFrame(const std::filesystem::path& path) {
  try {
    return imageio::readRgba8(path);
  } catch (const imageio::ImageIoError& e) {
    throw RenderError(e.what());
  }
}

void writePicture(const std::filesystem::path& path, const Rgba8Image& picture) {
  try {
    // RGB: the alpha is the GS's, meaningless in a picture file. Fast: frames are written in bulk.
    imageio::writePng(path, imageio::rgbOf(picture).view(), imageio::PngSpeed::Fast);
  } catch (const imageio::ImageIoError& e) {
    throw RenderError(e.what());
  }
}

// The simulated time of a vsync: timeline.csv's, else (no timeline) 60 vsyncs a second. Past the
// timeline's last row (the run's end), one more vsync period per vsync.
double timeOf(const player::RunDir& run, std::int64_t vsync) {
  if (run.timeline.empty()) return static_cast<double>(vsync) / 60.0;
  if (const auto it = run.timeline.find(vsync); it != run.timeline.end()) return it->second.timeSeconds;
  const auto& [lastV, lastRow] = *run.timeline.rbegin();
  const auto& [firstV, firstRow] = *run.timeline.begin();
  const double period =
      lastV > firstV ? (lastRow.timeSeconds - firstRow.timeSeconds) / static_cast<double>(lastV - firstV) : 1.0 / 60.0;
  return lastRow.timeSeconds + period * static_cast<double>(vsync - lastV);
}

// The last vsync of the run: timeline.csv's last row, else the last saved frame.
std::int64_t lastVsync(const player::RunDir& run) {
  return run.timeline.empty() ? run.frames.back().vsync : run.timeline.rbegin()->first;
}

// Late wins over waiting: a first frame that is due and has not come is late (a stall at spin-up).
Moment momentOf(const player::TimelineRow& r) {
  if (r.behind) return Moment::Late;
  if (r.catchUp) return Moment::CatchUp;
  return r.targetSeq < 0 ? Moment::Waiting : Moment::OnTime;  // target_seq -1: the GS has no frame
}

}  // namespace

RunRenderResult renderRun(const player::RunDir& run, const RunRenderRequest& req, const std::filesystem::path& outDir,
                          const RenderProgressFn& progress) {
  namespace fs = std::filesystem;
  RunRenderResult result;
  const Rgba8Image first = readFrame(run.frames.front().lightmap);

  lighting::TerrainSource source = req.terrain;
  if (source.heightfield.empty()) {
    source.procedural.cellSize = source.cellSize;
    if (req.proceduralSizeFromLightmap) {
      if (first.width != first.height) {
        throw RenderError(run.frames.front().lightmap.string() + ": the lightmap is " + std::to_string(first.width) +
                          "x" + std::to_string(first.height) +
                          " but the procedural terrain is square; give the terrain with --terrain");
      }
      source.procedural.size = first.width;
    }
  }
  lighting::Terrain terrain;
  try {
    terrain = lighting::loadTerrain(source);
  } catch (const streams::AuthoringError& e) {
    throw RenderError(e.what());
  }
  const lighting::FloatImage albedo = terrain.albedo;
  // One scene per variant the timeline shows, made when first needed (about 0.1 s each at 256x256).
  const std::vector<lighting::DayCycleParams> days =
      req.variantDays.empty() ? std::vector<lighting::DayCycleParams>{req.day} : req.variantDays;
  std::vector<std::unique_ptr<SceneLighting>> scenes(days.size());
  auto sceneOf = [&](int variant) -> SceneLighting& {
    auto& scene = scenes[static_cast<std::size_t>(variant)];
    if (!scene)
      scene = std::make_unique<SceneLighting>(terrain, days[static_cast<std::size_t>(variant)], req.loopFrame);
    return *scene;
  };
  Renderer renderer(sceneOf(0).terrain(), albedo, req.settings, req.contextFactory);
  result.context = renderer.contextDescription();

  fs::create_directories(outDir / "frames");
  std::unique_ptr<VideoWriter> video;
  if (req.video) {
    result.video = outDir / "playback.mp4";
    video = std::make_unique<VideoWriter>(result.video, req.settings.width - req.settings.width % 2,
                                          req.settings.height - req.settings.height % 2, req.videoFps);
  }

  // The video plays at the run's speed: each saved frame from its vsync's simulated time until the
  // next saved frame's, the last until the run's end (the vsync after timeline.csv's last row).
  std::vector<double> frameTimes;
  for (const player::RunFrame& f : run.frames) frameTimes.push_back(timeOf(run, f.vsync));
  const double runEnd = std::max(frameTimes.back(), timeOf(run, lastVsync(run) + 1));
  const std::vector<VideoSlot> slots =
      req.video ? videoSlots(frameTimes, runEnd, req.videoFps) : std::vector<VideoSlot>(frameTimes.size());

  // Per-vsync state and the drive's faults for the sheet.
  SheetRun sheetRun;
  if (!run.timeline.empty()) {
    sheetRun.states.assign(static_cast<std::size_t>(run.timeline.rbegin()->first + 1), Moment::OnTime);
    for (const auto& [v, row] : run.timeline) sheetRun.states[static_cast<std::size_t>(v)] = momentOf(row);
  }
  sheetRun.seconds = runEnd;
  sheetRun.faults = run.faults;
  // Tiles: at most ~48 evenly spread over the frames.
  const std::size_t n = run.frames.size();
  const std::size_t tileStep = std::max<std::size_t>(1, (n + 47) / 48);

  nlohmann::json framesJson = nlohmann::json::array();
  std::vector<SheetTile> tiles;
  std::int64_t previousTileVsync = -1;
  double previousTileTime = 0;
  double renderSeconds = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const player::RunFrame& f = run.frames[i];
    const Rgba8Image lm = i == 0 ? first : readFrame(f.lightmap);
    std::optional<Rgba8Image> sky;
    if (f.sky) sky = readFrame(*f.sky);
    // The frame the lightmap is showing or moving to; without a timeline, one frame per second.
    std::int64_t seq = f.vsync / 60;
    int variant = 0;
    const auto row = run.timeline.find(f.vsync);
    if (row != run.timeline.end()) {
      seq = row->second.targetSeq;
      variant = row->second.variant;
    }
    // Without per-variant settings, one lighting (`day`) for every frame.
    const int lit = req.variantDays.empty() ? 0 : variant;
    if (!req.variantDays.empty() && (variant < 0 || static_cast<std::size_t>(variant) >= days.size())) {
      throw RenderError((run.path / "timeline.csv").string() + ": vsync " + std::to_string(f.vsync) +
                        " shows variant " + std::to_string(variant) + ", but " + req.settingsFrom + " records " +
                        std::to_string(days.size()) + " variant(s)");
    }
    const auto t0 = std::chrono::steady_clock::now();
    FrameLight light = sceneOf(lit).evaluate(seq, lm, sky ? &*sky : nullptr);
    Rgba8Image picture = renderer.render(lm, sky ? &*sky : nullptr, light);
    renderSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    char name[64];
    std::snprintf(name, sizeof name, "render_%06lld.png", static_cast<long long>(f.vsync));
    writePicture(outDir / "frames" / name, picture);
    if (video && slots[i].shown) {
      if (picture.width % 2 != 0 || picture.height % 2 != 0) {
        Rgba8Image even(picture.width - picture.width % 2, picture.height - picture.height % 2);
        for (int y = 0; y < even.height; ++y)
          std::copy_n(picture.row(y), static_cast<std::size_t>(even.width) * 4, even.row(y));
        video->add(even, slots[i].pts, slots[i].duration);
      } else {
        video->add(picture, slots[i].pts, slots[i].duration);
      }
    }
    framesJson.push_back({{"vsync", f.vsync},
                          {"seq", seq},
                          {"variant", variant},
                          {"hour", light.hour},
                          {"stream_scale", light.streamScale},
                          {"sun_irradiance", light.sunIrradiance},
                          {"sky_irradiance", light.skyIrradiance},
                          {"triangles", renderer.stats().trianglesDrawn}});
    if (i % tileStep == 0 || i + 1 == n) {
      // Late and catch-up anywhere since the previous tile; waiting only when this tile's picture is
      // itself black (a tile after the first frame came says what the picture shows).
      Moment worst = Moment::OnTime;
      for (auto it = run.timeline.upper_bound(previousTileVsync); it != run.timeline.end() && it->first <= f.vsync;
           ++it) {
        const Moment m = momentOf(it->second);
        if (m != Moment::Waiting) worst = std::max(worst, m);
      }
      if (worst == Moment::OnTime && row != run.timeline.end() && momentOf(row->second) == Moment::Waiting)
        worst = Moment::Waiting;
      // The drive's faults since the previous tile (for the first: since the start).
      std::vector<std::string> faults;
      for (const player::FaultSpan& span : run.faults) {
        const bool overlaps = span.beginS <= frameTimes[i] && span.endS >= previousTileTime;
        if (overlaps && std::find(faults.begin(), faults.end(), span.kind) == faults.end()) faults.push_back(span.kind);
      }
      tiles.push_back(
          SheetTile{f.vsync, frameTimes[i], downscale(picture, req.sheetThumbWidth), worst, std::move(faults)});
      previousTileVsync = f.vsync;
      previousTileTime = frameTimes[i];
    }
    if (progress) progress(static_cast<int>(i + 1), static_cast<int>(n));
  }
  if (video) {
    video->finish();
    result.videoFrames = video->frames();
    for (const VideoSlot& v : slots) {
      if (v.shown) result.videoSeconds = static_cast<double>(v.pts + v.duration) / req.videoFps;
    }
  }
  result.sheet = outDir / "contact_sheet.png";
  writePicture(result.sheet, contactSheet(tiles, sheetRun, req.sheetColumns, req.sheetThumbWidth));
  result.frames = static_cast<int>(n);
  result.secondsPerFrame = renderSeconds / static_cast<double>(n);

  const CameraPlacement& c = renderer.camera();
  nlohmann::json doc = {{"run", run.path.string()},
                        {"settings_from", req.settingsFrom},
                        {"gl", result.context},
                        {"size", {req.settings.width, req.settings.height}},
                        {"camera", {c.eyeX, c.eyeZ, c.eyeHeight, c.targetX, c.targetZ}},
                        {"terrain", source.heightfield.empty() ? "procedural" : source.heightfield},
                        {"terrain_size", {terrain.width, terrain.height}},
                        {"cell_size_m", terrain.cellSize},
                        {"day",
                         {{"frames", req.day.frames},
                          {"start_hour", req.day.startHour},
                          {"end_hour", req.day.endHour},
                          {"latitude_deg", req.day.latitudeDeg},
                          {"day_of_year", req.day.dayOfYear}}},
                        {"frames", framesJson}};
  if (video) {
    doc["video"] = {{"file", "playback.mp4"},
                    {"codec", "MPEG-4 Part 2"},
                    {"clock_fps", req.videoFps},
                    {"frames", result.videoFrames},
                    {"duration_s", result.videoSeconds},
                    {"from_s", frameTimes.front()},
                    {"to_s", runEnd},
                    {"timing",
                     "the run's speed: each saved frame is shown from its simulated time until the next saved "
                     "frame's, the last until the run's end; frames closer than 1/clock_fps s to the one before "
                     "are left out"}};
  }
  std::ofstream(outDir / "render.json") << doc.dump(1) << "\n";
  return result;
}

}  // namespace vbim::render
