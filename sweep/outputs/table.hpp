// The results of a sweep plan (`vbim profile --plan`, docs/sweeps.md) and how they are written:
// cases.csv and cases.jsonl (one row per case: every axis value, every measure), summary.csv and
// summary.txt (each probability per group of cases that differ only in Monte Carlo axes, with its
// Wilson score interval), plots/probability_<n>.png/.svg; and a shard's records (shard.jsonl), the
// lossless form a merge reads back. A local run and a merge of shards write from the same records
// with the same code, so their files are the same bytes.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/runner.hpp"

namespace vbim::sweep {

// Writes every output into `dir`; `records` are all cases', in case order. Returns the names written.
std::vector<std::string> writeSweepOutputs(const SweepPlanSpec& plan, const std::vector<PlanCase>& cases,
                                           const std::vector<CaseRecord>& records, const std::filesystem::path& dir);

// The lines of summary.txt (also printed by the command).
std::vector<std::string> summaryLines(const SweepPlanSpec& plan, const std::vector<PlanCase>& cases,
                                      const std::vector<CaseRecord>& records);

// The value of a table column for a case (frames_late, ring_banks_mean, longest_stall_s,
// bitrate_bps, psnr_mean_db, ipu_busy_share, ...: docs/sweeps.md); none for a failed case, a column
// not known, or a PSNR of a stream that is not a measured re-encode. A case that fails even without
// a stall survives none: longest_stall_s 0.
std::optional<double> caseColumn(const std::string& column, const CaseRecord& r);

// A record as one JSON object with integer ticks (nothing rounded), and back (throws
// std::exception on a malformed line).
nlohmann::ordered_json recordJson(const CaseRecord& r);
CaseRecord recordFromJson(const nlohmann::json& j);

// The Wilson score interval of k successes in n trials at z (1.959964: 95 %); {0, 1} when n is 0.
struct Interval {
  double low = 0, high = 1;
};
Interval wilson(std::int64_t k, std::int64_t n, double z = 1.959963984540054);

// A CSV cell: as it is, or quoted (quotes doubled) when it holds a comma, a quote or a line break.
std::string csvQuote(const std::string& s);

}  // namespace vbim::sweep
