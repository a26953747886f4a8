#include "runs/replay_json.hpp"

#include <nlohmann/json.hpp>

#include "player/frame_hash.hpp"
#include "runs/play_json.hpp"

namespace vbim::runs {

using Json = nlohmann::ordered_json;

std::vector<LateArrival> lateOrUnshown(const player::Replay& replay, const player::ArrivalLog& log,
                                       const ReplayFacts& facts) {
  std::vector<LateArrival> out;
  for (const player::ReplayArrival& a : log.arrivals) {
    if (a.vsync >= facts.vsyncs) continue;  // after the replay's end
    LateArrival l{a, replay.dueVsync(a.seq)};
    l.late = a.vsync > l.dueVsync;
    l.neverShown = l.dueVsync < facts.vsyncs && facts.shown.count({a.sky, a.variant, a.seq}) == 0;
    if (l.late || l.neverShown) out.push_back(l);
  }
  return out;
}

namespace {

Json orNull(const std::string& s) {
  return s.empty() ? Json(nullptr) : Json(s);
}

Json orNull(std::int64_t v, bool known) {
  return known ? Json(v) : Json(nullptr);
}

// What a presenter showed at the vsync of the first difference: the frame due, its target and where
// and when the target arrived (as the text's indented lines under "first difference").
Json presenterJson(const player::Replay& replay, bool sky, const gs::VsyncRecord& r, std::int64_t vsync) {
  Json j{{"due_frame", r.dueSeq}, {"target_frame", orNull(r.targetSeq, r.targetSeq >= 0)}};
  if (r.targetSeq >= 0) {
    const player::ReplayArrival* a = replay.arrivalOf(sky, r.variant, r.targetSeq);
    const std::int64_t due = replay.dueVsync(r.targetSeq);
    j["variant"] = r.variant;
    j["fix"] = r.fix;
    j["copied_in"] = r.snapped;
    j["target_arrived_vsync"] = orNull(a != nullptr ? a->vsync : 0, a != nullptr);
    j["target_arrival_line"] = orNull(a != nullptr ? a->line : 0, a != nullptr);
    j["target_due_vsync"] = due;
    j["target_late_vsyncs"] = orNull(a != nullptr ? std::max<std::int64_t>(0, a->vsync - due) : 0, a != nullptr);
  }
  j["behind"] = r.behind;
  if (r.behind) {
    // The due frame arrives after this vsync, or not at all (null).
    const player::ReplayArrival* d = replay.arrivalOf(sky, r.variant, r.dueSeq);
    const bool later = d != nullptr && d->vsync > vsync;
    j["due_frame_arrives_vsync"] = orNull(later ? d->vsync : 0, later);
  }
  return j;
}

Json compareJson(const player::Replay& replay, const ReplayFacts& f, const player::ExpectedHashes& e) {
  Json j{{"with", e.origin},
         {"equal", !f.firstDifference.has_value()},
         {"vsyncs_compared", std::min<std::int64_t>(f.vsyncs, static_cast<std::int64_t>(e.hashes.size()))},
         {"expected_vsyncs", e.hashes.size()}};
  if (!f.firstDifference) {
    j["first_difference"] = nullptr;
    return j;
  }
  const player::VsyncRow& row = *f.firstDifference;
  const auto v = static_cast<std::size_t>(row.vsync);
  const bool listed = v < e.hashes.size();
  j["first_difference"] = Json{{"vsync", row.vsync},
                               {"time_s", toSeconds(row.at)},
                               {"replay_hash", player::hashHex(row.hash)},
                               {"expected_hash", listed ? Json(player::hashHex(e.hashes[v])) : Json(nullptr)},
                               {"expected_line", listed ? Json(v + 1) : Json(nullptr)},
                               {"lightmap", presenterJson(replay, false, row.lightmap, row.vsync)},
                               {"sky", row.sky ? presenterJson(replay, true, *row.sky, row.vsync) : Json(nullptr)}};
  return j;
}

}  // namespace

std::string replaySummaryJson(const ReplayRequest& r, const player::Replay& replay, const player::ArrivalLog& log,
                              const ReplayFacts& facts, const std::optional<player::ExpectedHashes>& expected,
                              bool& replaced) {
  Json j;
  j["stream"] = Json{{"path", r.stream}, {"file", orNull(facts.fileOnDisc)}};
  Json warnings = Json::array();
  for (const std::string& w : log.warnings) warnings.push_back(w);
  j["arrivals"] = Json{{"path", r.arrivals},
                       {"rows", log.arrivals.size()},
                       {"end_row_vsyncs", log.vsyncs ? Json(*log.vsyncs) : Json(nullptr)},
                       {"warnings", std::move(warnings)}};
  j["frames_from"] = orNull(r.frames);
  j["config"] = orNull(r.config);
  j["policy"] = facts.policy;
  j["vsyncs"] = facts.vsyncs;
  j["missing_pictures"] = replay.missingPictures();
  Json late = Json::array();
  for (const LateArrival& l : lateOrUnshown(replay, log, facts)) {
    late.push_back(Json{{"line", l.arrival.line},
                        {"stream", l.arrival.sky ? "sky" : "lightmap"},
                        {"variant", l.arrival.variant},
                        {"frame", l.arrival.seq},
                        {"arrived_vsync", l.arrival.vsync},
                        {"due_vsync", l.dueVsync},
                        {"late_vsyncs", l.late ? l.arrival.vsync - l.dueVsync : 0},
                        {"never_shown", l.neverShown}});
  }
  j["late_or_unshown"] = std::move(late);
  j["output"] = Json{{"directory", r.out},
                     {"images_written", facts.imagesWritten},
                     {"format", r.format},
                     {"alpha", r.alpha},
                     {"every", r.every}};
  j["compare"] = expected ? compareJson(replay, facts, *expected) : Json(nullptr);
  return jsonText(j, replaced);
}

}  // namespace vbim::runs
