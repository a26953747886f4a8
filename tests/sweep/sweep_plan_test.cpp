// `vbim profile --plan` end to end: the table is the same bytes at any --jobs; shards merged give
// exactly the local run's files, a missing shard is named with the command that re-runs it; the
// summary's intervals are the Wilson intervals of the table's counts; --emit-slurm writes a job
// array; a bad plan is refused with file:line: key; Ctrl-C at any moment of a sweep on two threads
// stops it cleanly.
#include <gtest/gtest.h>

#include <unistd.h>
#include "tests/support/random_interrupts.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch.hpp"
#include "tests/support/soak.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const std::string kPlan = std::string(VBIM_SOURCE_DIR) + "/tests/sweep/plans/array64.toml";
const std::string kSample = std::string(VBIM_SOURCE_DIR) + "/streams/samples/day_clear.vbim";

using Result = vbim::testing::CommandResult;

Result run(const std::string& args) {
  return vbim::testing::runProgram(VBIM_CLI, args);
}

fs::path scratch(const std::string& name) {
  return vbim::testing::scratchPath("sweep_" + name);
}

// Every file under `dir`, relative, with its bytes.
std::map<std::string, std::string> tree(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = vbim::testing::readFileBytes(e.path());
  }
  return files;
}

void expectSameTree(const fs::path& a, const fs::path& b) {
  const auto ta = tree(a), tb = tree(b);
  ASSERT_FALSE(ta.empty());
  EXPECT_EQ(ta.size(), tb.size());
  for (const auto& [name, bytes] : ta) {
    ASSERT_TRUE(tb.count(name)) << name << " only in " << a;
    EXPECT_TRUE(bytes == tb.at(name)) << name << " differs between " << a << " and " << b;
  }
}

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> f;
  std::stringstream s(line);
  for (std::string x; std::getline(s, x, ',');) f.push_back(x);
  return f;
}

TEST(SweepPlan, TableIsTheSameBytesAtAnyJobCount) {
  const fs::path one = scratch("jobs1"), two = scratch("jobs2");
  const Result r1 = run("profile --plan " + kPlan + " --jobs 1 --out " + one.string());
  ASSERT_EQ(r1.status, 0) << r1.output;
  const Result r2 = run("profile --plan " + kPlan + " --jobs 2 --out " + two.string());
  ASSERT_EQ(r2.status, 0) << r2.output;
  for (const char* f :
       {"cases.csv", "cases.jsonl", "summary.csv", "summary.txt", "plots/probability_1.png", "plots/probability_1.svg"})
    EXPECT_TRUE(fs::exists(one / f)) << f;
  expectSameTree(one, two);
  const std::string csv = vbim::testing::readFileBytes(one / "cases.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 64);
  const std::string jsonl = vbim::testing::readFileBytes(one / "cases.jsonl");
  EXPECT_EQ(std::count(jsonl.begin(), jsonl.end(), '\n'), 64);
  // The draws differ (seeded per template and draw), and some stalls make a late frame, some not.
  std::istringstream in(csv);
  std::string header, line;
  std::getline(in, header);
  const std::vector<std::string> h = fields(header);
  const auto col = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(h.begin(), h.end(), name) - h.begin());
  };
  std::set<std::string> drawn;
  int late = 0, onTime = 0;
  while (std::getline(in, line)) {
    const std::vector<std::string> f = fields(line);
    drawn.insert(f[col("drawn")]);
    (std::stoi(f[col("frames_late")]) > 0 ? late : onTime)++;
    EXPECT_EQ(f[col("status")], "ok") << line;
  }
  EXPECT_EQ(drawn.size(), 16u);
  EXPECT_GT(late, 0);
  EXPECT_GT(onTime, 0);
  fs::remove_all(one);
  fs::remove_all(two);
}

