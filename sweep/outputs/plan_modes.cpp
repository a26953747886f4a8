#include "sweep/outputs/plan_modes.hpp"

#include <iterator>
#include <tuple>

#include "player/report.hpp"
#include "sweep/outputs/plan_host.hpp"
#include "sweep/outputs/table.hpp"

namespace vbim::sweep {

namespace fs = std::filesystem;

std::vector<std::string> caseWarnings(const std::vector<CaseRecord>& records) {
  std::vector<std::string> out;
  std::size_t failed = 0, stuck = 0, starved = 0;
  for (const CaseRecord& r : records) {
    if (!r.ok) {
      if (++failed <= 5) out.push_back("case " + std::to_string(r.number) + " failed: " + r.error);
      continue;
    }
    const std::string verdict = player::runHealth(r.result.lightmap, r.result.totals).verdict;
    stuck += verdict == "stuck" ? 1 : 0;
    starved += verdict == "starved" ? 1 : 0;
  }
  if (failed > 5) out.push_back("... and " + std::to_string(failed - 5) + " more failed cases (see the table)");
  if (stuck + starved > 0) {
    out.push_back("warning: " + std::to_string(stuck) + " stuck and " + std::to_string(starved) + " starved of " +
                  std::to_string(records.size()) +
                  " cases: the display stopped for their last 5 s or more (the health column of cases.csv; "
                  "docs/player.md, \"Stuck and starved runs\")");
  }
  return out;
}

PlanSummary writePlanOutputs(const LoadedPlan& p, const std::vector<CaseRecord>& records, const fs::path& dir,
                             const fs::path& finalDir) {
  const std::vector<std::string> written = writeSweepOutputs(p.spec, p.cases, records, dir);
  PlanSummary s;
  s.lines = summaryLines(p.spec, p.cases, records);
  s.cases = records.size();
  for (const std::string& w : written) s.written.push_back((finalDir / w).string());
  return s;
}

Shard selectShard(const LoadedPlan& p, const std::string& text) {
  Shard s;
  std::tie(s.k, s.n) = parseShard(text);
  std::tie(s.first, s.last) = shardRange(p.cases.size(), s.k, s.n);
  const auto begin = p.cases.begin();
  s.cases.assign(std::next(begin, static_cast<std::ptrdiff_t>(s.first)),
                 std::next(begin, static_cast<std::ptrdiff_t>(s.last)));
  s.name = shardName(s.k, s.n);
  return s;
}

EmittedSlurm emitSlurmJob(const LoadedPlan& p, const std::string& planPath, const SlurmRequest& request,
                          const std::string& program, const fs::path& dir, const fs::path& finalDir,
                          const std::function<void(const PlanCase&)>& runCase) {
  const CaseCost cost = measureCaseCost(p, runCase);
  EmittedSlurm e;
  e.perCase = cost.seconds;
  e.job = sizeSlurmJob(request, p.cases.size(), cost.seconds, cost.rssMb);
  writeSlurmJob(request, e.job, p, planPath, program, dir, finalDir);
  return e;
}

std::string thisProgram() {
  std::error_code ec;
  const fs::path p = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("vbim") : p.string();
}

}  // namespace vbim::sweep
