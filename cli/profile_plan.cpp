#include "cli/profile_plan.hpp"

#include <sched.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>

#include "cli/command.hpp"
#include "cli/output_dir.hpp"
#include "cli/profile_outputs.hpp"
#include "cli/progress.hpp"
#include "cli/sweep_outputs.hpp"
#include "config/sweep_plan_toml.hpp"
#include "gs/blend_simd.hpp"
#include "iop/memory_disc.hpp"
#include "ipu/simd/simd_kernels.hpp"
#include "player/report.hpp"
#include "player/scenario.hpp"
#include "streams/authoring/error.hpp"
#include "streams/authoring/transcode.hpp"

namespace vbim::cli {

namespace {

namespace fs = std::filesystem;
using namespace player::profile;
using sweep::recordFromJson;
using sweep::recordJson;

constexpr unsigned kMaxJobs = 64;

// Cores this process may run on (a Slurm task or taskset sees fewer than the machine has).
unsigned coresAvailable() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1u, std::thread::hardware_concurrency());
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// FNV-1a over the plan's bytes: shards of one plan carry it, a merge refuses any other.
std::string digest(const std::string& text) {
  std::uint64_t h = 1469598103934665603ULL;
  for (char c : text) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  char b[24];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h));
  return b;
}

std::pair<std::size_t, std::size_t> parseShard(const std::string& text) {
  std::size_t k = 0, n = 0;
  int used = 0;
  if (std::sscanf(text.c_str(), "%zu/%zu%n", &k, &n, &used) != 2 || static_cast<std::size_t>(used) != text.size() ||
      n < 1 || k < 1 || k > n)
    throw Exit(2, "--shard '" + text + "': expected K/N with 1 <= K <= N, e.g. 3/8");
  return {k, n};
}

std::string shardName(std::size_t k, std::size_t n) {
  return "shard-" + std::to_string(k) + "-of-" + std::to_string(n);
}

// The plan's streams: files opened per case (a file handle is not shared between threads), the
// re-encoded ones made once, before the cases run, and read from memory by all.
class Streams {
 public:
  Streams(const SweepPlanSpec& plan, const std::vector<PlanCase>& cases) : plan_(plan), memory_(plan.streams.size()) {
    std::vector<bool> needed(plan.streams.size(), false);
    for (const PlanCase& c : cases) needed[c.stream] = true;
    for (std::size_t i = 0; i < plan.streams.size(); ++i) {
      if (!needed[i]) continue;
      const StreamSpec& s = plan.streams[i];
      try {
        bareStream(s.path);  // the file is a stream: checked once, before any case runs
      } catch (const iop::DiscError& e) {
        throw Exit(2, e.what());
      }
      if (s.bitrate == 0 && s.qscale == 0) continue;
      streams::EncoderSettings e;
      if (s.bitrate > 0) e.bitrate = s.bitrate;
      if (s.qscale > 0) e.qscale = s.qscale;
      std::vector<std::uint8_t> bytes;
      try {
        bytes = streams::transcodeStream(s.path, e);
      } catch (const streams::AuthoringError& x) {
        throw Exit(2, x.what());
      }
      memory_[i] = memoryStream(s.label, std::move(bytes));
    }
  }
  std::shared_ptr<Stream> open(std::size_t i) const {
    if (memory_[i]) return memory_[i];
    auto s = bareStream(plan_.streams[i].path);
    s->label = plan_.streams[i].label;
    return s;
  }

 private:
  static std::shared_ptr<Stream> memoryStream(const std::string& label, std::vector<std::uint8_t> bytes) {
    auto s = std::make_shared<Stream>();
    s->label = label;
    const auto sectors = static_cast<std::int64_t>(bytes.size() / iop::kSectorBytes);
    auto disc = std::make_shared<iop::MemoryDisc>(player::kBareFileLba + sectors + player::kBareFilePadSectors,
                                                  label + " (re-encoded in memory)");
    disc->addFile(label + ".vbim", player::kBareFileLba, std::move(bytes));
    s->file = *disc->find(label + ".vbim");
    s->disc = std::move(disc);
    return s;
  }
  const SweepPlanSpec& plan_;
  std::vector<std::shared_ptr<Stream>> memory_;
};

struct LoadedPlan {
  SweepPlanSpec spec;
  std::vector<PlanCase> cases;
  std::string digest;
};