TEST(SweepPlan, ShardsMergeIntoExactlyTheLocalRun) {
  const fs::path local = scratch("local"), shards = scratch("shards"), merged = scratch("merged");
  ASSERT_EQ(run("profile --plan " + kPlan + " --out " + local.string()).status, 0);
  for (int k : {1, 3}) {
    const Result r =
        run("profile --plan " + kPlan + " --shard " + std::to_string(k) + "/3 --jobs 1 --out " + shards.string());
    ASSERT_EQ(r.status, 0) << r.output;
  }
  // A shard writes only its own directory.
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(shards)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"shard-1-of-3", "shard-3-of-3"}));
  // Shard 2 missing: named, with the command that runs it alone; nothing written.
  const Result missing = run("profile --plan " + kPlan + " --merge " + shards.string() + " --out " + merged.string());
  EXPECT_EQ(missing.status, 3) << missing.output;  // docs/sweeps.md: re-run these shards, not bad input
  EXPECT_NE(missing.output.find("missing or unfinished: 2"), std::string::npos) << missing.output;
  EXPECT_NE(missing.output.find("--shard 2/3 --out " + shards.string()), std::string::npos) << missing.output;
  EXPECT_NE(missing.output.find("sbatch --array=2 "), std::string::npos) << missing.output;
  EXPECT_FALSE(fs::exists(merged));
  const auto before = tree(shards / "shard-1-of-3");
  ASSERT_EQ(run("profile --plan " + kPlan + " --shard 2/3 --out " + shards.string()).status, 0);
  EXPECT_TRUE(tree(shards / "shard-1-of-3") == before) << "running shard 2 changed shard 1";
  const Result m = run("profile --plan " + kPlan + " --merge " + shards.string() + " --out " + merged.string());
  ASSERT_EQ(m.status, 0) << m.output;
  expectSameTree(local, merged);
  // Shards of another plan are refused.
  const fs::path other = scratch("other.toml");
  std::ofstream(other) << vbim::testing::readFileBytes(kPlan) << "\n# edited\n";
  std::string text = vbim::testing::readFileBytes(other);
  const std::string stream = "../../../streams/samples/day_clear.vbim";
  text.replace(text.find(stream), stream.size(), kSample);
  std::ofstream(other, std::ios::trunc) << text;
  const Result foreign =
      run("profile --plan " + other.string() + " --merge " + shards.string() + " --out " + merged.string() + "2");
  EXPECT_NE(foreign.status, 0);
  EXPECT_NE(foreign.output.find("another plan"), std::string::npos) << foreign.output;
  for (const fs::path& p : {local, shards, merged, other}) fs::remove_all(p);
}

TEST(SweepPlan, SummaryIsTheWilsonIntervalOfTheTable) {
  const fs::path out = scratch("summary");
  ASSERT_EQ(run("profile --plan " + kPlan + " --out " + out.string()).status, 0);
  // Count late frames per (bufmax, policy) from the table.
  std::istringstream cases(vbim::testing::readFileBytes(out / "cases.csv"));
  std::string line;
  std::getline(cases, line);
  const std::vector<std::string> h = fields(line);
  const auto col = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(h.begin(), h.end(), name) - h.begin());
  };
  std::map<std::string, std::pair<int, int>> counts;  // hits, cases
  while (std::getline(cases, line)) {
    const std::vector<std::string> f = fields(line);
    auto& c = counts[f[col("bufmax_sectors")] + "/" + f[col("policy")]];
    c.first += std::stoi(f[col("frames_late")]) > 0 ? 1 : 0;
    c.second += 1;
  }
  std::istringstream summary(vbim::testing::readFileBytes(out / "summary.csv"));
  std::getline(summary, line);
  const std::vector<std::string> sh = fields(line);
  const auto scol = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(sh.begin(), sh.end(), name) - sh.begin());
  };
  int rows = 0;
  while (std::getline(summary, line)) {
    const std::vector<std::string> f = fields(line);
    const auto [k, n] = counts.at(f[scol("bufmax_sectors")] + "/" + f[scol("policy")]);
    EXPECT_EQ(std::stoi(f[scol("cases")]), n);
    EXPECT_EQ(std::stoi(f[scol("hits")]), k);
    // Wilson score interval at z = 1.96 (Wilson 1927), recomputed here.
    const double z = 1.959963984540054, p = static_cast<double>(k) / n;
    const double centre = (p + z * z / (2.0 * n)) / (1 + z * z / n);
    const double half = z / (1 + z * z / n) * std::sqrt(p * (1 - p) / n + z * z / (4.0 * n * n));
    EXPECT_NEAR(std::stod(f[scol("p")]), p, 1e-6);
    EXPECT_NEAR(std::stod(f[scol("ci_low")]), std::max(0.0, centre - half), 1e-6);
    EXPECT_NEAR(std::stod(f[scol("ci_high")]), std::min(1.0, centre + half), 1e-6);
    ++rows;
  }
  EXPECT_EQ(rows, 4);  // 2 rings x 2 policies; seeds and draws are the Monte Carlo axes
  fs::remove_all(out);
}

