// A sweep plan as a study (`vbim profile --plan`, docs/sweeps.md): the plan with its cases and
// digest, its streams (re-encoded ones made once, in memory), its cases run on host threads, one
// shard's files and the merge of shards, and the Slurm job array that runs the shards. The command
// (cli/profile_plan.cpp) parses the options and calls runs::planRun (runs/plan_run.hpp), which runs
// the modes; everything they write comes from here. No host time enters any file but the Slurm script's sizing
// (measured by the caller).
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "runtime/error.hpp"
#include "runtime/image.hpp"
#include "sweep/runner.hpp"

namespace vbim::sweep {

struct LoadedPlan {
  SweepPlanSpec spec;
  std::vector<PlanCase> cases;
  std::string digest;  // of the plan file's bytes: shards of one plan carry it, a merge refuses any other
};

// The plan read from `path` (by config::loadSweepPlan, given as `spec`), its cases and digest.
LoadedPlan loadedPlan(SweepPlanSpec spec, const std::string& path);

// FNV-1a over `text`, as 16 hex digits.
std::string planDigest(const std::string& text);

// Re-encodes the stream file of `s` at its settings (qscale or bitrate, GOP structure), filling
// `sources`, when given, with the frames the encoder took (sweep/outputs/reencoded_streams.hpp has
// the one through FFmpeg; programs without FFmpeg pass none).
using StreamTranscoder =
    std::function<std::vector<std::uint8_t>(const StreamSpec& s, std::vector<Yuv420Image>* sources)>;

// True when a stream of the plan is re-encoded (a StreamTranscoder is needed).
bool reencodes(const SweepPlanSpec& plan);

// The plan's streams: files opened per case (a file handle is not shared between threads), the
// re-encoded ones made once by `transcode`, before the cases run, and read from memory by all. Throws
// iop::DiscError or streams::AuthoringError for a stream that cannot be used, vbim::Error for a
// re-encoded one without a `transcode`.
class PlanStreams {
 public:
  PlanStreams(const SweepPlanSpec& plan, const std::vector<PlanCase>& cases, const StreamTranscoder& transcode);
  std::shared_ptr<Stream> open(std::size_t stream) const;

 private:
  const SweepPlanSpec& plan_;
  std::vector<std::shared_ptr<Stream>> memory_;
};

// Runs `cases` of the plan with `jobs` host threads and the SIMD kernels, its re-encoded streams made
// by `transcode`; `onDone` sees each record as it ends (one thread at a time, see sweep/runner.hpp).
std::vector<CaseRecord> runPlanCasesOf(const LoadedPlan& p, const std::vector<PlanCase>& cases, unsigned jobs,
                                       const std::function<void(const CaseRecord&)>& onDone,
                                       const StreamTranscoder& transcode);

// "K/N" with 1 <= K <= N (throws vbim::Error otherwise).
std::pair<std::size_t, std::size_t> parseShard(const std::string& text);
// shard-K-of-N: the directory of one shard.
std::string shardName(std::size_t k, std::size_t n);

// One shard's files in `dir`: its records (shard.jsonl) and what it is (shard.json). Returns the
// number of failed cases.
std::size_t writeShard(const LoadedPlan& p, std::size_t k, std::size_t n, const std::vector<CaseRecord>& records,
                       const std::filesystem::path& dir);

// Shards missing or unfinished: the message names them and how to re-run each (exit 3 in the CLI).
class MissingShards : public Error {
 public:
  using Error::Error;
};

struct Merged {
  std::size_t shards = 0;
  std::vector<CaseRecord> records;        // all cases', in case order
  std::vector<std::string> failedShards;  // "K (n failed cases)"
};

// Every shard-K-of-N of one N in `dir`, all of the plan at `planPath`. Throws vbim::Error for a
// directory that is not that (its message names the command that re-runs a shard), MissingShards.
Merged mergeShards(const LoadedPlan& p, const std::string& planPath, const std::string& dir);

// The cases whose cost sizes a Slurm job: up to three spread over the plan.
std::vector<PlanCase> costSample(const std::vector<PlanCase>& cases);

struct SlurmRequest {
  std::size_t shards = 0;  // 0: about ten minutes of cases each
  std::string partition;
  std::string account;
  unsigned cpusPerTask = 1;
};

struct SlurmJob {
  std::size_t cases = 0;
  std::size_t shards = 0;
  std::size_t perShard = 0;
  unsigned cpus = 1;
  double perCase = 0;   // host seconds measured per case
  double rssMb = 0;     // peak memory measured
  double seconds = 0;   // --time
  long long memMb = 0;  // --mem
};

// The job array's size from the measured cost of one case (seconds, peak MB).
SlurmJob sizeSlurmJob(const SlurmRequest& r, std::size_t cases, double perCase, double rssMb);

// HH:MM:SS, rounded up.
std::string hms(double seconds);

// Writes sweep.sbatch and plan.toml into `dir` (empty logs/ and shards/ beside them); `finalDir`
// is where `dir` will be, `program` the vbim that runs each task.
void writeSlurmJob(const SlurmRequest& r, const SlurmJob& job, const LoadedPlan& p, const std::string& planPath,
                   const std::string& program, const std::filesystem::path& dir, const std::filesystem::path& finalDir);

}  // namespace vbim::sweep
