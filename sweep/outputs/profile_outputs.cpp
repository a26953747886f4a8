#include "sweep/outputs/profile_outputs.hpp"
#include "sweep/outputs/table.hpp"

#include "player/report.hpp"

#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

namespace vbim::sweep {

std::string fixed(double v, int decimals) {
  char b[48];
  std::snprintf(b, sizeof b, "%.*f", decimals, v);
  return b;
}

namespace {

void writeSweepCsv(const ProfileData& d, std::ostream& o) {
  o << "stream,stream_bytes,bankmax,bufmax_sectors,faults,policy,frames_shown,frames_late,frames_dropped,"
       "frames_caught_up,behind_vsyncs,pop_max,pop_max_at_s,lag_max,lag_max_at_s,ring_banks_min,ring_banks_mean,"
       "ring_banks_max,ring_underruns,drive_retries,frames_lost,health\n";
  for (const SweepRun& s : d.sweep) {
    const CaseResult& r = s.result;
    const double mean =
        r.totals.vsyncs > 0 ? static_cast<double>(r.totals.ringSum) / static_cast<double>(r.totals.vsyncs) : 0.0;
    o << csvQuote(s.stream) << "," << r.streamBytes << "," << s.ring.bankmax << "," << s.ring.bufmax << ","
      << csvQuote(s.faults) << "," << s.policy << "," << r.lightmap.framesShown << "," << r.lightmap.framesLate << ","
      << r.lightmap.framesDropped << "," << r.lightmap.framesCaughtUp << "," << r.lightmap.behindVsyncs << ","
      << r.pop.value << "," << fixed(toSeconds(r.pop.at), 6) << "," << r.totals.lag.value << ","
      << fixed(toSeconds(r.totals.lag.at), 6) << "," << r.totals.ringMin << "," << fixed(mean, 3) << ","
      << r.totals.ringMax << "," << r.ringUnderruns << "," << r.driveRetries << "," << r.framesLost << ","
      << vbim::player::runHealth(r.lightmap, r.totals).verdict << "\n";
  }
}

nlohmann::ordered_json profileJson(const ProfileData& d) {
  using nlohmann::ordered_json;
  ordered_json j;
  j["stall_search"] = {
      {"stall_at_s", toSeconds(d.search.stallAt)},
      {"max_stall_s", toSeconds(d.search.maxStall)},
      {"resolution_s", toSeconds(d.search.resolution)},
      {"settle_s", toSeconds(d.search.settle)},
      {"pop_threshold",
       d.search.popThreshold >= 0 ? nlohmann::ordered_json(d.search.popThreshold) : nlohmann::ordered_json("auto")},
      {"survives",
       "one stall of length D at stall_at, played to stall_at + D + settle: 'no-late-frame' = no "
       "lightmap frame became the target after it was due; 'pop' = largest per-vsync lightmap byte "
       "change <= pop_threshold (the first frame copied in excluded); auto = the pop maximum of the same "
       "configuration without the stall over stall_at + max_stall + settle"}};
  ordered_json streams = ordered_json::array();
  for (const auto& [name, bytes] : d.streamBytes) streams.push_back({{"name", name}, {"bytes", bytes}});
  j["streams"] = streams;
  ordered_json sweep = ordered_json::array();
  for (const SweepRun& s : d.sweep) {
    const CaseResult& r = s.result;
    sweep.push_back({{"stream", s.stream},
                     {"bankmax", s.ring.bankmax},
                     {"bufmax_sectors", s.ring.bufmax},
                     {"faults", s.faults},
                     {"policy", s.policy},
                     {"frames",
                      {{"shown", r.lightmap.framesShown},
                       {"late", r.lightmap.framesLate},
                       {"dropped", r.lightmap.framesDropped},
                       {"caught_up", r.lightmap.framesCaughtUp}}},
                     {"behind_vsyncs", r.lightmap.behindVsyncs},
                     {"pop_max", {{"value", r.pop.value}, {"at_s", toSeconds(r.pop.at)}}},
                     {"lag_max", {{"value", r.totals.lag.value}, {"at_s", toSeconds(r.totals.lag.at)}}},
                     {"ring_banks",
                      {{"min", r.totals.ringMin},
                       {"max", r.totals.ringMax},
                       {"sum", r.totals.ringSum},
                       {"vsyncs", r.totals.vsyncs}}},
                     {"ring_underruns", r.ringUnderruns},
                     {"drive_retries", r.driveRetries},
                     {"frames_lost", r.framesLost},
                     {"health", vbim::player::runHealth(r.lightmap, r.totals).verdict}});
  }
  j["sweep"] = sweep;
  ordered_json stalls = ordered_json::array();
  for (const StallRow& s : d.stalls) {
    stalls.push_back(
        {{"stream", s.stream},
         {"bankmax", s.ring.bankmax},
         {"bufmax_sectors", s.ring.bufmax},
         {"policy", s.policy},
         {"criterion", toString(s.criterion)},
         {"longest_stall_s", s.result.longest ? ordered_json(toSeconds(*s.result.longest)) : ordered_json()},
         {"pop_threshold", s.result.popThreshold >= 0 ? ordered_json(s.result.popThreshold) : ordered_json()},
         {"saturated", s.result.saturated},
         {"runs", s.result.runs}});
  }
  j["stalls"] = stalls;
  return j;
}

}  // namespace

void writeStallCsv(const std::vector<StallRow>& rows, const StallSearch& search, std::ostream& o) {
  o << "stream,bankmax,bufmax_sectors,policy,criterion,pop_threshold,stall_at_s,longest_stall_s,saturated,runs\n";
  for (const StallRow& s : rows) {
    o << csvQuote(s.stream) << "," << s.ring.bankmax << "," << s.ring.bufmax << "," << s.policy << ","
      << toString(s.criterion) << ","
      << (s.result.popThreshold >= 0 ? std::to_string(s.result.popThreshold) : std::string()) << ","
      << fixed(toSeconds(search.stallAt), 6) << ","
      << (s.result.longest ? fixed(toSeconds(*s.result.longest), 6) : std::string()) << ","
      << (s.result.saturated ? 1 : 0) << "," << s.result.runs << "\n";
  }
}

std::vector<plots::profile::TracePoint> tracePoints(const std::vector<Sample>& series) {
  std::vector<plots::profile::TracePoint> points;
  points.reserve(series.size());
  for (const Sample& s : series) points.push_back({s.t, s.ringBanks, s.lag, s.pop});
  return points;
}

std::vector<plots::profile::StallPoint> stallPoints(const std::vector<StallRow>& rows) {
  std::vector<plots::profile::StallPoint> points;
  for (const StallRow& r : rows) {
    plots::profile::StallPoint p;
    p.line = r.stream + ", " + r.policy + ", " + toString(r.criterion);
    p.ringSectors = static_cast<double>(r.ring.bufmax);
    if (r.result.longest) p.longestS = toSeconds(*r.result.longest);
    points.push_back(std::move(p));
  }
  return points;
}

plots::profile::StallSearchSetup stallSearchSetup(const StallSearch& search) {
  return {toSeconds(search.stallAt), toSeconds(search.maxStall), search.popThreshold};
}

std::vector<std::string> writeProfileOutputs(const ProfileData& d, const std::filesystem::path& dir) {
  std::vector<plots::profile::SweepTrace> sweep;
  for (const SweepRun& s : d.sweep) {
    std::vector<plots::profile::FaultInterval> faults;
    for (const player::FaultSpan& f : s.result.faults) faults.push_back({f.kind, f.beginS, f.endS});
    sweep.push_back(
        {s.stream, s.faults, s.policy, s.ring.bankmax, s.ring.bufmax, tracePoints(s.result.series), faults});
  }
  std::vector<std::string> written =
      plots::profile::writeProfileFigures(sweep, stallPoints(d.stalls), stallSearchSetup(d.search), (dir / ""));
  {
    std::ofstream o((dir / "sweep.csv"), std::ios::binary);
    writeSweepCsv(d, o);
    written.push_back("sweep.csv");
  }
  if (!d.stalls.empty()) {
    std::ofstream o((dir / "stall.csv"), std::ios::binary);
    writeStallCsv(d.stalls, d.search, o);
    written.push_back("stall.csv");
  }
  {
    std::ofstream o((dir / "profile.json"), std::ios::binary);
    o << profileJson(d).dump(2) << "\n";
    written.push_back("profile.json");
  }
  return written;
}

}  // namespace vbim::sweep
