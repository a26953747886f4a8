#include "sweep/outputs/equal_quality.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <tuple>
#include <utility>

#include "plots/write_chart.hpp"
#include "sweep/outputs/profile_outputs.hpp"
#include "sweep/outputs/table.hpp"

namespace vbim::sweep {

namespace {

using Structure = std::tuple<int, int, bool>;  // gop, B pictures, open

Structure structureOf(const StreamSpec& s) {
  return {s.gop, s.bFrames, s.openGop};
}

double value(const CaseRecord& r, const char* column) {
  return caseColumn(column, r).value_or(0.0);
}

// A column of the table: its CSV key, its markdown heading, its text for a row (and in the CSV, when
// that is not the text: plain numbers there).
using CellText = std::function<std::string(const EqualQualityRow&, const CaseRecord&, const CaseRecord& ref)>;
struct Column {
  Column(std::string k, std::string h, CellText t, CellText c = {})
      : key(std::move(k)), heading(std::move(h)), text(std::move(t)), csv(std::move(c)) {}
  std::string key, heading;
  CellText text;  // empty: in the CSV only
  CellText csv;   // empty: the text
};

std::string signedFixed(double v, int decimals) {
  return (v >= 0 ? "+" : "") + fixed(v, decimals);
}

std::string stallText(const CaseRecord& r) {
  if (!r.stall.longest) return "none";
  return (r.stall.saturated ? ">= " : "") + fixed(toSeconds(*r.stall.longest), 2);
}

std::vector<Column> columns(const SweepPlanSpec& plan) {
  std::vector<Column> c;
  c.push_back({"structure", "GOP structure", [](const auto& row, const auto&, const auto&) {
                 return gopLabel(*row.stream) + (row.reference ? " (reference)" : "");
               }});
  c.push_back(
      {"gop", "", {}, [](const auto& row, const auto&, const auto&) { return std::to_string(row.stream->gop); }});
  c.push_back({"b_frames", "", {}, [](const auto& row, const auto&, const auto&) {
                 return std::to_string(row.stream->bFrames);
               }});
  c.push_back({"stream", "stream", [](const auto& row, const auto&, const auto&) { return row.stream->label; }});
  c.push_back({"qscale", "q", [](const auto& row, const auto&, const auto&) {
                 return row.stream->qscale > 0 ? std::to_string(row.stream->qscale)
                                               : std::to_string(row.stream->bitrate) + " bit/s";
               }});
  c.push_back({"psnr_mean_db", "PSNR mean (dB)",
               [](const auto&, const auto& r, const auto&) { return fixed(value(r, "psnr_mean_db"), 2); }});
  c.push_back({"psnr_min_db", "PSNR min (dB)",
               [](const auto&, const auto& r, const auto&) { return fixed(value(r, "psnr_min_db"), 2); }});
  c.push_back({"psnr_delta_db", "vs reference (dB)",
               [](const auto& row, const auto&, const auto&) { return signedFixed(row.deltaDb, 2); }});
  c.push_back({"equal", "equal", [](const auto& row, const auto&, const auto&) { return row.equal ? "yes" : "no"; }});
  c.push_back({"bitrate_kbps", "bitrate (kbit/s)",
               [](const auto&, const auto& r, const auto&) { return fixed(value(r, "bitrate_bps") / 1000.0, 1); }});
  c.push_back({"bitrate_vs_reference_pct", "of reference",
               [](const auto&, const auto& r, const auto& ref) {
                 const double b = value(ref, "bitrate_bps");
                 return b > 0 ? fixed(100.0 * value(r, "bitrate_bps") / b, 1) + " %" : std::string();
               },
               [](const auto&, const auto& r, const auto& ref) {
                 const double b = value(ref, "bitrate_bps");
                 return b > 0 ? fixed(100.0 * value(r, "bitrate_bps") / b, 1) : std::string();
               }});
  c.push_back({"sectors_per_frame", "sectors per frame",
               [](const auto&, const auto& r, const auto&) { return fixed(value(r, "sectors_per_frame"), 2); }});
  if (hasMeasure(plan, Measure::RingOccupancy)) {
    c.push_back({"ring_banks_mean", "ring banks mean (min-max)",
                 [](const auto&, const auto& r, const auto&) {
                   return fixed(value(r, "ring_banks_mean"), 2) + " (" + fixed(value(r, "ring_banks_min"), 0) + "-" +
                          fixed(value(r, "ring_banks_max"), 0) + ")";
                 },
                 [](const auto&, const auto& r, const auto&) { return fixed(value(r, "ring_banks_mean"), 3); }});
  }
  if (hasMeasure(plan, Measure::SurvivableStall)) {
    c.push_back({"longest_stall_s", "survivable stall (s)",
                 [](const auto&, const auto& r, const auto&) { return stallText(r); },
                 [](const auto&, const auto& r, const auto&) {
                   return r.stall.longest ? fixed(toSeconds(*r.stall.longest), 3) : std::string();
                 }});
    c.push_back({"stall_saturated", "", {}, [](const auto&, const auto& r, const auto&) {
                   return std::string(r.stall.saturated ? "1" : "0");
                 }});
  }
  if (hasMeasure(plan, Measure::BusyShare)) {
    for (const char* unit : {"ipu", "ee"}) {
      const std::string column = std::string(unit) + "_busy_share";
      const CellText pct = [column](const auto&, const auto& r, const auto&) {
        return fixed(100 * value(r, column.c_str()), 2) + " %";
      };
      const CellText number = [column](const auto&, const auto& r, const auto&) {
        return fixed(100 * value(r, column.c_str()), 3);
      };
      c.emplace_back(std::string(unit) + "_busy_pct", std::string(unit) == "ipu" ? "IPU busy" : "EE busy", pct, number);
    }
  }
  return c;
}

std::string groupLabel(const SweepPlanSpec& plan, const PlanCase& c) {
  std::string s =
      "ring " + std::to_string(plan.rings[c.ring].bankmax) + ":" + std::to_string(plan.rings[c.ring].bufmax);
  s += ", " + plan.policies[c.policy];
  for (const auto& [k, v] : plan.platforms[c.platform].values) s += ", " + k + "=" + v;
  s += ", faults " + plan.faults[c.faults].name;
  if (plan.faults[c.faults].draws.size() > 1) s += " draw " + std::to_string(c.draw);
  return s + ", seed " + std::to_string(c.runSeed(plan));
}

// Each measure against GOP length: one line per B-picture setting, the reference dashed.
plots::Figure figure(const SweepPlanSpec& plan, const EqualQualityGroup& g, const std::vector<CaseRecord>& records) {
  struct Measured {
    const char* column;
    const char* title;
    const char* unit;
    double scale;
    Measure measure;
  };
  const std::array<Measured, 5> measured{{
      {"bitrate_bps", "bitrate", "kbit/s", 1e-3, Measure::Coding},
      {"ring_banks_mean", "ring occupancy (mean)", "banks readable", 1, Measure::RingOccupancy},
      {"longest_stall_s", "longest survivable stall", "s", 1, Measure::SurvivableStall},
      {"ipu_busy_share", "IPU busy share", "%", 100, Measure::BusyShare},
      {"ee_busy_share", "EE busy share", "%", 100, Measure::BusyShare},
  }};
  const EqualQualityRow* ref = nullptr;
  for (const EqualQualityRow& r : g.rows) {
    if (r.reference) ref = &r;
  }
  plots::Figure f;
  f.title = "At equal quality (mean luma PSNR within " + fixed(plan.equalQuality->toleranceDb, 2) + " dB of " +
            fixed(g.referenceDb, 2) + " dB): " + g.label;
  f.panelHeight = 240;
  for (const Measured& m : measured) {
    if (!hasMeasure(plan, m.measure)) continue;
    plots::Panel p;
    p.title = m.title;
    p.xLabel = "GOP length (pictures from one I picture to the next)";
    p.yLabel = m.unit;
    std::map<std::pair<int, bool>, std::size_t> lineOf;  // (B pictures, open) -> series
    for (const EqualQualityRow& r : g.rows) {
      if (r.reference) continue;
      const auto key = std::make_pair(r.stream->bFrames, r.stream->openGop);
      auto [it, added] = lineOf.emplace(key, p.series.size());
      if (added) {
        plots::Series s;
        s.name = r.stream->bFrames == 0
                     ? "P pictures only"
                     : std::to_string(r.stream->bFrames) + " B pictures" + (r.stream->openGop ? ", open GOPs" : "");
        s.color = plots::paletteColor(p.series.size());
        s.markers = true;
        s.thickness = 2;
        p.series.push_back(s);
      }
      plots::Series& s = p.series[it->second];
      s.x.push_back(r.stream->gop);
      s.y.push_back(value(records[r.record], m.column) * m.scale);
    }
    if (ref != nullptr) {
      p.refLines.push_back(
          {gopLabel(*ref->stream) + " (reference)", value(records[ref->record], m.column) * m.scale, {80, 80, 80}});
    }
    f.panels.push_back(std::move(p));
  }
  return f;
}

}  // namespace

std::string gopLabel(const StreamSpec& s) {
  if (s.gop == 1) return "intra only";
  std::string l = "GOP " + std::to_string(s.gop);
  if (s.bFrames > 0) l += ", " + std::to_string(s.bFrames) + " B";
  if (s.openGop) l += ", open";
  return l;
}

std::vector<EqualQualityGroup> equalQualityGroups(const SweepPlanSpec& plan, const std::vector<PlanCase>& cases,
                                                  const std::vector<CaseRecord>& records) {
  const EqualQuality& eq = *plan.equalQuality;
  std::vector<Structure> structures;  // in order of the gops axis
  for (const StreamSpec& s : plan.streams) {
    if (s.reencoded() && std::find(structures.begin(), structures.end(), structureOf(s)) == structures.end())
      structures.push_back(structureOf(s));
  }
  // Cases that differ only in their stream: the same platform, faults, policy, ring, seed and draw.
  std::map<std::array<std::size_t, 6>, std::vector<std::size_t>> byGroup;
  std::vector<std::array<std::size_t, 6>> order;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const PlanCase& c = cases[i];
    const std::array<std::size_t, 6> key{c.platform, c.faults, c.policy, c.ring, c.seed, c.draw};
    auto& list = byGroup[key];
    if (list.empty()) order.push_back(key);
    list.push_back(i);
  }
  const Structure refStructure{eq.referenceGop, eq.referenceBFrames, false};
  std::vector<EqualQualityGroup> out;
  for (const auto& key : order) {
    const std::vector<std::size_t>& members = byGroup.at(key);
    const auto usable = [&](std::size_t i) {
      return records[i].ok && records[i].result.quality.has_value() && plan.streams[cases[i].stream].reencoded();
    };
    std::optional<std::size_t> ref;
    for (std::size_t i : members) {
      const StreamSpec& s = plan.streams[cases[i].stream];
      if (usable(i) && structureOf(s) == refStructure && s.qscale == eq.referenceQscale && s.bitrate == 0) ref = i;
    }
    if (!ref) continue;
    EqualQualityGroup g;
    g.label = groupLabel(plan, cases[*ref]);
    g.referenceDb = value(records[*ref], "psnr_mean_db");
    for (const Structure& st : structures) {
      std::optional<std::size_t> best;
      double bestDelta = 0;
      for (std::size_t i : members) {
        if (!usable(i) || structureOf(plan.streams[cases[i].stream]) != st) continue;
        const double delta = value(records[i], "psnr_mean_db") - g.referenceDb;
        const bool better = !best || std::fabs(delta) < std::fabs(bestDelta) ||
                            (std::fabs(delta) == std::fabs(bestDelta) &&
                             value(records[i], "bitrate_bps") < value(records[*best], "bitrate_bps"));
        if (st == refStructure) {
          if (i != *ref) continue;  // the reference stands for its own structure
        } else if (!better) {
          continue;
        }
        best = i;
        bestDelta = delta;
      }
      if (!best) continue;
      EqualQualityRow row;
      row.record = *best;
      row.stream = &plan.streams[cases[*best].stream];
      row.deltaDb = bestDelta;
      row.equal = std::fabs(bestDelta) <= eq.toleranceDb;
      row.reference = *best == *ref;
      g.rows.push_back(row);
    }
    out.push_back(std::move(g));
  }
  return out;
}