LoadedPlan load(const std::string& path) {
  LoadedPlan p;
  try {
    p.spec = config::loadSweepPlan(path);
  } catch (const ConfigError& e) {
    throw Exit(2, e.what());
  }
  p.cases = expandPlan(p.spec);
  p.digest = digest(readFile(path));
  return p;
}

unsigned jobsFor(const PlanRequest& r) {
  const unsigned cores = coresAvailable();
  if (r.jobs == 0) return std::min(cores, kMaxJobs);
  if (r.jobs > kMaxJobs) {
    throw Exit(2, "--jobs " + std::to_string(r.jobs) + ": at most " + std::to_string(kMaxJobs) +
                      " (this machine offers " + std::to_string(cores) + " cores)");
  }
  if (r.jobs > cores) {
    std::cerr << "vbim profile: --jobs " << r.jobs << " is more than the " << cores
              << " cores available: cases will share cores (no faster, same results)\n";
  }
  return r.jobs;
}

std::string clock(double seconds) {
  const auto s = static_cast<long long>(std::llround(seconds));
  char b[32];
  if (s >= 3600) {
    std::snprintf(b, sizeof b, "%lldh%02lldm", s / 3600, s / 60 % 60);
  } else {
    std::snprintf(b, sizeof b, "%lldm%02llds", s / 60, s % 60);
  }
  return b;
}

// Runs `cases` with progress on stderr (n/N, failures, time left): redrawn on a terminal, or one
// line every few seconds when --progress asks for it elsewhere.
std::vector<CaseRecord> runWithProgress(const LoadedPlan& p, const std::vector<PlanCase>& cases, unsigned jobs,
                                        bool forceProgress) {
  const Streams streams(p.spec, cases);
  Progress bar("vbim profile", "cases", forceProgress);
  const auto start = std::chrono::steady_clock::now();  // host time: the progress line only
  auto lastShown = start;
  std::size_t done = 0, failed = 0;
  RunOptions options;
  options.jobs = jobs;
  options.kernels = {&gs::simd::kernels(), &ipu::simdKernels()};
  const bool terminal = ::isatty(STDERR_FILENO) == 1;
  auto onDone = [&](const CaseRecord& rec) {
    ++done;
    if (!rec.ok) ++failed;
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start).count();
    if (!terminal && done < cases.size() && now - lastShown < std::chrono::seconds(5)) return;
    lastShown = now;
    const double left = elapsed / static_cast<double>(done) * static_cast<double>(cases.size() - done);
    bar.show(static_cast<double>(done), static_cast<double>(cases.size()),
             std::to_string(failed) + " failed, " + clock(left) + " left");
  };
  std::vector<CaseRecord> records = runPlanCases(
      p.spec, cases, [&](std::size_t s) { return streams.open(s); }, options, onDone);
  bar.finish();
  return records;
}

void reportFailures(const std::vector<CaseRecord>& records) {
  std::size_t failed = 0;
  for (const CaseRecord& r : records) {
    if (r.ok) continue;
    if (++failed <= 5) std::cerr << "vbim profile: case " << r.number << " failed: " << r.error << "\n";
  }
  if (failed > 5) std::cerr << "vbim profile: ... and " << failed - 5 << " more failed cases (see the table)\n";
  // Runs that stopped showing frames are findings, not failures: counted once, listed in the table.
  std::size_t stuck = 0, starved = 0;
  for (const CaseRecord& r : records) {
    if (!r.ok) continue;
    const std::string verdict = player::runHealth(r.result.lightmap, r.result.totals).verdict;
    stuck += verdict == "stuck" ? 1 : 0;
    starved += verdict == "starved" ? 1 : 0;
  }
  if (stuck + starved > 0) {
    std::cerr << "vbim profile: warning: " << stuck << " stuck and " << starved << " starved of " << records.size()
              << " cases: the display stopped for their last 5 s or more (the health column of cases.csv; "
                 "docs/player.md, \"Stuck and starved runs\")\n";
  }
}

void writeAll(const LoadedPlan& p, const std::vector<CaseRecord>& records, OutputDir& dir) {
  const std::vector<std::string> written = sweep::writeSweepOutputs(p.spec, p.cases, records, dir);
  dir.commit();
  for (const std::string& line : sweep::summaryLines(p.spec, p.cases, records)) std::cout << line << "\n";
  std::cout << "Open:\n";
  for (const std::string& w : written) std::cout << "  " << (dir.finalPath() / w).string() << "\n";
}

