// The command line as its users' habits expect (issue #33, docs/cli.md): unknown options named with
// a suggestion before any other complaint, short options (-o, -q, -v, -V), `vbim version`, --json
// summaries of play and profile, and "-" for a stream on stdin.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/support/run_command.hpp"
#include "tests/support/scratch.hpp"

namespace {

namespace fs = std::filesystem;

using Result = vbim::testing::CommandResult;

const std::string kVbim = VBIM_BINARY;
const std::string kSample = std::string(VBIM_SOURCE_DIR) + "/streams/samples/day_clear.vbim";

Result run(const std::string& args) {
  return vbim::testing::runProgram(kVbim, args);
}

// Runs `vbim args` with stdout into `out`; the result holds stderr alone.
Result runToFile(const std::string& args, const fs::path& out) {
  return vbim::testing::runCommand("{ " + kVbim + " " + args + " > '" + out.string() + "'; }");
}

fs::path scratch(const std::string& name) {
  return vbim::testing::scratchDir("habits_" + name);
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Plain string scans rather than <regex>: GCC 12 warns falsely inside <regex> in the -O1 sanitizer
// build, and -Werror turns that into a build failure (it stopped CI once).

// "vbim MAJOR.MINOR.PATCH\n", each part one or more digits.
bool isVersionLine(const std::string& line) {
  const std::string prefix = "vbim ";
  if (line.rfind(prefix, 0) != 0 || line.empty() || line.back() != '\n') return false;
  int parts = 0;
  std::size_t at = prefix.size();
  const std::size_t end = line.size() - 1;
  while (at < end) {
    const std::size_t digits = line.find_first_not_of("0123456789", at);
    const std::size_t stop = digits == std::string::npos ? end : std::min(digits, end);
    if (stop == at) return false;
    ++parts;
    at = stop;
    if (at < end) {
      if (line[at] != '.') return false;
      ++at;
      if (at == end) return false;
    }
  }
  return parts == 3;
}

// Every "--name" in `text` whose name starts with a lowercase letter and goes on in [a-z0-9-].
std::vector<std::string> longOptionsIn(const std::string& text) {
  const auto nameChar = [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-'; };
  std::vector<std::string> names;
  std::size_t at = text.find("--");
  while (at != std::string::npos) {
    std::size_t end = at + 2;
    if (end >= text.size() || text[end] < 'a' || text[end] > 'z') {
      at = text.find("--", at + 1);
      continue;
    }
    while (end < text.size() && nameChar(text[end])) ++end;
    names.push_back(text.substr(at, end - at));
    at = text.find("--", end);
  }
  return names;
}

// One line on stderr naming the command, the unknown option and the suggestion; exit 2.
void expectUnknown(const std::string& args, const std::string& command, const std::string& typed,
                   const std::string& meant) {
  const Result r = run(args);
  EXPECT_EQ(r.status, 2) << args << "\n" << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << args << "\n" << r.output;
  EXPECT_EQ(r.output.rfind("vbim " + command + ": unknown option '" + typed + "'", 0), 0u) << args << "\n" << r.output;
  EXPECT_TRUE(has(r.output, "did you mean '" + meant + "'")) << args << "\n" << r.output;
  EXPECT_FALSE(has(r.output, "required")) << args << "\n" << r.output;
}

TEST(CliHabits, AnUnknownOptionIsNamedFirstWithTheClosestOne) {
  const fs::path d = scratch("unknown");
  // Before: "--out is required" (the mistyped option was not named at all).
  expectUnknown("play " + kSample + " --outt " + (d / "o").string(), "play", "--outt", "--out");
  // Before: CLI11's "The following arguments were not expected: 7 --sede".
  expectUnknown("play " + kSample + " --sede 7 --out " + (d / "o").string(), "play", "--sede", "--seed");
  expectUnknown("decode " + kSample + " --thraeds 2 -o " + (d / "o").string(), "decode", "--thraeds", "--threads");
  expectUnknown("info " + kSample + " --jsn", "info", "--jsn", "--json");
  expectUnknown("profile " + kSample + " --no-serch --out " + (d / "o").string(), "profile", "--no-serch",
                "--no-search");
  expectUnknown("play " + kSample + " --seed=7 --durration=1s -o " + (d / "o").string(), "play", "--durration",
                "--duration");
  EXPECT_FALSE(fs::exists(d / "o"));
  // A value that looks like an option is still a value (checked as one), not an unknown option.
  const Result negative = run("play " + kSample + " --seed -1 --out " + (d / "o").string());
  EXPECT_EQ(negative.status, 2);
  EXPECT_TRUE(has(negative.output, "is negative")) << negative.output;
  // Nothing close: named, with no guess.
  const Result far = run("play " + kSample + " --zzzzzz --out " + (d / "o").string());
  EXPECT_EQ(far.status, 2);
  EXPECT_TRUE(has(far.output, "unknown option '--zzzzzz'")) << far.output;
  EXPECT_FALSE(has(far.output, "did you mean")) << far.output;
  // A mistyped command.
  const Result command = run("pla " + kSample);
  EXPECT_EQ(command.status, 2);
  EXPECT_TRUE(has(command.output, "unknown command 'pla' (did you mean 'play'?)")) << command.output;
  fs::remove_all(d);
}

TEST(CliHabits, EveryCommandThatWritesTakesShortOptions) {
  for (const char* cmd : {"play", "decode", "replay", "vectors", "demo", "author", "lightmap", "render", "profile"}) {
    const Result help = run(std::string(cmd) + " --help");
    ASSERT_EQ(help.status, 0) << cmd;
    EXPECT_TRUE(has(help.output, "-o,--out")) << cmd << "\n" << help.output;
    EXPECT_TRUE(has(help.output, "-q,--quiet")) << cmd << "\n" << help.output;
    EXPECT_TRUE(has(help.output, "-v,--verbose")) << cmd << "\n" << help.output;
    // --quiet's help names --json only where the command has it (it said so on decode, which has none).
    EXPECT_EQ(has(help.output, "errors (and --json)"), has(help.output, "\n  --json")) << cmd << "\n" << help.output;
  }
  // Commands whose output is what they print have no --quiet.
  for (const char* cmd : {"info", "config"}) {
    EXPECT_FALSE(has(run(std::string(cmd) + " --help").output, "--quiet")) << cmd;
  }
  const Result longVersion = run("--version");
  ASSERT_EQ(longVersion.status, 0);
  EXPECT_TRUE(isVersionLine(longVersion.output)) << longVersion.output;
  EXPECT_EQ(run("-V").output, longVersion.output);
  const Result version = run("version");
  EXPECT_EQ(version.status, 0);
  EXPECT_EQ(version.output, longVersion.output);

  const fs::path d = scratch("short");
  const Result play = run("play " + kSample + " --duration 1s -o " + (d / "run").string());
  EXPECT_EQ(play.status, 0) << play.output;
  EXPECT_TRUE(fs::exists(d / "run" / "stats.json"));
  fs::remove_all(d);
}

TEST(CliHabits, QuietPrintsOnlyErrorsAndVerboseListsTheFilesWritten) {
  const fs::path d = scratch("quiet");
  const Result quiet = run("play " + kSample + " --duration 2s -q -o " + (d / "q").string());
  EXPECT_EQ(quiet.status, 0);
  EXPECT_EQ(quiet.output, "");
  EXPECT_TRUE(fs::exists(d / "q" / "stats.json"));
  const Result quietDecode = run("decode " + kSample + " --quiet -o " + (d / "frames").string());
  EXPECT_EQ(quietDecode.status, 0);
  EXPECT_EQ(quietDecode.output, "");
  // Errors still speak.
  const Result error = run("play " + kSample + " --duration 2s -q -o " + (d / "q").string());
  EXPECT_EQ(error.status, 2);
  EXPECT_TRUE(has(error.output, "vbim play: ")) << error.output;

  // Verbose: progress lines even into a pipe, and every file written with its size, on stderr.
  const Result verbose = runToFile("play " + kSample + " --duration 2s -v -o " + (d / "v").string(), d / "stdout");
  EXPECT_EQ(verbose.status, 0);
  EXPECT_TRUE(has(verbose.output, "vbim play [")) << verbose.output;
  EXPECT_TRUE(has(verbose.output, "vbim play: wrote " + (d / "v" / "stats.json").string() + " (")) << verbose.output;
  EXPECT_TRUE(has(slurp(d / "stdout"), "played 2.0 s of")) << slurp(d / "stdout");
  // Not both.
  EXPECT_EQ(run("play " + kSample + " -q -v -o " + (d / "x").string()).status, 2);
  fs::remove_all(d);
}

TEST(CliHabits, PlayJsonSummaryHoldsTheTextSummarysFacts) {
  const fs::path d = scratch("playjson");
  const fs::path plan = d / "stall.toml";
  std::ofstream(plan) << "[[fault]]\nkind = \"stall\"\nat = \"2s\"\nduration = \"3s\"\n";
  const std::string args = "play " + kSample + " --duration 8s --faults " + plan.string() + " --every 240 ";
  const Result text = run(args + "-o " + (d / "text").string());
  ASSERT_EQ(text.status, 0) << text.output;
  // -v writes its list on stderr: stdout stays one JSON document.
  const Result json = runToFile(args + "--json -v -o " + (d / "json").string(), d / "summary.json");
  ASSERT_EQ(json.status, 0) << json.output;
  const nlohmann::json j = nlohmann::json::parse(slurp(d / "summary.json"));
  const nlohmann::json stats = nlohmann::json::parse(slurp(d / "json" / "stats.json"));
  EXPECT_EQ(j["disc"], kSample);
  EXPECT_EQ(j["simulated_s"], 8.0);
  EXPECT_EQ(j["vsyncs"], stats["vsyncs_recorded"]);
  EXPECT_EQ(j["frames"]["shown"], stats["frames"]["lightmap"]["frames_shown"]);
  EXPECT_EQ(j["frames"]["late"], stats["frames"]["lightmap"]["frames_late"]);
  EXPECT_EQ(j["frames"]["dropped"], stats["frames"]["lightmap"]["frames_dropped"]);
  EXPECT_EQ(j["lag"]["max"], stats["lag"]["lightmap"]["max"]);
  EXPECT_EQ(j["ring"]["underruns"], stats["ring"]["underruns"]);
  EXPECT_EQ(j["reference_run"], true);
  EXPECT_EQ(j["health"]["verdict"], stats["health"]["verdict"]);
  EXPECT_GT(j["images_written"].get<int>(), 0);
  EXPECT_TRUE(j["pictures"].contains("cpu_s"));
  // The text summary says the same numbers.
  const std::string frames = "frames: " + std::to_string(j["frames"]["shown"].get<int>()) + " shown, " +
                             std::to_string(j["frames"]["late"].get<int>()) + " late";
  EXPECT_TRUE(has(text.output, frames)) << text.output << "\n" << j.dump(2);
  fs::remove_all(d);
}

TEST(CliHabits, JsonIsValidWhateverBytesTheInputsNameHas) {
  const fs::path d = scratch("utf8");
  const fs::path odd = d / std::string("day\xff\xfe.vbim");
  fs::copy_file(kSample, odd);
  const Result r =
      runToFile("play '" + odd.string() + "' --duration 1s --json -o " + (d / "run").string(), d / "summary.json");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(has(r.output, "not UTF-8")) << r.output;
  const nlohmann::json j = nlohmann::json::parse(slurp(d / "summary.json"));
  EXPECT_TRUE(has(j["disc"].get<std::string>(), "day\xef\xbf\xbd")) << j["disc"];
  fs::remove_all(d);
}

TEST(CliHabits, ProfileJsonSummaryListsEveryRun) {
  const fs::path d = scratch("profilejson");
  const Result r = runToFile(
      "profile " + kSample + " --ring 4:16,5:160 --duration 3s --no-search --json -o " + (d / "prof").string(),
      d / "summary.json");
  ASSERT_EQ(r.status, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(slurp(d / "summary.json"));
  ASSERT_EQ(j["sweep_runs"].size(), 2u) << j.dump(2);
  EXPECT_EQ(j["sweep_runs"][0]["ring"]["banks"], 4);
  EXPECT_EQ(j["sweep_runs"][0]["faults"], "none");
  EXPECT_EQ(j["stall_searches"].size(), 0u);
  ASSERT_FALSE(j["outputs"].empty());
  for (const auto& path : j["outputs"]) EXPECT_TRUE(fs::exists(path.get<std::string>())) << path;
  fs::remove_all(d);
}

TEST(CliHabits, ADashReadsTheStreamFromStdin) {
  const fs::path d = scratch("stdin");
  const Result fromFile = run("info " + kSample);
  const Result fromStdin = run("info - < " + kSample);
  ASSERT_EQ(fromStdin.status, 0) << fromStdin.output;
  std::string expected = fromFile.output;
  expected.replace(expected.find(kSample), kSample.size(), "<stdin>");
  EXPECT_EQ(fromStdin.output, expected);
  EXPECT_EQ(nlohmann::json::parse(run("info - --json < " + kSample).output)["authoring"],
            nlohmann::json::parse(run("info " + kSample + " --json").output)["authoring"]);

  // play: the same bytes as from the file; the run names "<stdin>" with the stream's digest.
  ASSERT_EQ(run("play " + kSample + " --duration 3s -o " + (d / "file").string()).status, 0);
  const Result play =
      vbim::testing::runCommand("cat " + kSample + " | " + kVbim + " play - --duration 3s -o " + (d / "pipe").string());
  ASSERT_EQ(play.status, 0) << play.output;
  EXPECT_TRUE(has(play.output, "played 3.0 s of <stdin>")) << play.output;
  EXPECT_EQ(slurp(d / "pipe" / "hashes.txt"), slurp(d / "file" / "hashes.txt"));
  const nlohmann::json a = nlohmann::json::parse(slurp(d / "file" / "stats.json"))["run"]["disc"];
  const nlohmann::json b = nlohmann::json::parse(slurp(d / "pipe" / "stats.json"))["run"]["disc"];
  EXPECT_EQ(b["path"], "<stdin>");
  EXPECT_EQ(b["sha256"], a["sha256"]);

  const Result decode =
      vbim::testing::runCommand("cat " + kSample + " | " + kVbim + " decode - -o " + (d / "frames").string());
  ASSERT_EQ(decode.status, 0) << decode.output;
  EXPECT_TRUE(has(decode.output, "decoded 24 pictures")) << decode.output;

  // A damaged stream on stdin: the message names <stdin>, never a path of ours.
  const Result cut =
      vbim::testing::runCommand("head -c 5000 " + kSample + " | " + kVbim + " play - -o " + (d / "cut").string());
  EXPECT_EQ(cut.status, 2);
  EXPECT_TRUE(has(cut.output, "vbim play: <stdin>: ")) << cut.output;
  EXPECT_FALSE(has(cut.output, "/proc/")) << cut.output;
  EXPECT_FALSE(fs::exists(d / "cut"));
  fs::remove_all(d);
}

TEST(CliHabits, ThreadsMeanTheSameOnEveryCommand) {
  for (const char* cmd : {"play", "decode", "lightmap"}) {
    const Result help = run(std::string(cmd) + " --help");
    EXPECT_TRUE(has(help.output, "--threads UINT=1 ")) << cmd << "\n" << help.output;
    EXPECT_TRUE(has(help.output, "0: one per hardware thread")) << cmd << "\n" << help.output;
  }
  const fs::path d = scratch("threads");
  ASSERT_EQ(run("play " + kSample + " --duration 3s -o " + (d / "one").string()).status, 0);
  ASSERT_EQ(run("play " + kSample + " --duration 3s --threads 0 -o " + (d / "all").string()).status, 0);
  EXPECT_EQ(slurp(d / "one" / "hashes.txt"), slurp(d / "all" / "hashes.txt"));
  ASSERT_EQ(run("decode " + kSample + " --threads 0 -o " + (d / "frames").string()).status, 0);
  fs::remove_all(d);
}

TEST(CliHabits, AConfigThatPassesTheCheckIsOneLine) {
  const fs::path d = scratch("config");
  const fs::path cfg = d / "platform.toml";
  ASSERT_EQ(vbim::testing::runCommand(kVbim + " config > " + cfg.string()).status, 0);
  const Result check = run("config --check " + cfg.string());
  EXPECT_EQ(check.status, 0);
  EXPECT_EQ(check.output, cfg.string() + ": valid\n");
  const Result both = run("config --check " + cfg.string() + " --faults " + std::string(VBIM_SOURCE_DIR) +
                          "/examples/fault-plans/stall.toml");
  EXPECT_EQ(both.status, 0);
  EXPECT_EQ(std::count(both.output.begin(), both.output.end(), '\n'), 2) << both.output;
  // The effective config, when asked for: the line on stderr, the TOML on stdout.
  const Result effective = runToFile("config --check " + cfg.string() + " --effective", d / "effective.toml");
  EXPECT_EQ(effective.status, 0);
  EXPECT_EQ(effective.output, cfg.string() + ": valid; the effective config follows\n");
  EXPECT_EQ(slurp(d / "effective.toml"), slurp(cfg));
  fs::remove_all(d);
}

// The man page and the completions are generated from the options --help shows, for every command.
TEST(CliHabits, ManPageAndCompletionsNameEveryCommandAndOption) {
  const fs::path d = scratch("generate");
  for (const char* kind : {"man", "bash", "zsh"}) {
    const Result r =
        vbim::testing::runProgram(VBIM_FULL_BINARY, std::string("--generate ") + kind + " " + (d / kind).string());
    ASSERT_EQ(r.status, 0) << kind << "\n" << r.output;
  }
  const std::string man = slurp(d / "man");
  const std::string bash = slurp(d / "bash");
  const std::string zsh = slurp(d / "zsh");
  EXPECT_EQ(man.rfind(".TH VBIM 1 ", 0), 0u);
  const Result list = run("--help");
  int options = 0;
  for (const char* cmd : {"play", "info", "decode", "config", "vectors", "replay", "demo", "author", "lightmap",
                          "render", "profile", "version"}) {
    ASSERT_TRUE(has(list.output, std::string("  ") + cmd + " ")) << cmd;
    EXPECT_TRUE(has(man, std::string(".SS \"vbim ") + cmd)) << cmd;
    EXPECT_TRUE(has(bash, std::string("    ") + cmd + ")\n      opts=\"")) << cmd;
    EXPECT_TRUE(has(zsh, std::string("    ") + cmd + ")\n")) << cmd;
    // Every long option the command's --help shows.
    const std::string help = run(std::string(cmd) + " --help").output;
    for (const std::string& name : longOptionsIn(help)) {
      if (!has(help, "  " + name) && !has(help, "," + name)) continue;  // named in a description only
      std::string roff;
      for (char c : name) roff += c == '-' ? std::string("\\-") : std::string(1, c);
      ++options;
      EXPECT_TRUE(has(man, roff)) << cmd << " " << name;
      EXPECT_TRUE(has(bash, name)) << cmd << " " << name;
      EXPECT_TRUE(has(zsh, name)) << cmd << " " << name;
    }
  }
  EXPECT_GT(options, 100);  // the loop above saw the commands' options
  // bash accepts the script, and it completes commands and options.
  const Result complete = vbim::testing::runCommand(
      "bash -c 'source " + (d / "bash").string() +
      " && complete -p vbim && COMP_WORDS=(vbim pla) COMP_CWORD=1 && _vbim && echo \"${COMPREPLY[*]}\" && "
      "COMP_WORDS=(vbim play --ou) COMP_CWORD=2 && _vbim && echo \"${COMPREPLY[*]}\"'");
  EXPECT_EQ(complete.status, 0) << complete.output;
  EXPECT_TRUE(has(complete.output, "-F _vbim vbim\nplay\n--out\n")) << complete.output;
  // man reads the page without a warning.
  const Result page = vbim::testing::runCommand("MANWIDTH=80 man -l " + (d / "man").string() + " 2>&1 >/dev/null");
  EXPECT_EQ(page.output, "");
  fs::remove_all(d);
}

// The bash completion as bash-completion loads it (from completions/vbim under
// BASH_COMPLETION_USER_DIR, as `cmake --install` puts it in share/bash-completion/completions), run
// in bash with COMP_WORDS as bash fills it at a Tab: commands, options, and the values of every
// option with a fixed set (the checks --help shows: CLI11's IsMember, cli::oneOf), a list's next
// item after a comma, and nothing (not a file name) after an option that takes a number.
TEST(CliHabits, BashCompletesCommandsOptionsAndValues) {
  const std::string loader = "/usr/share/bash-completion/bash_completion";
  ASSERT_TRUE(fs::exists(loader)) << loader << " is missing: install bash-completion (scripts/setup.sh)";
  const fs::path d = scratch("bash");
  fs::create_directories(d / "completions");
  ASSERT_EQ(
      vbim::testing::runProgram(VBIM_FULL_BINARY, "--generate bash " + (d / "completions" / "vbim").string()).status,
      0);
  std::ofstream(d / "zz-only-file") << "";  // what a file name completion would offer
  std::ofstream(d / "complete.sh") << "source " << loader << R"(
_completion_loader vbim
complete -p vbim
t() {
  COMP_WORDS=("$@"); COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); COMP_LINE="$*"; COMP_POINT=${#COMP_LINE}
  COMPREPLY=()
  _vbim 2>/dev/null
  echo "[$*] ${COMPREPLY[*]}"
}
t vbim pla
t vbim help ren
t vbim play x --fau
t vbim play x --force --js
t vbim decode x --format ''
t vbim decode x --idct l
t vbim play x --policy h
t vbim replay x --format e
t vbim profile x --policy blend-through,p
t vbim play x --trace-detail ''
t vbim lightmap --layers-format ''
t vbim config --format g
t vbim decode x --format = y
t vbim play x --seed z
t vbim play x --faults z
t vbim render --width z
)";
  const Result r = vbim::testing::runCommand("cd " + d.string() + " && BASH_COMPLETION_USER_DIR=" + d.string() +
                                             " bash --norc --noprofile complete.sh");
  ASSERT_EQ(r.status, 0) << r.output;
  // The loader registered it (it lists complete's options in its own order).
  const auto registered = r.output.find(" -F _vbim vbim\n");
  ASSERT_NE(registered, std::string::npos) << r.output;
  const std::string expected =
      "[vbim pla] play\n"
      "[vbim help ren] render\n"
      "[vbim play x --fau] --faults\n"
      "[vbim play x --force --js] --json\n"
      "[vbim decode x --format ] png exr yuv rgba\n"
      "[vbim decode x --idct l] libmpeg2\n"
      "[vbim play x --policy h] hard-skip\n"
      "[vbim replay x --format e] exr\n"
      "[vbim profile x --policy blend-through,p] blend-through,play-late\n"
      "[vbim play x --trace-detail ] coalesced full ipu\n"
      "[vbim lightmap --layers-format ] exr tif\n"
      "[vbim config --format g] gif\n"
      "[vbim decode x --format = y] yuv\n"
      "[vbim play x --seed z] \n"
      "[vbim play x --faults z] zz-only-file\n"
      "[vbim render --width z] \n";
  EXPECT_EQ(r.output.substr(registered + 15), expected);
  fs::remove_all(d);
}

// The zsh completion in an interactive zsh on a pseudo-terminal (zpty), a Tab typed after each line:
// installed in $fpath (share/zsh/site-functions/_vbim) or sourced after compinit. A unique match is
// inserted whole, so the line after the Tab shows what was offered.
TEST(CliHabits, ZshCompletesCommandsOptionsAndValues) {
  ASSERT_EQ(vbim::testing::runCommand("command -v zsh").status, 0) << "zsh is missing: install it (scripts/setup.sh)";
  const fs::path d = scratch("zsh");
  ASSERT_EQ(vbim::testing::runProgram(VBIM_FULL_BINARY, "--generate zsh " + (d / "_vbim").string()).status, 0);
  std::ofstream(d / "zz-only-file") << "";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"vbim pla", "vbim play "},
      {"vbim play --fau", "vbim play --faults "},
      {"vbim play --force --js", "vbim play --force --json "},  // a flag takes no value
      {"vbim decode x --idct l", "vbim decode x --idct libmpeg2 "},
      {"vbim play x --policy h", "vbim play x --policy hard-skip "},
      {"vbim play x --trace-detail f", "vbim play x --trace-detail full "},
      {"vbim decode x --format y", "vbim decode x --format yuv "},
      {"vbim lightmap --format t", "vbim lightmap --format tif "},
      {"vbim profile x --policy blend-through,p", "vbim profile x --policy blend-through,play-late,"},
      {"vbim play x --seed z", "vbim play x --seed z"},  // a number: no file name
      {"vbim play x --faults z", "vbim play x --faults zz-only-file "},
  };
  std::string lines, expected;
  for (const auto& [typed, completed] : cases) {
    lines += " '" + typed + "'";
    expected += "[" + completed + "]\n";
  }
  for (const char* mode : {"fpath", "source"}) {
    const fs::path out = d / (std::string(mode) + ".txt");
    const Result r = vbim::testing::runCommand("cd " + d.string() + " && zsh -f " + std::string(VBIM_SOURCE_DIR) +
                                               "/tests/cli/complete_in_zsh.zsh " + mode + " " + (d / "_vbim").string() +
                                               " " + out.string() + lines);
    EXPECT_EQ(r.status, 0) << mode << "\n" << r.output;
    EXPECT_EQ(slurp(out), expected) << mode;
  }
  fs::remove_all(d);
}

// The progress line on a terminal (`script` gives vbim one) shows the rate and the time left once
// the run has gone half a second (issue #33: it showed `N/600 s` only), as docs/cli.md promises.
TEST(CliHabits, ProgressShowsRateAndTimeLeft) {
  ASSERT_EQ(vbim::testing::runCommand("command -v script").status, 0) << "no `script` (util-linux)";
  const fs::path d = scratch("progress");
  const Result r = vbim::testing::runCommand("script -qec '" + kVbim + " play " + kSample +
                                             " --duration 5000s --no-trace -o " + (d / "run").string() + "' /dev/null");
  ASSERT_EQ(r.status, 0) << r.output;
  // "\rvbim play [###...] 1200/5000 s  1.02e+03 s/s, 4 s left": a redrawn line with both.
  const auto rate = r.output.find(" s/s, ");
  ASSERT_NE(rate, std::string::npos) << r.output;
  const auto line = r.output.rfind("\rvbim play [", rate);
  ASSERT_NE(line, std::string::npos) << r.output;
  const std::string shown = r.output.substr(line + 1, r.output.find('\r', rate) - line - 1);
  EXPECT_TRUE(has(shown, "/5000 s  ")) << shown;
  EXPECT_TRUE(has(shown, " left")) << shown;
  fs::remove_all(d);
}

// The man page's EXIT STATUS lists the codes the program ends with (cli/exit_status.hpp), each of
// which a command here does end with, and man and groff read the page without a warning.
TEST(CliHabits, ManPageListsTheRealExitStatusesAndRendersCleanly) {
  const fs::path d = scratch("manpage");
  ASSERT_EQ(vbim::testing::runProgram(VBIM_FULL_BINARY, "--generate man " + (d / "vbim.1").string()).status, 0);
  const std::string man = slurp(d / "vbim.1");
  const auto section = [&man](const std::string& name) {
    const auto at = man.find(".SH " + name + "\n");
    if (at == std::string::npos) return std::string();
    const auto end = man.find("\n.SH ", at + 1);
    return man.substr(at, end == std::string::npos ? std::string::npos : end - at);
  };
  // ".TP\nCODE\n" per status, in order.
  const std::string exit = section("\"EXIT STATUS\"");
  ASSERT_FALSE(exit.empty()) << man;
  std::vector<int> codes;
  for (auto at = exit.find(".TP\n"); at != std::string::npos; at = exit.find(".TP\n", at + 1))
    codes.push_back(std::stoi(exit.substr(at + 4)));
  EXPECT_EQ(codes, (std::vector<int>{0, 1, 2, 3, 130, 143, 129})) << exit;
  EXPECT_TRUE(has(exit, "SIGINT (Ctrl\\-C)")) << exit;
  for (const char* name : {"ENVIRONMENT", "FILES", "\"SEE ALSO\""}) EXPECT_FALSE(section(name).empty()) << name;
  EXPECT_TRUE(has(section("ENVIRONMENT"), "VBIM_PROGRESS")) << man;

  // The program does end with them: 0, 2 (an unknown option), 129 (SIGHUP) here; 1 in
  // replay_cli_test and port_reference_cli_test (a difference found), 3 in the sweep tests (a merge
  // with a shard missing, tests/sweep/), 130 and 143 in
  // conventions_test (InterruptsAtRandomMomentsLeaveNothingBehind).
  EXPECT_EQ(run("version").status, 0);
  EXPECT_EQ(run("play " + kSample + " --bogus").status, 2);
  const Result hup = vbim::testing::runCommand(
      kVbim + " play " + kSample + " --duration 86400s --no-trace -o " + (d / "hup").string() + " 2>" +
      (d / "hup.log").string() +
      " & pid=$!; for i in $(seq 600); do c=$(awk '/^SigCgt/{print $2}' /proc/$pid/status 2>/dev/null); "
      "[ -n \"$c\" ] && [ $(( 0x$c & 1 )) -ne 0 ] && break; sleep 0.05; done; "  // SIGHUP's handler is in
      "sleep 0.5; kill -HUP $pid; wait $pid; echo status=$?");
  EXPECT_TRUE(has(hup.output, "status=129")) << hup.output << slurp(d / "hup.log");
  EXPECT_TRUE(has(slurp(d / "hup.log"), "stopped by a signal; temporary files removed")) << slurp(d / "hup.log");

  // man and groff: not one warning, at 80 columns as in a terminal.
  const Result page = vbim::testing::runCommand("MANWIDTH=80 man -l " + (d / "vbim.1").string() + " 2>&1 >/dev/null");
  EXPECT_EQ(page.output, "");
  const Result groff = vbim::testing::runCommand("groff -ww -z -man " + (d / "vbim.1").string());
  EXPECT_EQ(groff.status, 0) << groff.output;
  EXPECT_EQ(groff.output, "");
  fs::remove_all(d);
}

}  // namespace
