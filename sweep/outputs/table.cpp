#include "sweep/outputs/table.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>

#include "player/report.hpp"
#include "plots/sweep_figures.hpp"
#include "sweep/outputs/equal_quality.hpp"
#include "sweep/outputs/profile_outputs.hpp"

namespace vbim::sweep {

namespace {

double share(Tick part, Tick whole) {
  return whole > 0 ? static_cast<double>(part) / static_cast<double>(whole) : 0.0;
}

}  // namespace

std::optional<double> caseColumn(const std::string& column, const CaseRecord& r) {
  if (!r.ok) return std::nullopt;
  const CaseResult& m = r.result;
  if (column == "frames_late") return static_cast<double>(m.lightmap.framesLate);
  if (column == "frames_dropped") return static_cast<double>(m.lightmap.framesDropped);
  if (column == "frames_caught_up") return static_cast<double>(m.lightmap.framesCaughtUp);
  if (column == "pop_max") return m.pop.value;
  if (column == "lag_max") return m.totals.lag.value;
  if (column == "ring_banks_min") return static_cast<double>(m.totals.ringMin);
  if (column == "ring_banks_mean")
    return m.totals.vsyncs > 0 ? static_cast<double>(m.totals.ringSum) / static_cast<double>(m.totals.vsyncs) : 0.0;
  if (column == "ring_banks_max") return static_cast<double>(m.totals.ringMax);
  if (column == "ring_underruns") return static_cast<double>(m.ringUnderruns);
  if (column == "longest_stall_s") return r.stall.longest ? toSeconds(*r.stall.longest) : 0.0;
  // The stream's bytes (all variants, descriptor packs included) per frame, times game frames per
  // second: the rate the player reads at in steady play.
  const double frames = static_cast<double>(std::max<std::int64_t>(1, m.streamFrames));
  if (column == "bitrate_bps") {
    return static_cast<double>(m.streamBytes) * 8.0 * static_cast<double>(m.gameFpsNum) /
           (frames * static_cast<double>(std::max<std::int64_t>(1, m.gameFpsDen)));
  }
  if (column == "sectors_per_frame") return static_cast<double>(m.streamBytes) / 2048.0 / frames;
  if (column == "psnr_mean_db" && m.quality) return m.quality->meanDb;
  if (column == "psnr_min_db" && m.quality) return m.quality->minDb;
  if (column == "ipu_busy_share") return share(m.ipuBusy, m.elapsed);
  if (column == "ee_busy_share") return share(m.eeBusy, m.elapsed);
  return std::nullopt;
}

namespace {

// One cell of the table: its text (as in the CSV) and how JSON writes it.
struct Cell {
  enum class Kind { Number, String, Null };
  std::string key;
  std::string text;
  Kind kind = Kind::Number;
};

Cell number(std::string key, std::int64_t v) {
  return {std::move(key), std::to_string(v), Cell::Kind::Number};
}
Cell real(std::string key, double v, int decimals) {
  return {std::move(key), fixed(v, decimals), Cell::Kind::Number};
}
Cell text(std::string key, std::string v) {
  return {std::move(key), std::move(v), Cell::Kind::String};
}

std::string ringLabel(const RingSize& r) {
  return std::to_string(r.bankmax) + ":" + std::to_string(r.bufmax);
}

// The axis cells of a case: the same for every record of it.
std::vector<Cell> axisCells(const SweepPlanSpec& plan, const PlanCase& c) {
  std::vector<Cell> row;
  row.push_back(number("case", static_cast<std::int64_t>(c.number)));
  row.push_back(text("stream", plan.streams[c.stream].label));
  row.push_back(number("bankmax", plan.rings[c.ring].bankmax));
  row.push_back(number("bufmax_sectors", plan.rings[c.ring].bufmax));
  row.push_back(text("policy", plan.policies[c.policy]));
  for (const std::string& key : plan.platformKeys) {
    std::string v;
    for (const auto& [k, value] : plan.platforms[c.platform].values) {
      if (k == key) v = value;
    }
    row.push_back(text(key, v));
  }
  row.push_back(text("faults", plan.faults[c.faults].name));
  row.push_back(number("draw", static_cast<std::int64_t>(c.draw)));
  row.push_back(text("drawn", plan.faults[c.faults].draws[c.draw].drawn));
  row.push_back(number("seed", static_cast<std::int64_t>(c.runSeed(plan))));
  return row;
}

std::vector<Cell> measureCells(const SweepPlanSpec& plan, const StreamSpec& spec, const CaseRecord& r) {
  std::vector<Cell> row;
  row.push_back(text("status", r.ok ? "ok" : "failed"));
  const CaseResult& m = r.result;
  row.push_back(number("stream_bytes", m.streamBytes));
  row.push_back(number("frames_shown", m.lightmap.framesShown));
  // ok, stuck or starved (player/report.hpp, runHealth): always shown, whatever the measures.
  row.push_back(r.ok ? text("health", player::runHealth(m.lightmap, m.totals).verdict)
                     : Cell{"health", "", Cell::Kind::Null});
  for (const Measure ms : plan.measures) {
    switch (ms) {
      case Measure::FramesLate:
        row.push_back(number("frames_late", m.lightmap.framesLate));
        row.push_back(number("behind_vsyncs", m.lightmap.behindVsyncs));
        break;
      case Measure::FramesDropped:
        row.push_back(number("frames_dropped", m.lightmap.framesDropped));
        break;
      case Measure::FramesCaughtUp:
        row.push_back(number("frames_caught_up", m.lightmap.framesCaughtUp));
        break;
      case Measure::PopMax:
        row.push_back(number("pop_max", m.pop.value));
        row.push_back(real("pop_max_at_s", toSeconds(m.pop.at), 6));
        break;
      case Measure::LagMax:
        row.push_back(number("lag_max", m.totals.lag.value));
        row.push_back(real("lag_max_at_s", toSeconds(m.totals.lag.at), 6));
        break;
      case Measure::RingOccupancy: {
        const double mean =
            m.totals.vsyncs > 0 ? static_cast<double>(m.totals.ringSum) / static_cast<double>(m.totals.vsyncs) : 0.0;
        row.push_back(number("ring_banks_min", m.totals.ringMin));
        row.push_back(real("ring_banks_mean", mean, 3));
        row.push_back(number("ring_banks_max", m.totals.ringMax));
        row.push_back(number("ring_underruns", m.ringUnderruns));
        break;
      }
      case Measure::SurvivableStall:
        row.push_back(r.stall.longest ? real("longest_stall_s", toSeconds(*r.stall.longest), 6)
                                      : Cell{"longest_stall_s", "", Cell::Kind::Null});
        row.push_back(number("stall_saturated", r.stall.saturated ? 1 : 0));
        row.push_back(number("stall_runs", r.stall.runs));
        break;
      case Measure::Coding: {
        row.push_back(number("qscale", spec.qscale));
        row.push_back(number("gop", spec.gop));
        row.push_back(number("b_frames", spec.bFrames));
        row.push_back(number("bitrate_bps", static_cast<std::int64_t>(std::llround(*caseColumn("bitrate_bps", r)))));
        row.push_back(real("sectors_per_frame", *caseColumn("sectors_per_frame", r), 3));
        const auto cell = [&](const char* key) {
          const auto v = caseColumn(key, r);
          return v ? real(key, *v, 3) : Cell{key, "", Cell::Kind::Null};
        };
        row.push_back(cell("psnr_mean_db"));
        row.push_back(cell("psnr_min_db"));
        break;
      }
      case Measure::BusyShare:
        row.push_back(real("ipu_busy_share", *caseColumn("ipu_busy_share", r), 4));
        row.push_back(real("ee_busy_share", *caseColumn("ee_busy_share", r), 4));
        break;
    }
  }
  if (!r.ok) {  // a failed case measured nothing: empty cells (null in JSON), not zeros
    for (std::size_t i = 1; i < row.size(); ++i) row[i] = Cell{row[i].key, "", Cell::Kind::Null};
  }
  row.push_back(text("error", r.error));
  return row;
}

std::string jsonLine(const std::vector<Cell>& row) {
  std::string o = "{";
  for (std::size_t i = 0; i < row.size(); ++i) {
    const Cell& c = row[i];
    if (i > 0) o += ",";
    o += nlohmann::json(c.key).dump() + ":";
    if (c.kind == Cell::Kind::String) {
      o += nlohmann::json(c.text).dump();
    } else {
      o += c.kind == Cell::Kind::Null ? "null" : c.text;
    }
  }
  return o + "}";
}

bool holds(const Probability& p, double v) {
  if (p.op == ">") return v > p.threshold;
  if (p.op == ">=") return v >= p.threshold;
  if (p.op == "<") return v < p.threshold;
  return v <= p.threshold;
}

// Cases that differ only in Monte Carlo axes (seed, draw) form a group; groups in case order.
struct Group {
  const PlanCase* first = nullptr;
  std::int64_t cases = 0, failed = 0;
  std::vector<std::int64_t> hits;  // per probability
};

std::vector<Group> groups(const SweepPlanSpec& plan, const std::vector<PlanCase>& cases,
                          const std::vector<CaseRecord>& records) {
  std::vector<Group> out;
  std::map<std::array<std::size_t, 5>, std::size_t> index;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const PlanCase& c = cases[i];
    const std::array<std::size_t, 5> key{c.stream, c.platform, c.faults, c.policy, c.ring};
    auto [it, added] = index.emplace(key, out.size());
    if (added) out.push_back(Group{&c, 0, 0, std::vector<std::int64_t>(plan.probabilities.size(), 0)});
    Group& g = out[it->second];
    if (!records[i].ok) {
      ++g.failed;
      continue;
    }
    ++g.cases;
    for (std::size_t p = 0; p < plan.probabilities.size(); ++p) {
      const auto v = caseColumn(plan.probabilities[p].measure, records[i]);
      if (v && holds(plan.probabilities[p], *v)) ++g.hits[p];
    }
  }
  return out;
}

std::string groupLabel(const SweepPlanSpec& plan, const PlanCase& c, bool withRing) {
  std::string s = plan.streams[c.stream].label;
  if (withRing) s += ", ring " + ringLabel(plan.rings[c.ring]);
  s += ", " + plan.policies[c.policy];
  for (const auto& [k, v] : plan.platforms[c.platform].values) s += ", " + k + "=" + v;
  return s + ", faults " + plan.faults[c.faults].name;
}

std::string probabilityText(const Probability& p) {
  std::string t = fixed(p.threshold, 6);
  while (t.back() == '0') t.pop_back();
  if (t.back() == '.') t.pop_back();
  return p.measure + " " + p.op + " " + t;
}

void writeSummaryCsv(const SweepPlanSpec& plan, const std::vector<Group>& gs, std::ostream& o) {
  o << "probability,condition,stream,bankmax,bufmax_sectors,policy";
  for (const std::string& k : plan.platformKeys) o << "," << csvQuote(k);
  o << ",faults,cases,failed,hits,p,ci_low,ci_high\n";
  for (std::size_t p = 0; p < plan.probabilities.size(); ++p) {
    for (const Group& g : gs) {
      const PlanCase& c = *g.first;
      const Interval ci = wilson(g.hits[p], g.cases);
      o << csvQuote(plan.probabilities[p].name) << "," << csvQuote(probabilityText(plan.probabilities[p])) << ","
        << csvQuote(plan.streams[c.stream].label) << "," << plan.rings[c.ring].bankmax << ","
        << plan.rings[c.ring].bufmax << "," << plan.policies[c.policy];
      for (const auto& [k, v] : plan.platforms[c.platform].values) o << "," << csvQuote(v);
      o << "," << csvQuote(plan.faults[c.faults].name) << "," << g.cases << "," << g.failed << "," << g.hits[p] << ","
        << (g.cases > 0 ? fixed(static_cast<double>(g.hits[p]) / static_cast<double>(g.cases), 6) : "") << ","
        << fixed(ci.low, 6) << "," << fixed(ci.high, 6) << "\n";
    }
  }
}

}  // namespace

