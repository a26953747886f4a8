#include "runs/profile_run.hpp"

#include <filesystem>
#include <sstream>
#include <utility>

#include "config/fault_plan_toml.hpp"
#include "config/option_values.hpp"
#include "config/platform_config_toml.hpp"
#include "gs/error.hpp"
#include "gs/simd/blend_simd.hpp"
#include "ipu/simd/simd_kernels.hpp"
#include "player/report.hpp"
#include "runs/output_dir.hpp"
#include "streams/disc/stream_disc.hpp"
#include "sweep/outputs/profile_outputs.hpp"

namespace vbim::runs {

namespace {

using namespace vbim::sweep;

std::string stem(const std::string& path) {
  return std::filesystem::path(path).stem().string();
}

// A disc as given: a bare stream file or the stream on an ISO 9660 image, labelled by its name.
std::shared_ptr<Stream> discStream(const std::string& path, const std::string& file) {
  streams::StreamDisc opened = streams::openStreamDisc(path, file);
  auto s = std::make_shared<Stream>();
  s->label = stem(path);
  s->disc = std::move(opened.disc);
  s->file = opened.file;
  return s;
}

// The sweep's axes from the request; `streams` holds what plan.streams points at.
SweepPlan sweepPlan(const ProfileRequest& r, const std::vector<std::shared_ptr<Stream>>& streams) {
  SweepPlan plan;
  for (const auto& s : streams) plan.streams.push_back(s.get());
  if (!r.config.empty()) plan.base = config::loadPlatformFile(r.config);
  for (const std::string& s : r.rings) plan.rings.push_back(parseRingSize(s));
  sortRings(plan.rings);
  for (const std::string& p : r.policies) plan.policies.push_back(config::catchupPolicy(p));
  // Fault plans: "none" first, then each file (parsed against the first stream's disc).
  plan.plans = {{"none", iop::FaultPlan{}}};
  for (const std::string& f : r.faults)
    plan.plans.emplace_back(stem(f), config::loadFaultPlan(f, streams[0]->disc.get()));
  plan.duration = config::parseTime("--duration", r.duration);
  if (plan.duration <= 0) throw Error("--duration must be positive");
  plan.search.stallAt = config::parseTime("--stall-at", r.stallAt);
  plan.search.maxStall = config::parseTime("--max-stall", r.maxStall);
  plan.search.resolution = config::parseTime("--resolution", r.resolution);
  plan.search.settle = config::parseTime("--settle", r.settle);
  plan.search.popThreshold = parsePopThreshold(r.popThreshold);
  checkStallSearch(plan.search);
  plan.seed = r.seed;
  plan.searchStalls = r.search;
  plan.kernels = {&gs::simd::kernels(), &ipu::simdKernels()};
  return plan;
}

}  // namespace

SweepRunReport sweepRunReport(const SweepRun& run) {
  std::ostringstream line;
  line << "sweep  " << run.stream << "  ring " << run.ring.bankmax << ":" << run.ring.bufmax << "  faults "
       << run.faults << "  " << run.policy << ": late " << run.result.lightmap.framesLate << ", pop max "
       << run.result.pop.value << ", lag max " << run.result.totals.lag.value;
  const auto h = player::runHealth(run.result.lightmap, run.result.totals);
  if (h.verdict == "ok") return {line.str(), {}};
  line << "  " << (h.verdict == "starved" ? "STARVED" : "STUCK");
  std::ostringstream warning;
  warning << run.stream << " ring " << run.ring.bankmax << ":" << run.ring.bufmax << " " << run.policy << ": "
          << player::healthWarning(h);
  return {line.str(), warning.str()};
}

std::string stallSearchLine(const StallRow& row) {
  std::ostringstream line;
  line << "stall  " << row.stream << "  ring " << row.ring.bankmax << ":" << row.ring.bufmax << "  " << row.policy
       << "  " << toString(row.criterion) << ": "
       << (row.result.longest ? (row.result.saturated ? ">= " : "") + fixed(toSeconds(*row.result.longest), 3) + " s"
                              : std::string("fails without a stall"))
       << " (" << row.result.runs << " runs)";
  return line.str();
}

bool reencodes(const ProfileRequest& r) {
  return !r.qscales.empty() || !r.bitrates.empty();
}

ProfileResult profileRun(const ProfileRequest& r, const Reencoder& reencode, const ProfileObserver& observer) {
  if (r.discs.empty()) throw Error("no stream file given (or --plan sweep.toml)");
  if (r.out.empty()) throw Error("--out is required");
  OutputDir dir(r.out, r.force);  // an existing, non-empty --out is refused before the sweep, not after it
  // Streams: every disc as given, then the first one re-encoded at each quantiser and bitrate.
  std::vector<std::shared_ptr<Stream>> streams;
  for (const std::string& d : r.discs) streams.push_back(discStream(d, r.file));
  if (reencodes(r) && !reencode) throw Error("--qscale and --bitrate re-encode, and this program has no encoder");
  if (reencodes(r)) {
    for (auto& s : reencode(*streams[0], r.discs[0], r.qscales, r.bitrates)) streams.push_back(std::move(s));
  }
  const SweepPlan plan = sweepPlan(r, streams);
  // Every sweep run and stall search, for a count of n/N.
  const std::size_t shape = plan.streams.size() * plan.policies.size() * plan.rings.size();
  if (observer.onStart) observer.onStart(shape * plan.plans.size() + (plan.searchStalls ? shape * 2 : 0));
  ProfileResult result;
  try {
    result.data = runSweep(plan, observer.sweep);
  } catch (const gs::GsError& e) {
    throw Error(config::gsConfigMessage(e, r.config));
  }
  for (const std::string& w : writeProfileOutputs(result.data, dir.directory()))
    result.written.push_back((dir.finalPath() / w).string());
  if (observer.beforeCommit) observer.beforeCommit();
  dir.commit();
  return result;
}

}  // namespace vbim::runs