void runLocal(const PlanRequest& r, const LoadedPlan& p) {
  OutputDir dir(r.out, r.force);  // an existing --out is refused before the sweep, not after it
  const unsigned jobs = jobsFor(r);
  const auto wall0 = std::chrono::steady_clock::now();
  const std::vector<CaseRecord> records = runWithProgress(p, p.cases, jobs, r.progress);
  reportFailures(records);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  writeAll(p, records, dir);
  std::cout << "ran " << p.cases.size() << " cases with " << jobs << " job(s) in " << cli::profile::fixed(wall, 1)
            << " s of host time\n";
}

// One shard into --out/shard-K-of-N/ (complete or absent; no other shard's files touched): its
// records (shard.jsonl) and what it is (shard.json).
void runShard(const PlanRequest& r, const LoadedPlan& p) {
  const auto [k, n] = parseShard(r.shard);
  const auto [first, last] = shardRange(p.cases.size(), k, n);
  OutputDir dir(fs::path(r.out) / shardName(k, n), r.force);
  const std::vector<PlanCase> mine(p.cases.begin() + static_cast<std::ptrdiff_t>(first),
                                   p.cases.begin() + static_cast<std::ptrdiff_t>(last));
  const unsigned jobs = jobsFor(r);
  const std::vector<CaseRecord> records = runWithProgress(p, mine, jobs, r.progress);
  reportFailures(records);
  std::size_t failed = 0;
  {
    std::ofstream o(dir.path("shard.jsonl"), std::ios::binary);
    for (const CaseRecord& rec : records) {
      o << recordJson(rec).dump() << "\n";
      failed += rec.ok ? 0 : 1;
    }
  }
  {
    nlohmann::ordered_json j;
    j["plan_digest"] = p.digest;
    j["shard"] = k;
    j["shards"] = n;
    j["first_case"] = first;
    j["end_case"] = last;
    j["failed_cases"] = failed;
    std::ofstream o(dir.path("shard.json"), std::ios::binary);
    o << j.dump(2) << "\n";
  }
  dir.commit();
  std::cout << "shard " << k << "/" << n << ": cases " << first << ".." << (last == first ? first : last - 1) << ", "
            << failed << " failed -> " << dir.finalPath().string() << "\n";
}

// --merge DIR: every shard-K-of-N of one N, all of this plan; the outputs a local run writes.
void runMerge(const PlanRequest& r, const LoadedPlan& p) {
  std::map<std::size_t, std::map<std::size_t, fs::path>> byCount;  // N -> K -> dir
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(r.merge, ec)) {
    std::size_t k = 0, n = 0;
    int used = 0;
    const std::string name = e.path().filename().string();
    if (std::sscanf(name.c_str(), "shard-%zu-of-%zu%n", &k, &n, &used) == 2 &&
        static_cast<std::size_t>(used) == name.size() && e.is_directory())
      byCount[n][k] = e.path();
  }
  if (ec) throw Exit(2, "--merge " + r.merge + ": cannot read the directory: " + ec.message());
  if (byCount.empty()) throw Exit(2, "--merge " + r.merge + ": no shard-K-of-N directories in it");
  if (byCount.size() > 1) throw Exit(2, "--merge " + r.merge + ": shards of different counts N; keep one run's");
  const std::size_t n = byCount.begin()->first;
  const auto& shards = byCount.begin()->second;
  std::vector<std::size_t> missing;
  std::vector<CaseRecord> records;
  std::vector<std::string> failedShards;
  for (std::size_t k = 1; k <= n; ++k) {
    const auto it = shards.find(k);
    if (it == shards.end()) {
      missing.push_back(k);
      continue;
    }
    nlohmann::json info;
    try {
      info = nlohmann::json::parse(readFile((it->second / "shard.json").string()));
      if (info.at("plan_digest").get<std::string>() != p.digest) {
        throw Exit(2, (it->second / "shard.json").string() + ": made from another plan (digest " +
                          info.at("plan_digest").get<std::string>() + ", this plan's is " + p.digest + ")");
      }
      const auto [first, last] = shardRange(p.cases.size(), k, n);
      std::istringstream lines(readFile((it->second / "shard.jsonl").string()));
      std::size_t expect = first;
      for (std::string line; std::getline(lines, line);) {
        CaseRecord rec = recordFromJson(nlohmann::json::parse(line));
        if (rec.number != expect) throw std::runtime_error("case " + std::to_string(rec.number) + " out of place");
        ++expect;
        records.push_back(std::move(rec));
      }
      if (expect != last) {
        throw std::runtime_error("holds cases up to " + std::to_string(expect) + " of " + std::to_string(first) + ".." +
                                 std::to_string(last - 1));
      }
      if (info.at("failed_cases").get<std::size_t>() > 0) {
        failedShards.push_back(std::to_string(k) + " (" + std::to_string(info.at("failed_cases").get<std::size_t>()) +
                               " failed cases)");
      }
    } catch (const Exit&) {
      throw;
    } catch (const std::exception& e) {
      throw Exit(2, it->second.string() + ": not a complete shard of this plan: " + e.what() +
                        " (re-run it: vbim profile --plan " + r.plan + " --shard " + std::to_string(k) + "/" +
                        std::to_string(n) + " --out " + r.merge + " --force)");
    }
  }
  if (!missing.empty()) {
    std::string list, array, commands;
    for (std::size_t k : missing) {
      list += (list.empty() ? "" : ", ") + std::to_string(k);
      array += (array.empty() ? "" : ",") + std::to_string(k);
      commands += "\n  vbim profile --plan " + r.plan + " --shard " + std::to_string(k) + "/" + std::to_string(n) +
                  " --out " + r.merge;
    }
    throw Exit(3, "--merge " + r.merge + ": " + std::to_string(missing.size()) + " of " + std::to_string(n) +
                      " shards missing or unfinished: " + list + "\nre-run each alone:" + commands +
                      "\nor re-submit only those array tasks: sbatch --array=" + array + " SCRIPT");
  }
  for (const std::string& f : failedShards)
    std::cerr << "vbim profile: shard " << f << ": kept in the table with status failed\n";
  OutputDir dir(r.out, r.force);
  writeAll(p, records, dir);
  std::cout << "merged " << n << " shards, " << records.size() << " cases\n";
}