TEST(SweepPlan, StuckAndStarvedCasesAreMarkedAndCounted) {
  // One stall from 0 s that outlasts the run (never a frame: starved), one from 4 s (stuck), none.
  const fs::path dir = scratch("health");
  fs::create_directories(dir);
  {
    std::ofstream plan(dir / "plan.toml");
    plan << "[run]\nduration = \"15s\"\nseed = 1\n[axes]\nstreams = [\"" << kSample
         << "\"]\nrings = [\"4:8\"]\npolicies = [\"blend-through\"]\n"
            "[[faults]]\nname = \"none\"\n"
            "[[faults]]\nname = \"from0\"\n[[faults.fault]]\nkind = \"stall\"\nat = \"0s\"\nduration = \"600s\"\n"
            "[[faults]]\nname = \"from4\"\n[[faults.fault]]\nkind = \"stall\"\nat = \"4s\"\nduration = \"600s\"\n";
  }
  const Result r = run("profile --plan " + (dir / "plan.toml").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("vbim profile: warning: 1 stuck and 1 starved of 3 cases"), std::string::npos) << r.output;
  std::istringstream cases(vbim::testing::readFileBytes(dir / "out" / "cases.csv"));
  std::string line;
  std::getline(cases, line);
  const std::vector<std::string> h = fields(line);
  const auto col = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(h.begin(), h.end(), name) - h.begin());
  };
  ASSERT_LT(col("health"), h.size()) << line;
  std::map<std::string, std::string> verdict;
  while (std::getline(cases, line)) {
    const std::vector<std::string> f = fields(line);
    verdict[f[col("faults")]] = f[col("health")];
  }
  EXPECT_EQ(verdict["none"], "ok");
  EXPECT_EQ(verdict["from0"], "starved");
  EXPECT_EQ(verdict["from4"], "stuck");
  fs::remove_all(dir);
}

TEST(SweepPlan, EmitSlurmWritesAJobArray) {
  const fs::path out = scratch("slurm");
  const Result r = run("profile --plan " + kPlan + " --emit-slurm " + out.string() +
                       " --shards 4 --account lab42 --cpus-per-task 2");
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string script = vbim::testing::readFileBytes(out / "sweep.sbatch");
  EXPECT_EQ(vbim::testing::readFileBytes(out / "plan.toml"), vbim::testing::readFileBytes(kPlan));
  for (const char* want : {"#SBATCH --array=1-4\n", "#SBATCH --cpus-per-task=2\n", "#SBATCH --time=", "#SBATCH --mem=",
                           "#SBATCH --account=lab42\n", "##SBATCH --partition=", "--shard \"$SLURM_ARRAY_TASK_ID/4\""})
    EXPECT_NE(script.find(want), std::string::npos) << want << "\n" << script;
  EXPECT_TRUE(fs::is_directory(out / "shards"));
  fs::remove_all(out);
}

