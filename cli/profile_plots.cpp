#include "cli/profile_plots.hpp"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

namespace vbim::cli::profile {

namespace {

std::string fixed(double v, int decimals) {
  char b[48];
  std::snprintf(b, sizeof b, "%.*f", decimals, v);
  return b;
}

std::string ringLabel(const RingSize& r) {
  return std::to_string(r.bufmax) + " sectors (" + std::to_string(r.bankmax) + " banks)";
}

// A file-name-safe version of a label.
std::string safe(const std::string& s) {
  std::string o;
  for (char c : s) o += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
  return o;
}

std::string csvQuote(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string o = "\"";
  for (char c : s) o += c == '"' ? std::string("\"\"") : std::string(1, c);
  return o + "\"";
}

void writeSweepCsv(const ProfileData& d, std::ostream& o) {
  o << "stream,stream_bytes,bankmax,bufmax_sectors,faults,policy,frames_shown,frames_late,frames_dropped,"
       "frames_caught_up,behind_vsyncs,pop_max,pop_max_at_s,lag_max,lag_max_at_s,ring_banks_min,ring_banks_mean,"
       "ring_banks_max,ring_underruns,drive_retries,frames_lost\n";
  for (const SweepRun& s : d.sweep) {
    const CaseResult& r = s.result;
    const double mean =
        r.totals.vsyncs > 0 ? static_cast<double>(r.totals.ringSum) / static_cast<double>(r.totals.vsyncs) : 0.0;
    o << csvQuote(s.stream) << "," << r.streamBytes << "," << s.ring.bankmax << "," << s.ring.bufmax << ","
      << csvQuote(s.faults) << "," << s.policy << "," << r.lightmap.framesShown << "," << r.lightmap.framesLate << ","
      << r.lightmap.framesDropped << "," << r.lightmap.framesCaughtUp << "," << r.lightmap.behindVsyncs << ","
      << r.pop.value << "," << fixed(toSeconds(r.pop.at), 6) << "," << r.totals.lag.value << ","
      << fixed(toSeconds(r.totals.lag.at), 6) << "," << r.totals.ringMin << "," << fixed(mean, 3) << ","
      << r.totals.ringMax << "," << r.ringUnderruns << "," << r.driveRetries << "," << r.framesLost << "\n";
  }
}

void writeStallCsv(const ProfileData& d, std::ostream& o) {
  o << "stream,bankmax,bufmax_sectors,policy,criterion,pop_threshold,stall_at_s,longest_stall_s,saturated,runs\n";
  for (const StallRow& s : d.stalls) {
    o << csvQuote(s.stream) << "," << s.ring.bankmax << "," << s.ring.bufmax << "," << s.policy << ","
      << toString(s.criterion) << ","
      << (s.result.popThreshold >= 0 ? std::to_string(s.result.popThreshold) : std::string()) << ","
      << fixed(toSeconds(d.search.stallAt), 6) << ","
      << (s.result.longest ? fixed(toSeconds(*s.result.longest), 6) : std::string()) << ","
      << (s.result.saturated ? 1 : 0) << "," << s.result.runs << "\n";
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
                     {"frames_lost", r.framesLost}});
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

void writePlot(const plot::Figure& f, const OutputDir& dir, const std::string& name, std::vector<std::string>& out) {
  if (!plot::writePng(f, dir.path(name)))
    std::cerr << "warning: no TrueType font found; " << name << " has no labels\n";
  out.push_back(name);
}

}  // namespace

plot::Figure occupancyFigure(const std::string& title, const std::vector<NamedSeries>& runs) {
  plot::Figure f;
  f.title = title;
  f.panelHeight = 360;
  plot::Panel p;
  p.title = "Stream ring occupancy";
  p.yLabel = "% of the ring readable";
  p.xLabel = "simulated time (s)";
  p.yMin = 0;
  p.yMax = 105;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    plot::Series s;
    s.name = runs[i].name;
    s.color = plot::paletteColor(i);
    s.step = true;
    s.thickness = 2;
    const double banks = static_cast<double>(std::max<std::int64_t>(runs[i].ring.bankmax, 1));
    for (const Sample& v : *runs[i].series) {
      s.x.push_back(v.t);
      s.y.push_back(100.0 * v.ringBanks / banks);
    }
    p.series.push_back(std::move(s));
  }
  f.panels.push_back(std::move(p));
  return f;
}

