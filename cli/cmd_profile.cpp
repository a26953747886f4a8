// vbim profile: sweeps over ring size, stream (several discs, or one re-encoded at several
// quantisers / bitrates), fault plans and catch-up policy; searches the longest drive stall each
// ring size survives; writes sweep.csv, stall.csv, profile.json and plots/*.png and *.svg into --out
// (complete or absent). docs/player.md, "Profiling". --plan: a sweep plan (cli/profile_plan.hpp).
#include <algorithm>
#include <chrono>
#include <iostream>
#include <memory>

#include "cli/command.hpp"
#include "cli/common_options.hpp"
#include "cli/interrupt.hpp"
#include "cli/option_checks.hpp"
#include "cli/profile_json.hpp"
#include "cli/profile_plan.hpp"
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
#include "sweep/outputs/reencoded_streams.hpp"
#include "sweep/profile_sweep.hpp"

namespace vbim::cli {

namespace {

using namespace vbim::sweep;

struct ProfileRequest {
  std::vector<std::string> discs;
  std::string file;  // the stream on each disc image (--file), or empty: its only VBIM stream
  std::string config;
  std::vector<std::string> faults;
  std::vector<std::string> rings{"4:8", "4:16", "4:32", "4:64", "5:160"};
  std::vector<int> qscales;
  std::vector<std::int64_t> bitrates;
  std::vector<std::string> policies{"blend-through"};
  std::uint64_t seed = 1;
  std::string duration = "20s";
  std::string stallAt = "3s";
  std::string maxStall = "20s";
  std::string resolution = "50ms";
  std::string settle = "5s";
  std::string popThreshold = "auto";
  bool search = true;
  bool force = false;
  bool json = false;  // the summary as JSON on stdout, instead of the lines (cli/profile_json.hpp)
  std::string out;
};

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

void runProfile(const ProfileRequest& r) {
  const auto wall0 = std::chrono::steady_clock::now();  // host time: stdout only
  // An existing, non-empty --out is refused before the sweep, not after it.
  runs::OutputDir dir(r.out, r.force);
  // Streams: every disc as given, then the first one re-encoded at each quantiser and bitrate.
  std::vector<std::shared_ptr<Stream>> streams;
  for (const std::string& d : r.discs) streams.push_back(discStream(d, r.file));
  for (auto& s : reencodedStreams(*streams[0], r.discs[0], r.qscales, r.bitrates)) streams.push_back(std::move(s));

  player::PlatformConfig base;
  if (!r.config.empty()) base = config::loadPlatformFile(r.config);
  std::vector<RingSize> rings;
  for (const std::string& s : r.rings) rings.push_back(parseRingSize(s));
  sortRings(rings);
  std::vector<std::string> policies;
  for (const std::string& p : r.policies) policies.push_back(config::catchupPolicy(p));
  // Fault plans: "none" first, then each file (parsed against the first stream's disc).
  std::vector<std::pair<std::string, iop::FaultPlan>> plans{{"none", iop::FaultPlan{}}};
  for (const std::string& f : r.faults) plans.emplace_back(stem(f), config::loadFaultPlan(f, streams[0]->disc.get()));
  const Tick duration = config::parseTime("--duration", r.duration);
  if (duration <= 0) throw Exit(2, "--duration must be positive");
  StallSearch search;
  search.stallAt = config::parseTime("--stall-at", r.stallAt);
  search.maxStall = config::parseTime("--max-stall", r.maxStall);
  search.resolution = config::parseTime("--resolution", r.resolution);
  search.settle = config::parseTime("--settle", r.settle);
  search.popThreshold = parsePopThreshold(r.popThreshold);
  checkStallSearch(search);

  SweepPlan plan;
  for (const auto& s : streams) plan.streams.push_back(s.get());
  plan.base = base;
  plan.plans = std::move(plans);
  plan.policies = policies;
  plan.rings = rings;
  plan.seed = r.seed;
  plan.duration = duration;
  plan.searchStalls = r.search;
  plan.search = search;
  plan.kernels = {&gs::simd::kernels(), &ipu::simdKernels()};
  // Each line counts n/N over every sweep run and stall search, with the host time left at the
  // rate so far (the same count plan mode's progress line shows; host time is never hashed).
  const std::size_t shape = plan.streams.size() * plan.policies.size() * plan.rings.size();
  const std::size_t total = shape * plan.plans.size() + (plan.searchStalls ? shape * 2 : 0);
  const auto started = std::chrono::steady_clock::now();
  auto count = [total, started, done = std::size_t{0}]() mutable {
    ++done;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const double left = elapsed / static_cast<double>(done) * static_cast<double>(total - std::min(done, total));
    return "[" + std::to_string(done) + "/" + std::to_string(total) + ", " + fixed(left, 0) + " s left] ";
  };
  // With --json the lines are in the document at the end, not on stdout.
  std::ostream nowhere(nullptr);
  std::ostream& lines = r.json ? nowhere : std::cout;
  SweepObserver progress;
  progress.onRun = [&count, &lines](const SweepRun& run) {
    checkInterrupted();  // Ctrl-C between runs: the output directory is not started yet
    lines << count() << "sweep  " << run.stream << "  ring " << run.ring.bankmax << ":" << run.ring.bufmax
          << "  faults " << run.faults << "  " << run.policy << ": late " << run.result.lightmap.framesLate
          << ", pop max " << run.result.pop.value << ", lag max " << run.result.totals.lag.value;
    // A run that stopped showing frames is flagged on its line and warned about on stderr.
    // The line is finished (and flushed) before the warning, so the two never share a line.
    const auto h = player::runHealth(run.result.lightmap, run.result.totals);
    if (h.verdict != "ok") lines << "  " << (h.verdict == "starved" ? "STARVED" : "STUCK");
    lines << std::endl;
    if (h.verdict != "ok") {
      std::cerr << "vbim profile: " << run.stream << " ring " << run.ring.bankmax << ":" << run.ring.bufmax << " "
                << run.policy << ": " << player::healthWarning(h) << "\n";
    }
  };
  progress.onStall = [&count, &lines](const StallRow& row) {
    checkInterrupted();
    lines << count() << "stall  " << row.stream << "  ring " << row.ring.bankmax << ":" << row.ring.bufmax << "  "
          << row.policy << "  " << toString(row.criterion) << ": "
          << (row.result.longest ? (row.result.saturated ? ">= " : "") + fixed(toSeconds(*row.result.longest), 3) + " s"
                                 : std::string("fails without a stall"))
          << " (" << row.result.runs << " runs)\n";
  };
  ProfileData data;
  try {
    data = runSweep(plan, progress);
  } catch (const gs::GsError& e) {
    throw Exit(2, config::gsConfigMessage(e, r.config));
  }

  const std::vector<std::string> written = writeProfileOutputs(data, dir.directory());
  dir.commit();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  if (r.json) {
    std::vector<std::string> paths;
    paths.reserve(written.size());
    for (const std::string& w : written) paths.push_back((dir.finalPath() / w).string());
    requestedOut() << profileSummaryJson(data, wall, paths);
    return;
  }
  std::cout << "profiled " << data.sweep.size() << " sweep runs and " << data.stalls.size() << " stall searches in "
            << fixed(wall, 1) << " s of host time\nOpen:\n";
  for (const std::string& w : written) std::cout << "  " << (dir.finalPath() / w).string() << "\n";
}

}  // namespace

void addProfile(CLI::App& app) {
  auto r = std::make_shared<ProfileRequest>();
  auto plan = std::make_shared<PlanRequest>();
  auto* cmd = app.add_subcommand(kProfileCommand.name, kProfileCommand.summary);
  cmd->add_option("disc", r->discs,
                  "VBIM stream file(s) or ISO 9660 disc images; several discs are one sweep axis (not with --plan)")
      ->check(inputFile());
  cmd->add_option("--file", r->file,
                  "The stream on each disc image, e.g. '\\DATA\\DAY.VBI;1' (default: its only VBIM stream)");
  cmd->add_option("--config", r->config, "Platform config (TOML) the sweep starts from")->check(inputFile());
  cmd->add_option("--faults", r->faults, "Fault plan(s) to sweep (repeatable); a run without faults is always included")
      ->check(inputFile());
  cmd->add_option("--ring", r->rings, "Ring sizes BANKS:SECTORS (ring.bankmax:ring.bufmax_sectors)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--qscale", r->qscales, "Also sweep the first disc re-encoded at these quantisers (1..31)")
      ->delimiter(',');
  cmd->add_option("--bitrate", r->bitrates, "Also sweep the first disc re-encoded at these bitrates (bit/s)")
      ->delimiter(',');
  cmd->add_option("--policy", r->policies, "Catch-up policies: blend-through, hard-skip, play-late")
      ->delimiter(',')
      ->check(catchupPolicy())
      ->capture_default_str();
  cmd->add_option("--seed", r->seed, "Seed of every random draw of the model")->capture_default_str();
  cmd->add_option("--duration", r->duration, "Simulated time of each sweep run")->capture_default_str();
  cmd->add_option("--stall-at", r->stallAt, "Stall search: when the stall starts")->capture_default_str();
  cmd->add_option("--max-stall", r->maxStall, "Stall search: longest stall tried")->capture_default_str();
  cmd->add_option("--resolution", r->resolution, "Stall search: bisection stops at this width")->capture_default_str();
  cmd->add_option("--settle", r->settle, "Stall search: simulated time played after the stall ends")
      ->capture_default_str();
  cmd->add_option("--pop-threshold", r->popThreshold,
                  "Stall search: largest pop (per-byte change per vsync) allowed, or auto (the "
                  "configuration's own pop maximum without the stall)")
      ->capture_default_str();
  cmd->add_flag_callback(
      "--no-search", [r] { r->search = false; }, "Skip the survivable-stall search");
  cmd->add_flag("--force", r->force, "Replace a non-empty output directory");
  cmd->add_flag("--json", r->json,
                "Print the summary as JSON on stdout instead of a line per run (docs/cli.md, \"JSON summaries\")");
  cmd->add_option("-o,--out", r->out, "Output directory (written complete or not at all)");
  addPlanOptions(*cmd, *plan);
  cmd->footer(
      "Examples:\n"
      "  vbim profile streams/samples/day_clear.vbim --ring 4:16,5:160 --out prof/\n"
      "  vbim profile streams/samples/day_clear.vbim --faults examples/fault-plans/stall.toml --policy "
      "blend-through,hard-skip --out prof/\n"
      "  vbim profile --plan examples/sweeps/survivable-stall.toml --jobs 2 --out study/\n");
  cmd->callback([r, plan] {
    if (planMode(*plan)) {
      if (!r->discs.empty()) throw Exit(2, "a sweep plan names its streams: give --plan or stream files, not both");
      plan->out = r->out;
      plan->force = r->force;
      plan->json = r->json;
      return runPlan(*plan);
    }
    if (r->discs.empty()) throw Exit(2, "no stream file given (or --plan sweep.toml)");
    if (r->out.empty()) throw Exit(2, "--out is required");
    runProfile(*r);
  });
}

}  // namespace vbim::cli
