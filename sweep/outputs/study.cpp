#include "sweep/outputs/study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "gs/simd/blend_simd.hpp"
#include "ipu/simd/simd_kernels.hpp"
#include "sweep/outputs/profile_outputs.hpp"
#include "sweep/outputs/stream_quality.hpp"
#include "sweep/outputs/table.hpp"

namespace vbim::sweep {

namespace {

namespace fs = std::filesystem;

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

std::string planDigest(const std::string& text) {
  std::uint64_t h = 1469598103934665603ULL;
  for (char c : text) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  char b[24];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h));
  return b;
}

LoadedPlan loadedPlan(SweepPlanSpec spec, const std::string& path) {
  LoadedPlan p;
  p.spec = std::move(spec);
  p.cases = expandPlan(p.spec);
  p.digest = planDigest(readFile(path));
  return p;
}

bool reencodes(const SweepPlanSpec& plan) {
  return std::any_of(plan.streams.begin(), plan.streams.end(), [](const StreamSpec& s) { return s.reencoded(); });
}

PlanStreams::PlanStreams(const SweepPlanSpec& plan, const std::vector<PlanCase>& cases,
                         const StreamTranscoder& transcode)
    : plan_(plan), memory_(plan.streams.size()) {
  std::vector<bool> needed(plan.streams.size(), false);
  for (const PlanCase& c : cases) needed[c.stream] = true;
  for (std::size_t i = 0; i < plan.streams.size(); ++i) {
    if (!needed[i]) continue;
    const StreamSpec& s = plan.streams[i];
    bareStream(s.path);  // the file is a stream: checked once, before any case runs
    if (!s.reencoded()) continue;
    if (!transcode) throw Error(s.label + ": a re-encoded stream, and this program has no encoder (run vbim-full)");
    const bool measure = hasMeasure(plan, Measure::Coding);
    std::vector<Yuv420Image> sources;
    std::vector<std::uint8_t> bytes = transcode(s, measure ? &sources : nullptr);
    std::optional<StreamQuality> quality;
    if (measure) quality = measureStreamQuality(bytes, s.label + " (re-encoded in memory)", sources);
    memory_[i] = memoryStream(s.label, std::move(bytes));
    memory_[i]->quality = quality;
  }
}

std::shared_ptr<Stream> PlanStreams::open(std::size_t stream) const {
  if (memory_[stream]) return memory_[stream];
  auto s = bareStream(plan_.streams[stream].path);
  s->label = plan_.streams[stream].label;
  return s;
}

std::vector<CaseRecord> runPlanCasesOf(const LoadedPlan& p, const std::vector<PlanCase>& cases, unsigned jobs,
                                       const std::function<void(const CaseRecord&)>& onDone,
                                       const StreamTranscoder& transcode) {
  const PlanStreams streams(p.spec, cases, transcode);
  RunOptions options;
  options.jobs = jobs;
  options.kernels = {&gs::simd::kernels(), &ipu::simdKernels()};
  return runPlanCases(
      p.spec, cases, [&](std::size_t s) { return streams.open(s); }, options, onDone);
}

std::pair<std::size_t, std::size_t> parseShard(const std::string& text) {
  std::size_t k = 0, n = 0;
  int used = 0;
  if (std::sscanf(text.c_str(), "%zu/%zu%n", &k, &n, &used) != 2 || static_cast<std::size_t>(used) != text.size() ||
      n < 1 || k < 1 || k > n)
    throw Error("--shard '" + text + "': expected K/N with 1 <= K <= N, e.g. 3/8");
  return {k, n};
}

std::string shardName(std::size_t k, std::size_t n) {
  return "shard-" + std::to_string(k) + "-of-" + std::to_string(n);
}