std::string hms(double seconds) {
  const auto s = static_cast<long long>(std::ceil(seconds));
  char b[32];
  std::snprintf(b, sizeof b, "%02lld:%02lld:%02lld", s / 3600, s / 60 % 60, s % 60);
  return b;
}

std::string selfPath() {
  std::error_code ec;
  const fs::path p = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("vbim") : p.string();
}

// --emit-slurm DIR: a job array with one task per shard, its time and memory from a measured
// per-case cost (the slowest of up to three cases spread over the plan, run here).
void emitSlurm(const PlanRequest& r, const LoadedPlan& p) {
  OutputDir dir(r.emitSlurm, r.force);
  std::vector<PlanCase> sample{p.cases.front()};
  if (p.cases.size() > 2) sample.push_back(p.cases[p.cases.size() / 2]);
  if (p.cases.size() > 1) sample.push_back(p.cases.back());
  double perCase = 0;
  for (const PlanCase& c : sample) {
    const auto t0 = std::chrono::steady_clock::now();
    runWithProgress(p, {c}, 1, false);
    perCase = std::max(perCase, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double rssMb = static_cast<double>(usage.ru_maxrss) / 1024.0;
  const std::size_t cases = p.cases.size();
  // Default shards: about ten minutes of work each (on one core), at most one per case.
  std::size_t shards = r.shards;
  if (shards == 0) shards = static_cast<std::size_t>(std::ceil(perCase * static_cast<double>(cases) / 600.0));
  shards = std::clamp<std::size_t>(shards, 1, cases);
  const std::size_t perShard = (cases + shards - 1) / shards;
  const unsigned cpus = std::max(1u, r.cpusPerTask);
  // Three times the measured cost (cluster nodes may be slower, other jobs share them) plus a
  // minute for start-up; memory: twice the peak seen here per concurrent case, at least 256 MB.
  const double seconds = 60.0 + 3.0 * perCase * std::ceil(static_cast<double>(perShard) / cpus);
  const auto memMb = static_cast<long long>(std::max(256.0, std::ceil(2.0 * rssMb * cpus)));
  const fs::path finalDir = fs::absolute(dir.finalPath());
  const fs::path plan = fs::absolute(r.plan).lexically_normal();
  fs::copy_file(r.plan, dir.path("plan.toml"));
  fs::create_directories(dir.path("logs"));
  fs::create_directories(dir.path("shards"));
  {
    std::ofstream o(dir.path("sweep.sbatch"), std::ios::binary);
    o << "#!/bin/sh\n"
      << "# A Slurm job array for the sweep plan " << plan.string() << " (written by vbim profile --emit-slurm).\n"
      << "# " << cases << " cases in " << shards << " shards of up to " << perShard << "; measured "
      << cli::profile::fixed(perCase, 3) << " s and " << cli::profile::fixed(rssMb, 0)
      << " MB per case here. Submit: sbatch " << (finalDir / "sweep.sbatch").string() << "\n"
      << "# Then: vbim profile --plan " << plan.string() << " --merge " << (finalDir / "shards").string()
      << " --out RESULTS\n"
      << "# plan.toml beside this script is the plan as submitted (its digest: " << p.digest << ").\n"
      << "#SBATCH --job-name=vbim-sweep\n"
      << "#SBATCH --array=1-" << shards << "\n"
      << "#SBATCH --ntasks=1\n"
      << "#SBATCH --cpus-per-task=" << cpus << "\n"
      << "#SBATCH --time=" << hms(seconds) << "\n"
      << "#SBATCH --mem=" << memMb << "M\n"
      << "#SBATCH --output=" << (finalDir / "logs" / "%A_%a.out").string() << "\n"
      << (r.partition.empty() ? "##SBATCH --partition=PARTITION   (a site's partition: give --partition or edit)\n"
                              : "#SBATCH --partition=" + r.partition + "\n")
      << (r.account.empty() ? "##SBATCH --account=ACCOUNT   (a site's account: give --account or edit)\n"
                            : "#SBATCH --account=" + r.account + "\n")
      << "set -eu\n"
      << "exec " << selfPath() << " profile --plan " << plan.string() << " --shard \"$SLURM_ARRAY_TASK_ID/" << shards
      << "\" --jobs \"${SLURM_CPUS_PER_TASK:-1}\" --progress --force --out " << (finalDir / "shards").string() << "\n";
  }
  fs::permissions(dir.path("sweep.sbatch"), fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                  fs::perm_options::add);
  dir.commit();
  std::cout << "wrote " << (finalDir / "sweep.sbatch").string() << ": " << shards << " array tasks, --time "
            << hms(seconds) << ", --mem " << memMb << "M (measured " << cli::profile::fixed(perCase, 3)
            << " s per case)\n"
            << "submit: sbatch " << (finalDir / "sweep.sbatch").string() << "\nthen:   vbim profile --plan " << r.plan
            << " --merge " << (finalDir / "shards").string() << " --out RESULTS\n";
}

}  // namespace

void addPlanOptions(CLI::App& cmd, PlanRequest& r) {
  cmd.add_option("--plan", r.plan, "Sweep plan (TOML, docs/sweeps.md): run its cases instead of the options above");
  cmd.add_option("--jobs", r.jobs, "Sweep plan: cases run at once (default: the cores available)");
  cmd.add_flag("--progress", r.progress, "Sweep plan: progress on stderr even when it is not a terminal");
  cmd.add_option("--shard", r.shard, "Sweep plan: run only shard K of N into --out/shard-K-of-N");
  cmd.add_option("--merge", r.merge, "Sweep plan: join the shards in this directory into --out");
  cmd.add_option("--emit-slurm", r.emitSlurm, "Sweep plan: write a Slurm job-array script and the plan here");
  cmd.add_option("--shards", r.shards, "--emit-slurm: array tasks (default: about 10 minutes of cases each)");
  cmd.add_option("--partition", r.partition, "--emit-slurm: the Slurm partition");
  cmd.add_option("--account", r.account, "--emit-slurm: the Slurm account");
  cmd.add_option("--cpus-per-task", r.cpusPerTask, "--emit-slurm: cores per array task (its --jobs)")
      ->capture_default_str();
}

bool planMode(const PlanRequest& r) {
  return !r.plan.empty() || !r.merge.empty() || !r.emitSlurm.empty() || !r.shard.empty();
}

void runPlan(const PlanRequest& r) {
  if (r.plan.empty()) throw Exit(2, "--shard, --merge and --emit-slurm need --plan (the sweep plan)");
  const int modes = (r.shard.empty() ? 0 : 1) + (r.merge.empty() ? 0 : 1) + (r.emitSlurm.empty() ? 0 : 1);
  if (modes > 1) throw Exit(2, "give one of --shard, --merge and --emit-slurm");
  if (r.emitSlurm.empty() && r.out.empty()) throw Exit(2, "--out is required");
  const LoadedPlan p = load(r.plan);
  if (!r.emitSlurm.empty()) return emitSlurm(r, p);
  if (!r.merge.empty()) return runMerge(r, p);
  if (!r.shard.empty()) return runShard(r, p);
  runLocal(r, p);
}

}  // namespace vbim::cli
