#include "runs/play_json.hpp"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "player/report.hpp"

namespace vbim::runs {

using Json = nlohmann::ordered_json;

std::string jsonText(const Json& j, bool& replaced) {
  replaced = false;
  try {
    return j.dump(2) + "\n";
  } catch (const nlohmann::json::type_error&) {
    replaced = true;
    return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  }
}

namespace {

// A maximum and when it happened ("at_s": null when it never rose above 0).
Json extreme(const player::Extreme& e) {
  return Json{{"max", e.value}, {"at_s", e.vsync >= 0 ? Json(toSeconds(e.at)) : Json(nullptr)}};
}

Json health(const gs::PresenterCounters& lightmap, const player::RunTotals& totals) {
  const player::RunHealth h = player::runHealth(lightmap, totals);
  return Json{{"verdict", h.verdict}, {"stuck_s", toSeconds(h.stuckFor)}};
}

}  // namespace

std::string playSummaryJson(const player::Player& player, const std::string& disc, double wallSeconds,
                            double cpuSeconds, std::int64_t images, const PictureCost& pictures, bool& replaced) {
  const player::Pipeline& p = player.pipeline();
  const gs::PresenterCounters& c = p.lightmap().counters();
  const player::RunTotals& t = player.totals();
  const auto& ring = p.ring().stats();
  const double seconds = toSeconds(player.duration());
  Json j;
  j["disc"] = disc;
  j["simulated_s"] = seconds;
  j["vsyncs"] = t.vsyncs;
  j["host_s"] = wallSeconds;
  j["host_speed_x"] = seconds / std::max(wallSeconds, 1e-9);
  j["cpu_s"] = cpuSeconds;
  j["cpu_speed_x"] = seconds / std::max(cpuSeconds, 1e-9);
  j["frames"] = Json{{"shown", c.framesShown},        {"late", c.framesLate},      {"dropped", c.framesDropped},
                     {"caught_up", c.framesCaughtUp}, {"loop_wraps", c.loopWraps}, {"branches", c.branches}};
  j["pop"] = extreme(t.pop);
  j["lag"] = extreme(t.lag);
  j["reference_run"] = player.hasReference();
  // As the text summary: a fault plan that left the screen as without it.
  j["faults_changed_nothing"] = player.hasReference() && t.lag.value == 0 && c.framesLate == 0 && c.framesDropped == 0;
  j["ring"] = Json{{"underruns", ring.underruns}, {"startup_polls", ring.startupPolls}, {"seek_polls", ring.seekPolls}};
  j["drive_retries"] = p.drive().stats().retries;
  j["damaged_or_lost_frames"] = p.demux().counters().picturesDamaged + p.demux().counters().framesLost;
  j["images_written"] = images;
  if (images > 0) {
    j["pictures"] = Json{{"cpu_s", pictures.cpuSeconds},
                         {"share_of_cpu", pictures.cpuSeconds / std::max(cpuSeconds, 1e-9)},
                         {"format", pictures.format}};
  }
  j["health"] = health(c, t);
  return jsonText(j, replaced);
}

}  // namespace vbim::runs
