#include "runs/demo_run.hpp"

#include <unistd.h>

#include <filesystem>
#include <utility>

#include "iop/fault_plan.hpp"
#include "lighting/authoring/sample_day.hpp"
#include "lighting/authoring/terrain_author.hpp"
#include "player/run_dir_reader.hpp"
#include "render/error.hpp"
#include "render/render_run.hpp"
#include "runs/error.hpp"
#include "sweep/outputs/demo_profile.hpp"

namespace vbim::runs {

namespace fs = std::filesystem;

// The sample's whole 75 sectors fit in the EE's buffers after a few seconds, so the stall starts
// early, during the spin-up, before the first frames arrive.
const char* const kDemoFaults = R"(# vbim demo: built-in fault plan
[[fault]]
kind = "stall"          # the drive freezes before the stream has been read: the lightmap falls behind
at = "200ms"
duration = "6s"

[[fault]]
kind = "read_error"     # a scratched sector in the stream file: drive retries, then the ring's run-up retries
lba = 2090              # file sector 42 (the bare file lies at LBA 2048)
attempts = 300
)";

namespace {

// The authored stream beside the output, until it is copied in at the commit.
struct RemovedAtEnd {
  fs::path path;
  explicit RemovedAtEnd(fs::path p) : path(std::move(p)) {}
  RemovedAtEnd(const RemovedAtEnd&) = delete;
  RemovedAtEnd& operator=(const RemovedAtEnd&) = delete;
  ~RemovedAtEnd() {
    std::error_code ec;
    fs::remove(path, ec);
  }
};

}  // namespace

PlayRequest demoRequest() {
  PlayRequest r;
  r.out = "out/demo";
  r.duration = "60s";         // past the sample day's end: loop wraps (24 frames: at 24.5 s and 44.5 s)
  r.every = 240;              // about every 4 s: a rendered day on the contact sheet
  r.at = {"6s", "7s", "8s"};  // the catch-up after the stall
  r.seed = 1;
  return r;
}

DemoResult demoRun(PlayRequest r, const std::function<void(const std::string& line)>& say,
                   const PlayProgressFn& onSecond, const std::function<void()>& checkStop) {
  // The authored stream goes beside the output first and into it with the rest at commit.
  const fs::path out = outputPath(r.out);
  refuseExistingOutputDir(out, r.force);  // before minutes of work, not after
  const fs::path parent = out.has_parent_path() ? out.parent_path() : fs::path(".");
  fs::create_directories(parent);
  const RemovedAtEnd stream{parent / ("." + out.filename().string() + ".day-" + std::to_string(::getpid()) + ".vbim")};
  say("vbim demo: authoring a day cycle from the procedural terrain (Technique A)\n");
  // The sample's recipe, so that the demo's stream and the committed sample cannot drift apart (a
  // test checks they are byte-identical).
  const lighting::TechniqueAStreamSettings recipe = lighting::sampleDaySettings();
  // Named as it is kept in the output (day.vbim), never by its temporary name: the summary and
  // stats.json's run.disc.path are the same on every run.
  r.disc = stream.path.string();
  r.discLabel = "day.vbim";
  say(lighting::authoredSummary((out / r.discLabel).string(), lighting::authorTechniqueA(recipe, stream.path),
                                recipe.stream.encoder.containerFps));
  if (iop::parseDuration(r.duration) <= fromMs(8'000)) r.at.clear();  // the catch-up shots lie past a short run
  r.faultsText = kDemoFaults;
  say("vbim demo: playing it with a 6 s drive stall at 0.2 s, a read error at LBA 2090 and loop wraps\n");
  sweep::DemoProfile prof;
  DemoResult result;
  r.onRow = [&prof](const player::VsyncRow& row) { prof.onRow(row); };
  r.beforeCommit = [&](const OutputDir& dir) {
    prof.write(r.disc, dir.directory(), checkStop);
    std::error_code ec;
    fs::copy_file(stream.path, dir.path("day.vbim"), fs::copy_options::overwrite_existing, ec);
    if (ec) throw Error(dir.path("day.vbim").string() + ": cannot copy the authored stream: " + ec.message());
    fs::create_directories(dir.path("render"));
    try {
      // The terrain and day the stream was authored with, from the record play copied.
      player::RunDir run = player::readRunDir(dir.path(""));
      run.path = "..";  // render.json names the run as seen from render/, not the temporary directory
      render::RunRenderRequest request;
      if (run.authoring) render::applyAuthoring(*run.authoring, "authoring.json", request);
      const render::RunRenderResult rendered =
          render::renderRun(run, request, dir.path("render"), [&checkStop](int, int) {
            if (checkStop) checkStop();
          });
      result.renderedFrames = rendered.frames;
      result.renderContext = rendered.context;
    } catch (const render::RenderError& e) {
      throw RunFailure(std::string("rendering failed: ") + e.what());
    }
  };
  result.play = playRun(r, onSecond);
  result.profileSeconds = prof.seconds();
  return result;
}

}  // namespace vbim::runs