TEST(SweepPlan, BadPlansNameFileLineAndKey) {
  const fs::path dir = scratch("bad");
  fs::create_directories(dir);
  const fs::path plan = dir / "plan.toml";
  const std::string streams = "[axes]\nstreams = [\"" + kSample + "\"]\n";
  struct Case {
    std::string text, expect;
  } cases[] = {
      {streams + "rings = [\"4x8\"]\n", "plan.toml:3: key 'axes.rings'"},
      {streams + "policies = [\"fast\"]\n", "plan.toml:3: key 'axes.policies'"},
      {streams + "colour = 1\n", "plan.toml:3: key 'axes.colour': unknown key"},
      {"[run]\nduration = \"-1s\"\n" + streams, "plan.toml:2: key 'run.duration'"},
      {streams + "[[axes.platform]]\nkey = \"gs.nonsense\"\nvalues = [1]\n", "plan.toml:5: key 'gs.nonsense'"},
      {streams + "[[faults]]\nname = \"x\"\ndraws = 4\n[[faults.fault]]\nkind = \"stall\"\nat = \"1s\"\n"
                 "duration = { min = \"2s\", max = \"1s\" }\n",
       "plan.toml:9: fault 'stall', field 'duration'"},
      {streams + "[[probability]]\nmeasure = \"longest_stall_s\"\nop = \">\"\nvalue = 1\n",
       "plan.toml:4: key 'probability.measure'"},
      {"[axes]\nrings = [\"4:8\"]\n", "key 'axes.streams': missing"},
  };
  for (const Case& c : cases) {
    std::ofstream(plan, std::ios::trunc) << c.text;
    const Result r = run("profile --plan " + plan.string() + " --out " + (dir / "out").string());
    EXPECT_NE(r.status, 0) << c.text;
    EXPECT_NE(r.output.find(c.expect), std::string::npos) << c.text << "\n" << r.output;
    EXPECT_FALSE(fs::exists(dir / "out"));
  }
  const Result jobs = run("profile --plan " + kPlan + " --jobs 1000 --out " + (dir / "out").string());
  EXPECT_NE(jobs.status, 0);
  EXPECT_NE(jobs.output.find("--jobs 1000: at most"), std::string::npos) << jobs.output;
  fs::remove_all(dir);
}

}  // namespace

namespace {

// Ctrl-C or SIGTERM at any moment of a sweep on two threads (issue #33): the progress report that
// saw the signal on a worker thread ended the process in std::terminate (exit 134, no message), found
// by hand at about 3 s into examples/sweeps/survivable-stall.toml. 40 runs of the 64-case plan with
// --jobs 2, four at a time, one SIGINT or SIGTERM each at a random moment
// (tests/support/random_interrupts.hpp): each ends complete or stopped with 130/143 and its message,
// its output directory absent, nothing hidden left.
TEST(SweepPlan, InterruptsAtRandomMomentsOfATwoThreadSweepLeaveNothingBehind) {
  const fs::path dir = scratch("random_interrupts");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const int wanted = vbim::testing::soakRepetitions(40, 12);
  const std::vector<vbim::testing::InterruptedRun> runs = vbim::testing::runWithRandomInterrupts(
      dir, VBIM_CLI, "  echo \"profile --plan " + kPlan + " --jobs 2 --out $D/r$1\"", 1, wanted);
  int complete = 0, stopped = 0;
  for (const vbim::testing::InterruptedRun& r : runs) {
    const fs::path out = dir / ("r" + std::to_string(r.index));
    if (r.status == 0) {
      ++complete;
      EXPECT_TRUE(fs::exists(out / "summary.txt")) << "run " << r.index << " exited 0 without its tables\n" << r.log;
      continue;
    }
    ++stopped;
    vbim::testing::expectStoppedCleanly(r);
    EXPECT_FALSE(fs::exists(out)) << "run " << r.index << " was stopped but left " << out;
  }
  EXPECT_EQ(static_cast<int>(runs.size()), wanted);
  std::cout << stopped << " stopped, " << complete << " complete\n";
  // The moments reach into the sweep (22 of 40 stopped on a loaded machine). Not asserted at the
  // sanitizer suite's 12 runs: there start-up, the tables and the plots take most of each run and
  // the cases a small part, 2 of 12 were stopped, and the count would be chance; the runs are still
  // each checked above.
  if (wanted == 40) {
    EXPECT_GT(stopped, wanted / 4) << complete << " complete";
  }
  vbim::testing::expectNothingHiddenLeft(dir);
  fs::remove_all(dir);
}

}  // namespace