std::vector<std::string> writeEqualQuality(const SweepPlanSpec& plan, const std::vector<PlanCase>& cases,
                                           const std::vector<CaseRecord>& records, const std::filesystem::path& dir) {
  const std::vector<EqualQualityGroup> groups = equalQualityGroups(plan, cases, records);
  const std::vector<Column> cols = columns(plan);
  std::vector<std::string> written;
  for (std::size_t n = 0; n < groups.size(); ++n) {
    const std::string stem = "plots/equal_quality_" + std::to_string(n + 1);
    std::filesystem::create_directories(dir / "plots");
    for (const std::filesystem::path& file : plots::writeChartFiles(figure(plan, groups[n], records), dir / stem))
      written.push_back(stem + file.extension().string());
  }
  std::ofstream csv(dir / "equal_quality.csv", std::ios::binary);
  std::ofstream md(dir / "equal_quality.md", std::ios::binary);
  csv << "group";
  for (const Column& c : cols) csv << "," << c.key;
  csv << "\n";
  md << "Per GOP structure, the re-encode whose mean luma PSNR against the source frames is nearest the "
        "reference's; equal: within "
     << fixed(plan.equalQuality->toleranceDb, 2) << " dB.\n";
  for (const EqualQualityGroup& g : groups) {
    const CaseRecord* ref = nullptr;
    for (const EqualQualityRow& r : g.rows) {
      if (r.reference) ref = &records[r.record];
    }
    md << "\n" << g.label << " (reference " << fixed(g.referenceDb, 2) << " dB):\n\n|";
    for (const Column& c : cols) {
      if (c.text) md << " " << c.heading << " |";
    }
    md << "\n|";
    std::size_t shown = 0;  // text columns left-aligned: structure, stream, q
    for (const Column& c : cols) {
      if (c.text) md << (shown++ < 3 ? "---|" : "--:|");
    }
    md << "\n";
    for (const EqualQualityRow& row : g.rows) {
      csv << csvQuote(g.label);
      md << "|";
      for (const Column& c : cols) {
        const CaseRecord& r = records[row.record];
        csv << "," << csvQuote(c.csv ? c.csv(row, r, *ref) : c.text(row, r, *ref));
        if (c.text) md << " " << c.text(row, r, *ref) << " |";
      }
      csv << "\n";
      md << "\n";
    }
  }
  written.push_back("equal_quality.csv");
  written.push_back("equal_quality.md");
  return written;
}

}  // namespace vbim::sweep
