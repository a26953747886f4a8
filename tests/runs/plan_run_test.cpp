// `vbim profile --plan`'s modes as library calls (runs/plan_run.hpp), on a plan of two short cases:
// the request's refusals, what the observer is told, the lines and the JSON of a run here, a shard,
// a merge (and one that lacks a shard), and a Slurm job array with its measured cases.
#include "runs/plan_run.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/error.hpp"
#include "tests/support/scratch.hpp"

namespace vbim::runs {
namespace {

namespace fs = std::filesystem;

// Two cases (one ring, one policy, two stall draws), each a few simulated seconds.
std::string planText(const std::string& extraAxes = "") {
  return "[run]\nduration = \"3s\"\nseed = 5\n\n[axes]\nstreams = [\"" + std::string(VBIM_SOURCE_DIR) +
         "/streams/samples/day_clear.vbim\"]\nrings = [\"4:16\"]\npolicies = [\"blend-through\"]\n" + extraAxes +
         "\n[[faults]]\nname = \"stall\"\ndraws = 2\n[[faults.fault]]\nkind = \"stall\"\n"
         "at = { min = \"1s\", max = \"2s\" }\nduration = { min = \"1s\", max = \"2s\" }\n";
}

struct Scratch {
  fs::path dir = vbim::testing::testScratchDir("plan_run");
  ~Scratch() { fs::remove_all(dir); }
  std::string plan(const std::string& text) const {
    const fs::path p = dir / "plan.toml";
    std::ofstream(p) << text;
    return p.string();
  }
};

// What an observer saw, in order.
struct Seen {
  std::vector<std::string> events;
  PlanObserver observer() {
    PlanObserver o;
    o.onCasesStart = [this](std::size_t n, bool measuring) {
      events.push_back((measuring ? "measure " : "start ") + std::to_string(n));
    };
    o.onCaseDone = [this](const sweep::CaseRecord& r) { events.push_back("case " + std::to_string(r.number)); };
    o.onCasesEnd = [this] { events.push_back("end"); };
    o.onWarning = [this](const std::string& w) { events.push_back("warning " + w); };
    return o;
  }
};

std::string messageOf(const PlanRequest& r) {
  try {
    loadPlan(r);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(PlanRun, RequestsThatCannotRunAreRefusedBeforeThePlanIsRead) {
  PlanRequest r;
  r.shard = "1/2";
  EXPECT_TRUE(planMode(r));
  EXPECT_EQ(messageOf(r), "--shard, --merge and --emit-slurm need --plan (the sweep plan)");
  r.plan = "no-such-plan.toml";
  r.merge = "shards";
  EXPECT_EQ(messageOf(r), "give one of --shard, --merge and --emit-slurm");
  r.merge.clear();
  EXPECT_EQ(messageOf(r), "--out is required");
  r.out = "out";
  r.json = true;
  EXPECT_EQ(messageOf(r), "--json summarises a plan run here or merged (--merge), not --shard or --emit-slurm");
  r.json = false;
  EXPECT_NE(messageOf(r).find("no-such-plan.toml"), std::string::npos) << messageOf(r);
  EXPECT_FALSE(planMode(PlanRequest{}));
}

TEST(PlanRun, ReencodingIsAskedOfEveryModeButAMerge) {
  const Scratch s;
  PlanRequest r;
  r.plan = s.plan(planText("qscales = [8]\n"));
  r.out = (s.dir / "out").string();
  const sweep::LoadedPlan p = loadPlan(r);
  EXPECT_TRUE(reencodes(r, p));
  r.merge = "shards";
  EXPECT_FALSE(reencodes(r, p));
  r.plan = s.plan(planText());
  r.merge.clear();
  EXPECT_FALSE(reencodes(r, loadPlan(r)));
}

TEST(PlanRun, ARunHereTellsEachCaseAndPrintsTheSummary) {
  const Scratch s;
  PlanRequest r;
  r.plan = s.plan(planText());
  r.out = (s.dir / "out").string();
  r.jobs = 1;
  Seen seen;
  const PlanResult result = planRun(r, loadPlan(r), {}, seen.observer());
  EXPECT_EQ(seen.events, (std::vector<std::string>{"start 2", "case 0", "case 1", "end"}));
  EXPECT_TRUE(result.json.empty());
  EXPECT_NE(result.text.find("Open:\n  " + r.out + "/cases.csv\n"), std::string::npos) << result.text;
  EXPECT_NE(result.text.find("ran 2 cases with 1 job(s) in "), std::string::npos) << result.text;
  EXPECT_TRUE(fs::exists(s.dir / "out" / "cases.csv"));
  // An existing --out is refused before any case runs.
  Seen again;
  EXPECT_THROW(planRun(r, loadPlan(r), {}, again.observer()), Error);
  EXPECT_TRUE(again.events.empty());
  // --json: the document instead of the lines.
  r.out = (s.dir / "json").string();
  r.json = true;
  const PlanResult json = planRun(r, loadPlan(r), {}, {});
  EXPECT_TRUE(json.text.empty());
  EXPECT_NE(json.json.find("\"cases\": 2"), std::string::npos) << json.json;
}

TEST(PlanRun, ShardsMergeAndAMissingShardIsItsOwnError) {
  const Scratch s;
  PlanRequest r;
  r.plan = s.plan(planText());
  r.out = (s.dir / "shards").string();
  r.shard = "1/2";
  const sweep::LoadedPlan p = loadPlan(r);
  const PlanResult one = planRun(r, p, {}, {});
  EXPECT_EQ(one.text, "shard 1/2: cases 0..0, 0 failed -> " + r.out + "/shard-1-of-2\n");
  PlanRequest m;
  m.plan = r.plan;
  m.merge = r.out;
  m.out = (s.dir / "merged").string();
  EXPECT_THROW(planRun(m, loadPlan(m), {}, {}), sweep::MissingShards);
  EXPECT_FALSE(fs::exists(m.out));
  r.shard = "2/2";
  planRun(r, p, {}, {});
  const PlanResult merged = planRun(m, loadPlan(m), {}, {});
  EXPECT_NE(merged.text.find("merged 2 shards, 2 cases\n"), std::string::npos) << merged.text;
  EXPECT_TRUE(fs::exists(fs::path(m.out) / "cases.csv"));
}

// The command's Ctrl-C check runs once the outputs are written: a stop there leaves no output in
// any mode, and nothing beside it (the temporary directory goes too).
TEST(PlanRun, AStopJustBeforeTheOutputsTakeTheirNamesLeavesNothing) {
  const Scratch s;
  PlanObserver stop;
  int asked = 0;
  stop.beforeCommit = [&asked] {
    ++asked;
    throw std::runtime_error("stop");
  };
  const auto left = [&s] {
    std::vector<std::string> names;
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(s.dir)) {
      names.push_back(fs::relative(e.path(), s.dir).string());
    }
    std::sort(names.begin(), names.end());
    return names;
  };
  PlanRequest here;
  here.plan = s.plan(planText());
  here.out = (s.dir / "out").string();
  here.jobs = 1;
  EXPECT_THROW(planRun(here, loadPlan(here), {}, stop), std::runtime_error);
  EXPECT_EQ(left(), std::vector<std::string>{"plan.toml"});
  // A shard: the shards' directory, which every shard shares, stays, without the shard in it.
  PlanRequest shard = here;
  shard.shard = "1/2";
  EXPECT_THROW(planRun(shard, loadPlan(shard), {}, stop), std::runtime_error);
  EXPECT_EQ(left(), (std::vector<std::string>{"out", "plan.toml"}));
  fs::remove(s.dir / "out");
  PlanRequest slurm;
  slurm.plan = here.plan;
  slurm.emitSlurm = (s.dir / "slurm").string();
  EXPECT_THROW(planRun(slurm, loadPlan(slurm), {}, stop), std::runtime_error);
  EXPECT_EQ(left(), std::vector<std::string>{"plan.toml"});
  EXPECT_EQ(asked, 3);
  // Without the stop the same request runs to the end.
  PlanObserver go;
  go.beforeCommit = [&asked] { ++asked; };
  planRun(here, loadPlan(here), {}, go);
  EXPECT_EQ(asked, 4);
  EXPECT_TRUE(fs::exists(s.dir / "out" / "cases.csv"));
}

TEST(PlanRun, ASlurmJobIsSizedFromCasesMeasuredOneAtATime) {
  const Scratch s;
  PlanRequest r;
  r.plan = s.plan(planText());
  r.emitSlurm = (s.dir / "slurm").string();
  Seen seen;
  const PlanResult result = planRun(r, loadPlan(r), {}, seen.observer());
  ASSERT_FALSE(seen.events.empty());
  EXPECT_EQ(seen.events.front(), "measure 1");
  for (const std::string& e : seen.events) EXPECT_EQ(e.rfind("warning", 0), std::string::npos) << e;
  EXPECT_EQ(result.text.rfind("wrote " + fs::absolute(r.emitSlurm).string() + "/sweep.sbatch: ", 0), 0u) << result.text;
  EXPECT_TRUE(fs::exists(fs::path(r.emitSlurm) / "sweep.sbatch"));
}

}  // namespace
}  // namespace vbim::runs