plot::Figure lagPopFigure(const std::string& title, const std::vector<NamedSeries>& runs, int popThreshold) {
  plot::Figure f;
  f.title = title;
  plot::Panel lag, pop, behind;
  lag.title = "Lag: largest per-byte difference from the fault-free run";
  lag.yLabel = "lag (8-bit levels)";
  lag.xLabel = "simulated time (s)";
  pop.title = "Pop: largest per-byte change of the lightmap in one vsync";
  pop.yLabel = "pop (8-bit levels)";
  pop.xLabel = "simulated time (s)";
  if (popThreshold >= 0)
    pop.refLines.push_back(plot::RefLine{"threshold " + std::to_string(popThreshold), double(popThreshold)});
  for (std::size_t i = 0; i < runs.size(); ++i) {
    plot::Series l, p;
    l.name = p.name = runs[i].name;
    l.color = p.color = plot::paletteColor(i);
    l.thickness = 2;
    for (const Sample& v : *runs[i].series) {
      l.x.push_back(v.t);
      l.y.push_back(v.lag);
      p.x.push_back(v.t);
      p.y.push_back(v.pop);
    }
    lag.series.push_back(std::move(l));
    pop.series.push_back(std::move(p));
  }
  f.panels.push_back(std::move(lag));
  f.panels.push_back(std::move(pop));
  return f;
}

plot::Figure stallFigure(const std::string& title, const std::vector<StallRow>& rows, const StallSearch& search) {
  plot::Figure f;
  f.title = title;
  f.panelHeight = 420;
  plot::Panel p;
  p.title = "Longest drive stall survived (stall at " + fixed(toSeconds(search.stallAt), 1) + " s; pop threshold " +
            (search.popThreshold >= 0 ? std::to_string(search.popThreshold) : std::string("auto")) + ")";
  p.yLabel = "longest stall (s)";
  p.xLabel = "stream ring size (sectors of 2 KiB, log scale)";
  p.xLog2 = true;
  p.refLines.push_back(plot::RefLine{
      "search limit " + fixed(toSeconds(search.maxStall), 0) + " s", toSeconds(search.maxStall), {0.6f, 0.6f, 0.6f}});
  std::map<std::string, plot::Series> lines;  // by stream / policy / criterion, in first-seen order below
  std::vector<std::string> order;
  for (const StallRow& r : rows) {
    const std::string key = r.stream + ", " + r.policy + ", " + toString(r.criterion);
    if (!lines.count(key)) {
      order.push_back(key);
      plot::Series& s = lines[key];
      s.name = key;
      s.color = plot::paletteColor(order.size() - 1);
      s.markers = true;
      s.thickness = 2;
    }
    if (!r.result.longest) continue;  // fails without a stall: no point
    lines[key].x.push_back(static_cast<double>(r.ring.bufmax));
    lines[key].y.push_back(toSeconds(*r.result.longest));
  }
  // Lines that coincide (common: criteria and policies often agree) stay visible as nested
  // stripes: the first drawn is the widest.
  for (std::size_t i = 0; i < order.size(); ++i) {
    plot::Series& s = lines[order[i]];
    s.thickness = 2 + 3 * static_cast<int>(order.size() - 1 - i);
    p.series.push_back(std::move(s));
  }
  f.panels.push_back(std::move(p));
  return f;
}

std::vector<std::string> writeProfileOutputs(const ProfileData& d, const OutputDir& dir) {
  std::vector<std::string> written;
  std::filesystem::create_directories(dir.path("plots"));
  // One occupancy and one lag/pop figure per (stream, faults, policy), lines per ring size.
  std::map<std::string, std::vector<const SweepRun*>> groups;
  std::vector<std::string> order;
  for (const SweepRun& s : d.sweep) {
    const std::string key = s.stream + "_" + s.faults + "_" + s.policy;
    if (!groups.count(key)) order.push_back(key);
    groups[key].push_back(&s);
  }
  for (const std::string& key : order) {
    std::vector<NamedSeries> runs;
    const SweepRun& first = *groups[key].front();
    for (const SweepRun* s : groups[key])
      runs.push_back(NamedSeries{"ring " + ringLabel(s->ring), s->ring, &s->result.series});
    const std::string what = first.stream + ", faults: " + first.faults + ", catch-up: " + first.policy;
    writePlot(occupancyFigure(what, runs), dir, "plots/occupancy_" + safe(key) + ".png", written);
    writePlot(lagPopFigure(what, runs, d.search.popThreshold), dir, "plots/lag_pop_" + safe(key) + ".png", written);
  }
  if (!d.stalls.empty()) {
    writePlot(stallFigure("Survivable drive stall against ring size", d.stalls, d.search), dir,
              "plots/survivable_stall.png", written);
  }
  {
    std::ofstream o(dir.path("sweep.csv"), std::ios::binary);
    writeSweepCsv(d, o);
    written.push_back("sweep.csv");
  }
  if (!d.stalls.empty()) {
    std::ofstream o(dir.path("stall.csv"), std::ios::binary);
    writeStallCsv(d, o);
    written.push_back("stall.csv");
  }
  {
    std::ofstream o(dir.path("profile.json"), std::ios::binary);
    o << profileJson(d).dump(2) << "\n";
    written.push_back("profile.json");
  }
  return written;
}

}  // namespace vbim::cli::profile
