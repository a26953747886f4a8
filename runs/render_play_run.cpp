#include "runs/render_play_run.hpp"

#include <sstream>

#include "render/camera.hpp"
#include "render/render_run.hpp"
#include "runs/output_dir.hpp"

namespace vbim::runs {

std::string renderPlayRun(const RenderPlayRequest& r, const RenderPlayObserver& observer) {
  render::RunRequestOptions options = r.options;
  if (!r.camera.empty()) options.values.settings.camera = render::parseCamera(r.camera);
  const player::RunDir run = player::readRunDir(r.run);
  const render::RunRenderRequest request = render::requestForRun(run, options, [&](const std::string& note) {
    if (observer.onNote) observer.onNote(note);
  });
  OutputDir dir(r.out, r.force);
  const render::RunRenderResult result = render::renderRun(run, request, dir.path(""), observer.onProgress);
  dir.commit();
  const std::string shown = dir.finalPath().string();
  std::ostringstream text;
  text << "rendered " << result.frames << " frame(s) of " << r.run << " with " << result.context << " ("
       << static_cast<int>(result.secondsPerFrame * 1000) << " ms/frame)\n"
       << "  " << shown << "/frames/render_NNNNNN.png\n"
       << "  " << shown << "/contact_sheet.png   (red frame: stall, orange: catch-up)\n";
  if (request.video) text << "  " << shown << "/playback.mp4\n";
  return text.str();
}

}  // namespace vbim::runs