std::size_t writeShard(const LoadedPlan& p, std::size_t k, std::size_t n, const std::vector<CaseRecord>& records,
                       const fs::path& dir) {
  const auto [first, last] = shardRange(p.cases.size(), k, n);
  std::size_t failed = 0;
  {
    std::ofstream o(dir / "shard.jsonl", std::ios::binary);
    for (const CaseRecord& rec : records) {
      o << recordJson(rec).dump() << "\n";
      failed += rec.ok ? 0 : 1;
    }
  }
  nlohmann::ordered_json j;
  j["plan_digest"] = p.digest;
  j["shard"] = k;
  j["shards"] = n;
  j["first_case"] = first;
  j["end_case"] = last;
  j["failed_cases"] = failed;
  std::ofstream o(dir / "shard.json", std::ios::binary);
  o << j.dump(2) << "\n";
  return failed;
}

Merged mergeShards(const LoadedPlan& p, const std::string& planPath, const std::string& dir) {
  std::map<std::size_t, std::map<std::size_t, fs::path>> byCount;  // N -> K -> dir
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    std::size_t k = 0, n = 0;
    int used = 0;
    const std::string name = e.path().filename().string();
    if (std::sscanf(name.c_str(), "shard-%zu-of-%zu%n", &k, &n, &used) == 2 &&
        static_cast<std::size_t>(used) == name.size() && e.is_directory())
      byCount[n][k] = e.path();
  }
  if (ec) throw Error("--merge " + dir + ": cannot read the directory: " + ec.message());
  if (byCount.empty()) throw Error("--merge " + dir + ": no shard-K-of-N directories in it");
  if (byCount.size() > 1) throw Error("--merge " + dir + ": shards of different counts N; keep one run's");
  Merged m;
  const std::size_t n = byCount.begin()->first;
  m.shards = n;
  const auto& shards = byCount.begin()->second;
  std::vector<std::size_t> missing;
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
        throw Error((it->second / "shard.json").string() + ": made from another plan (digest " +
                    info.at("plan_digest").get<std::string>() + ", this plan's is " + p.digest + ")");
      }
      const auto [first, last] = shardRange(p.cases.size(), k, n);
      std::istringstream lines(readFile((it->second / "shard.jsonl").string()));
      std::size_t expect = first;
      for (std::string line; std::getline(lines, line);) {
        CaseRecord rec = recordFromJson(nlohmann::json::parse(line));
        if (rec.number != expect) throw std::runtime_error("case " + std::to_string(rec.number) + " out of place");
        ++expect;
        m.records.push_back(std::move(rec));
      }
      if (expect != last) {
        throw std::runtime_error("holds cases up to " + std::to_string(expect) + " of " + std::to_string(first) + ".." +
                                 std::to_string(last - 1));
      }
      if (info.at("failed_cases").get<std::size_t>() > 0) {
        m.failedShards.push_back(std::to_string(k) + " (" + std::to_string(info.at("failed_cases").get<std::size_t>()) +
                                 " failed cases)");
      }
    } catch (const Error&) {
      throw;
    } catch (const std::exception& e) {
      throw Error(it->second.string() + ": not a complete shard of this plan: " + e.what() +
                  " (re-run it: vbim profile --plan " + planPath + " --shard " + std::to_string(k) + "/" +
                  std::to_string(n) + " --out " + dir + " --force)");
    }
  }
  if (!missing.empty()) {
    std::string list, array, commands;
    for (std::size_t k : missing) {
      list += (list.empty() ? "" : ", ") + std::to_string(k);
      array += (array.empty() ? "" : ",") + std::to_string(k);
      commands += "\n  vbim profile --plan " + planPath + " --shard " + std::to_string(k) + "/" + std::to_string(n) +
                  " --out " + dir;
    }
    throw MissingShards("--merge " + dir + ": " + std::to_string(missing.size()) + " of " + std::to_string(n) +
                        " shards missing or unfinished: " + list + "\nre-run each alone:" + commands +
                        "\nor re-submit only those array tasks: sbatch --array=" + array + " SCRIPT");
  }
  return m;
}

std::vector<PlanCase> costSample(const std::vector<PlanCase>& cases) {
  std::vector<PlanCase> sample{cases.front()};
  if (cases.size() > 2) sample.push_back(cases[cases.size() / 2]);
  if (cases.size() > 1) sample.push_back(cases.back());
  return sample;
}