Interval wilson(std::int64_t k, std::int64_t n, double z) {
  if (n <= 0) return {};
  const double nn = static_cast<double>(n);
  const double p = static_cast<double>(k) / nn;
  const double z2 = z * z;
  const double centre = (p + z2 / (2 * nn)) / (1 + z2 / nn);
  const double half = z / (1 + z2 / nn) * std::sqrt(p * (1 - p) / nn + z2 / (4 * nn * nn));
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

std::vector<std::string> summaryLines(const SweepPlanSpec& plan, const std::vector<PlanCase>& cases,
                                      const std::vector<CaseRecord>& records) {
  std::vector<std::string> lines;
  const std::vector<Group> gs = groups(plan, cases, records);
  for (std::size_t p = 0; p < plan.probabilities.size(); ++p) {
    for (const Group& g : gs) {
      const Interval ci = wilson(g.hits[p], g.cases);
      const double est = g.cases > 0 ? static_cast<double>(g.hits[p]) / static_cast<double>(g.cases) : 0.0;
      std::string line = plan.probabilities[p].name + ": P(" + probabilityText(plan.probabilities[p]) + " | " +
                         groupLabel(plan, *g.first, true) + ") = " + fixed(est, 3) + ", 95 % interval [" +
                         fixed(ci.low, 3) + ", " + fixed(ci.high, 3) + "] (Wilson) over " + std::to_string(g.cases) +
                         " cases";
      if (g.failed > 0) line += " (" + std::to_string(g.failed) + " failed, left out)";
      lines.push_back(std::move(line));
    }
  }
  return lines;
}

std::vector<std::string> writeSweepOutputs(const SweepPlanSpec& plan, const std::vector<PlanCase>& cases,
                                           const std::vector<CaseRecord>& records, const std::filesystem::path& dir) {
  std::vector<std::string> written;
  // Figures first (as `vbim profile` lists them): one per probability, a line per group without ring.
  const std::vector<Group> gs = groups(plan, cases, records);
  for (std::size_t p = 0; p < plan.probabilities.size(); ++p) {
    std::vector<plots::sweep::ProbabilityLine> lines;
    std::map<std::string, std::size_t> byName;
    for (const Group& g : gs) {
      const std::string name = groupLabel(plan, *g.first, false);
      auto [it, added] = byName.emplace(name, lines.size());
      if (added) lines.push_back({name, {}, {}, {}, {}});
      if (g.cases == 0) continue;
      plots::sweep::ProbabilityLine& l = lines[it->second];
      const Interval ci = wilson(g.hits[p], g.cases);
      l.ringSectors.push_back(static_cast<double>(plan.rings[g.first->ring].bufmax));
      l.p.push_back(static_cast<double>(g.hits[p]) / static_cast<double>(g.cases));
      l.low.push_back(ci.low);
      l.high.push_back(ci.high);
    }
    const Probability& pr = plan.probabilities[p];
    const plots::Figure fig =
        plots::sweep::probabilityFigure(pr.name + ": P(" + probabilityText(pr) + ")", "95 % Wilson interval", lines);
    for (std::string& w :
         plots::sweep::writeProbabilityFigure(fig, (dir / ""), "plots/probability_" + std::to_string(p + 1)))
      written.push_back(std::move(w));
  }
  {
    std::ofstream csv((dir / "cases.csv"), std::ios::binary);
    std::ofstream jsonl((dir / "cases.jsonl"), std::ios::binary);
    for (std::size_t i = 0; i < cases.size(); ++i) {
      std::vector<Cell> row = axisCells(plan, cases[i]);
      for (Cell& c : measureCells(plan, plan.streams[cases[i].stream], records[i])) row.push_back(std::move(c));
      if (i == 0) {
        for (std::size_t k = 0; k < row.size(); ++k) csv << (k > 0 ? "," : "") << csvQuote(row[k].key);
        csv << "\n";
      }
      for (std::size_t k = 0; k < row.size(); ++k) csv << (k > 0 ? "," : "") << csvQuote(row[k].text);
      csv << "\n";
      jsonl << jsonLine(row) << "\n";
    }
    written.push_back("cases.csv");
    written.push_back("cases.jsonl");
  }
  if (plan.equalQuality) {
    for (std::string& w : writeEqualQuality(plan, cases, records, dir)) written.push_back(std::move(w));
  }
  if (!plan.probabilities.empty()) {
    std::ofstream csv((dir / "summary.csv"), std::ios::binary);
    writeSummaryCsv(plan, gs, csv);
    std::ofstream txt((dir / "summary.txt"), std::ios::binary);
    for (const std::string& l : summaryLines(plan, cases, records)) txt << l << "\n";
    written.push_back("summary.csv");
    written.push_back("summary.txt");
  }
  return written;
}

nlohmann::ordered_json recordJson(const CaseRecord& r) {
  const CaseResult& m = r.result;
  nlohmann::ordered_json j;
  j["case"] = r.number;
  j["ok"] = r.ok;
  j["error"] = r.error;
  j["lightmap"] = {{"shown", m.lightmap.framesShown},
                   {"late", m.lightmap.framesLate},
                   {"dropped", m.lightmap.framesDropped},
                   {"caught_up", m.lightmap.framesCaughtUp},
                   {"behind", m.lightmap.behindVsyncs}};
  j["pop"] = {m.pop.value, m.pop.vsync, m.pop.at};
  j["lag"] = {m.totals.lag.value, m.totals.lag.vsync, m.totals.lag.at};
  j["ring"] = {m.totals.ringMin, m.totals.ringMax, m.totals.ringSum, m.totals.vsyncs};
  j["underruns"] = m.ringUnderruns;
  j["retries"] = m.driveRetries;
  j["lost"] = m.framesLost;
  j["stream_bytes"] = m.streamBytes;
  j["stream_frames"] = {m.streamFrames, m.gameFpsNum, m.gameFpsDen};
  j["quality"] = m.quality ? nlohmann::ordered_json{m.quality->meanDb, m.quality->minDb, m.quality->frames}
                           : nlohmann::ordered_json();
  j["busy"] = {m.elapsed, m.ipuBusy, m.eeBusy};
  j["health"] = {m.totals.lastVsyncAt, m.totals.endsBehind, m.totals.lastProgressAt};
  j["stall"] = {{"longest", r.stall.longest ? nlohmann::ordered_json(*r.stall.longest) : nlohmann::ordered_json()},
                {"saturated", r.stall.saturated},
                {"runs", r.stall.runs},
                {"pop_threshold", r.stall.popThreshold}};
  return j;
}

CaseRecord recordFromJson(const nlohmann::json& j) {
  CaseRecord r;
  CaseResult& m = r.result;
  r.number = j.at("case").get<std::size_t>();
  r.ok = j.at("ok").get<bool>();
  r.error = j.at("error").get<std::string>();
  const auto& l = j.at("lightmap");
  m.lightmap.framesShown = l.at("shown");
  m.lightmap.framesLate = l.at("late");
  m.lightmap.framesDropped = l.at("dropped");
  m.lightmap.framesCaughtUp = l.at("caught_up");
  m.lightmap.behindVsyncs = l.at("behind");
  const auto extreme = [](const nlohmann::json& a, player::Extreme& e) {
    e.value = a.at(0);
    e.vsync = a.at(1);
    e.at = a.at(2);
  };
  extreme(j.at("pop"), m.pop);
  extreme(j.at("lag"), m.totals.lag);
  const auto& ring = j.at("ring");
  m.totals.ringMin = ring.at(0);
  m.totals.ringMax = ring.at(1);
  m.totals.ringSum = ring.at(2);
  m.totals.vsyncs = ring.at(3);
  m.ringUnderruns = j.at("underruns");
  m.driveRetries = j.at("retries");
  m.framesLost = j.at("lost");
  const auto& health = j.at("health");
  m.totals.lastVsyncAt = health.at(0);
  m.totals.endsBehind = health.at(1);
  m.totals.lastProgressAt = health.at(2);
  m.streamBytes = j.at("stream_bytes");
  const auto& frames = j.at("stream_frames");
  m.streamFrames = frames.at(0);
  m.gameFpsNum = frames.at(1);
  m.gameFpsDen = frames.at(2);
  if (const auto& q = j.at("quality"); !q.is_null())
    m.quality = StreamQuality{q.at(0).get<double>(), q.at(1).get<double>(), q.at(2).get<std::int64_t>()};
  const auto& busy = j.at("busy");
  m.elapsed = busy.at(0);
  m.ipuBusy = busy.at(1);
  m.eeBusy = busy.at(2);
  const auto& s = j.at("stall");
  if (!s.at("longest").is_null()) r.stall.longest = s.at("longest").get<Tick>();
  r.stall.saturated = s.at("saturated");
  r.stall.runs = s.at("runs");
  r.stall.popThreshold = s.at("pop_threshold");
  return r;
}

std::string csvQuote(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string o = "\"";
  for (char c : s) o += c == '"' ? std::string("\"\"") : std::string(1, c);
  return o + "\"";
}

}  // namespace vbim::sweep