SlurmJob sizeSlurmJob(const SlurmRequest& r, std::size_t cases, double perCase, double rssMb) {
  SlurmJob j;
  j.cases = cases;
  j.perCase = perCase;
  j.rssMb = rssMb;
  // Default shards: about ten minutes of work each (on one core), at most one per case.
  j.shards = r.shards;
  if (j.shards == 0) j.shards = static_cast<std::size_t>(std::ceil(perCase * static_cast<double>(cases) / 600.0));
  j.shards = std::clamp<std::size_t>(j.shards, 1, cases);
  j.perShard = (cases + j.shards - 1) / j.shards;
  j.cpus = std::max(1u, r.cpusPerTask);
  // Three times the measured cost (cluster nodes may be slower, other jobs share them) plus a
  // minute for start-up; memory: twice the peak seen here per concurrent case, at least 256 MB.
  j.seconds = 60.0 + 3.0 * perCase * std::ceil(static_cast<double>(j.perShard) / j.cpus);
  j.memMb = static_cast<long long>(std::max(256.0, std::ceil(2.0 * rssMb * j.cpus)));
  return j;
}

std::string hms(double seconds) {
  const auto s = static_cast<long long>(std::ceil(seconds));
  char b[32];
  std::snprintf(b, sizeof b, "%02lld:%02lld:%02lld", s / 3600, s / 60 % 60, s % 60);
  return b;
}

void writeSlurmJob(const SlurmRequest& r, const SlurmJob& job, const LoadedPlan& p, const std::string& planPath,
                   const std::string& program, const fs::path& dir, const fs::path& finalDir) {
  const fs::path plan = fs::absolute(planPath).lexically_normal();
  fs::copy_file(planPath, dir / "plan.toml");
  fs::create_directories(dir / "logs");
  fs::create_directories(dir / "shards");
  {
    std::ofstream o(dir / "sweep.sbatch", std::ios::binary);
    o << "#!/bin/sh\n"
      << "# A Slurm job array for the sweep plan " << plan.string() << " (written by vbim profile --emit-slurm).\n"
      << "# " << job.cases << " cases in " << job.shards << " shards of up to " << job.perShard << "; measured "
      << fixed(job.perCase, 3) << " s and " << fixed(job.rssMb, 0) << " MB per case here. Submit: sbatch "
      << (finalDir / "sweep.sbatch").string() << "\n"
      << "# Then: vbim profile --plan " << plan.string() << " --merge " << (finalDir / "shards").string()
      << " --out RESULTS\n"
      << "# plan.toml beside this script is the plan as submitted (its digest: " << p.digest << ").\n"
      << "#SBATCH --job-name=vbim-sweep\n"
      << "#SBATCH --array=1-" << job.shards << "\n"
      << "#SBATCH --ntasks=1\n"
      << "#SBATCH --cpus-per-task=" << job.cpus << "\n"
      << "#SBATCH --time=" << hms(job.seconds) << "\n"
      << "#SBATCH --mem=" << job.memMb << "M\n"
      << "#SBATCH --output=" << (finalDir / "logs" / "%A_%a.out").string() << "\n"
      << (r.partition.empty() ? "##SBATCH --partition=PARTITION   (a site's partition: give --partition or edit)\n"
                              : "#SBATCH --partition=" + r.partition + "\n")
      << (r.account.empty() ? "##SBATCH --account=ACCOUNT   (a site's account: give --account or edit)\n"
                            : "#SBATCH --account=" + r.account + "\n")
      << "set -eu\n"
      << "exec " << program << " profile --plan " << plan.string() << " --shard \"$SLURM_ARRAY_TASK_ID/" << job.shards
      << "\" --jobs \"${SLURM_CPUS_PER_TASK:-1}\" --progress --force --out " << (finalDir / "shards").string() << "\n";
  }
  fs::permissions(dir / "sweep.sbatch", fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                  fs::perm_options::add);
}

}  // namespace vbim::sweep
