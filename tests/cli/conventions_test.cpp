// The one convention of every vbim command (docs/cli.md): `vbim CMD: message` on stderr, exit 2 for
// bad usage or bad input, one line for a usage error with a pointer to the help, `vbim help CMD`,
// strict numbers, and input files checked before any work starts.
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <string>

#include "tests/support/random_interrupts.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch.hpp"
#include "tests/support/soak.hpp"

namespace {

namespace fs = std::filesystem;

using Result = vbim::testing::CommandResult;

Result run(const std::string& args) {
  return vbim::testing::runProgram(VBIM_BINARY, args);
}

const std::string kSample = std::string(VBIM_SOURCE_DIR) + "/streams/samples/day_clear.vbim";

fs::path scratch(const std::string& name) {
  return vbim::testing::scratchPath("conventions_" + name);
}

int lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n' ? 1 : 0;
  return n;
}

// A usage error: one line, prefixed with the command, ending with where the help is; exit 2.
void expectUsageError(const std::string& args, const std::string& command, const std::string& mentions) {
  const Result r = run(args);
  EXPECT_EQ(r.status, 2) << args << "\n" << r.output;
  EXPECT_EQ(lines(r.output), 1) << args << "\n" << r.output;
  EXPECT_EQ(r.output.rfind("vbim " + command + ": ", 0), 0u) << args << "\n" << r.output;
  EXPECT_NE(r.output.find(mentions), std::string::npos) << args << "\n" << r.output;
  EXPECT_NE(r.output.find("see 'vbim " + command + " --help'"), std::string::npos) << args << "\n" << r.output;
}

TEST(CliConventions, HelpCommandIsTheCommandsHelp) {
  for (const char* cmd :
       {"play", "info", "decode", "config", "vectors", "replay", "profile", "author", "render", "demo", "lightmap"}) {
    const Result help = run(std::string("help ") + cmd);
    const Result option = run(std::string(cmd) + " --help");
    EXPECT_EQ(help.status, 0) << cmd << "\n" << help.output;
    EXPECT_EQ(help.output, option.output) << cmd;
    EXPECT_NE(help.output.find("Examples:\n  vbim " + std::string(cmd)), std::string::npos) << help.output;
    // CLI11 leftovers a user cannot read: validator names after the type, flag defaults in braces.
    EXPECT_EQ(help.output.find(":NONNEGATIVE"), std::string::npos) << help.output;
    EXPECT_EQ(help.output.find("{false}"), std::string::npos) << help.output;
    EXPECT_EQ(help.output.find("TEXT:FILE"), std::string::npos) << help.output;
    // A validator's description is kept whole, after the default (it once lost its first word).
    if (help.output.find("--threads") != std::string::npos) {
      const auto option = help.output.find("--threads UINT=");
      ASSERT_NE(option, std::string::npos) << help.output;
      EXPECT_EQ(help.output.find(" (at most the machine's hardware threads)", option),
                help.output.find_first_of(' ', option + 15))
          << help.output;
    }
  }
  EXPECT_EQ(run("help").status, 0);
}

TEST(CliConventions, UsageErrorsAreOneLineWithAPointerToTheHelp) {
  expectUsageError(kSample.substr(0, 0) + "play " + kSample + " --bogus --out x", "play", "--bogus");
  expectUsageError("info", "info", "STREAM");
  expectUsageError("decode " + kSample + " --format gif --out x", "decode", "gif");
  expectUsageError("profile " + kSample + " --out x --bogus", "profile", "--bogus");
}

TEST(CliConventions, NumbersAreParsedStrictly) {
  expectUsageError("play " + kSample + " --seed -1 --out x", "play", "'-1' is negative");
  expectUsageError("play " + kSample + " --seed 18446744073709551616 --out x", "play", "out of range");
  expectUsageError("play " + kSample + " --seed 12abc --out x", "play", "not a whole number");
  expectUsageError("play " + kSample + " --every -1 --out x", "play", "'-1' is negative");
  expectUsageError("decode " + kSample + " --threads -2 --out x", "decode", "'-2' is negative");
  expectUsageError("profile " + kSample + " --seed -5 --out x", "profile", "'-5' is negative");
  // The largest seed is accepted as it is (not clamped, not wrapped): the run starts.
  const Result big = run("config --check /nonexistent-config.toml");
  EXPECT_EQ(big.status, 2) << big.output;
}

TEST(CliConventions, InputFilesAreCheckedAndNamed) {
  const fs::path dir = scratch("inputs");
  fs::create_directories(dir);
  const std::string d = dir.string();
  expectUsageError("play " + kSample + " --faults " + d + " --out x", "play", d + ": is a directory; expected a file");
  expectUsageError("play " + kSample + " --config " + d + " --out x", "play", d + ": is a directory; expected a file");
  expectUsageError("play " + d + "/missing.vbim --out x", "play", "missing.vbim: no such file");
  expectUsageError("info " + d, "info", d + ": is a directory; expected a file");
  expectUsageError("decode " + d + " --out x", "decode", "is a directory");
  expectUsageError("config --check " + d, "config", "is a directory");
  expectUsageError("author --procedural --lighting-config " + d + "/missing.toml --out x.vbim", "author",
                   "missing.toml: no such file");
  expectUsageError("lightmap --config " + d + " --out x", "lightmap", "is a directory");
  expectUsageError("render " + kSample + " --out x", "render", "is a file; expected a directory");
  // Nothing was written.
  EXPECT_FALSE(fs::exists("x"));
  EXPECT_FALSE(fs::exists("x.vbim"));
  fs::remove_all(dir);
}

// A value left out: CLI11 takes the next word, even an option, as the value. The message names the
// option that lost its value and the option taken in its place, whatever the value's own checks.
TEST(CliConventions, AnOptionIsNeverTakenAsAValue) {
  const fs::path dir = scratch("optionvalue");
  fs::create_directories(dir);
  const std::string d = dir.string();
  expectUsageError("config --check --stream " + d, "config", "--check: expects a file, got the option '--stream'");
  expectUsageError("play " + kSample + " --seed --duration 1s --out x", "play",
                   "--seed: expects a number, got the option '--duration'");
  expectUsageError("play " + kSample + " --out --force", "play", "--out: expects a value, got the option '--force'");
  expectUsageError("vectors --check --force", "vectors", "--check: expects a value, got the option '--force'");
  expectUsageError("lightmap --config --frames 2 --out x", "lightmap",
                   "--config: expects a file, got the option '--frames'");
  // --stream given a directory says so, on every command that has the option.
  expectUsageError("config --stream " + d, "config", d + ": is a directory; expected a file");
  expectUsageError("vectors --stream " + d + " --out x", "vectors", d + ": is a directory; expected a file");
  EXPECT_FALSE(fs::exists("x"));
  fs::remove_all(dir);
}

TEST(CliConventions, BadInputNamesTheCommandAndExitsTwo) {
  const Result branch = run("play " + kSample + " --branch 5s=overcast --duration 1s --out x");
  EXPECT_EQ(branch.status, 2) << branch.output;
  EXPECT_EQ(branch.output.rfind("vbim play: --branch '5s=overcast'", 0), 0u) << branch.output;
  const Result streamId = run("decode " + kSample + " --stream-id zz --out x");
  EXPECT_EQ(streamId.status, 2) << streamId.output;
  EXPECT_EQ(streamId.output.rfind("vbim decode: --stream-id zz", 0), 0u) << streamId.output;
  // Not a stream: a bad input (2), named with the file, in info as in every command.
  const fs::path dir = scratch("notastream");
  fs::create_directories(dir);
  const fs::path text = dir / "notes.txt";
  {
    std::FILE* f = std::fopen(text.c_str(), "w");
    std::fputs("not a stream\n", f);
    std::fclose(f);
  }
  for (const std::string cmd : {"info ", "play "}) {
    const Result r = run(cmd + text.string() + (cmd == "play " ? " --out " + (dir / "o").string() : ""));
    EXPECT_EQ(r.status, 2) << cmd << r.output;
    EXPECT_EQ(r.output.rfind("vbim " + cmd.substr(0, cmd.size() - 1) + ": ", 0), 0u) << r.output;
    EXPECT_NE(r.output.find(text.string()), std::string::npos) << r.output;
  }
  fs::remove_all(dir);
}

}  // namespace

namespace {

// `vbim author` with a source and --out only makes a stream every other command accepts on the
// default platform config (issue #15: it used to need --fps, then did not fit the GS's VRAM).
TEST(CliConventions, AuthorDefaultsMakeAStreamTheOtherCommandsAccept) {
  const fs::path dir = scratch("defaults");
  fs::create_directories(dir);
  const std::string d = dir.string();
  const Result author = run("author --procedural --out " + d + "/day.vbim");
  ASSERT_EQ(author.status, 0) << author.output;
  const Result play = run("play " + d + "/day.vbim --duration 4s --every 120 --out " + d + "/run");
  EXPECT_EQ(play.status, 0) << play.output;
  const Result info = run("info " + d + "/day.vbim");
  EXPECT_EQ(info.status, 0) << info.output;
  const Result profile = run("profile " + d + "/day.vbim --ring 4:16 --duration 3s --no-search --out " + d + "/prof");
  EXPECT_EQ(profile.status, 0) << profile.output;
  const Result render = run("render " + d + "/run --no-video --width 64 --height 36 --out " + d + "/pictures");
  EXPECT_EQ(render.status, 0) << render.output;
  fs::remove_all(dir);
}

// A layout that does not fit names the setting that makes it fit.
TEST(CliConventions, AVramOverflowNamesTheWayOut) {
  const fs::path dir = scratch("vram");
  fs::create_directories(dir);
  const std::string d = dir.string();
  const Result author = run("author --procedural --size 512 --frame-count 4 --out " + d + "/big.vbim");
  ASSERT_EQ(author.status, 0) << author.output;
  const Result play = run("play " + d + "/big.vbim --duration 1s --out " + d + "/run");
  EXPECT_EQ(play.status, 2) << play.output;
  EXPECT_NE(play.output.find("the default platform config: VRAM layout does not fit"), std::string::npos)
      << play.output;
  EXPECT_NE(play.output.find("gs.upload_mode = \"strips\""), std::string::npos) << play.output;
  // Following the advice works.
  {
    std::FILE* f = std::fopen((d + "/strips.toml").c_str(), "w");
    std::fputs("[gs]\nupload_mode = \"strips\"\nsky_height = 128\n", f);
    std::fclose(f);
  }
  const Result fixed = run("play " + d + "/big.vbim --config " + d + "/strips.toml --duration 1s --out " + d + "/run");
  EXPECT_EQ(fixed.status, 0) << fixed.output;
  fs::remove_all(dir);
}

}  // namespace

namespace {

// Every command that writes refuses an existing output before any work starts, unless --force.
TEST(CliConventions, ExistingOutputsAreRefusedBeforeAnyWorkUnlessForced) {
  const fs::path dir = scratch("existing");
  fs::create_directories(dir / "full");
  {
    std::FILE* f = std::fopen((dir / "full" / "keep.txt").c_str(), "w");
    std::fputs("keep\n", f);
    std::fclose(f);
  }
  {
    std::FILE* f = std::fopen((dir / "old.vbim").c_str(), "w");
    std::fputs("old\n", f);
    std::fclose(f);
  }
  const std::string d = dir.string();
  for (const std::string& args :
       {"demo --out " + d + "/full", "demo --out " + d + "/full/", "lightmap --out " + d + "/full/",
        "play " + kSample + " --out " + d + "/full/", "profile " + kSample + " --out " + d + "/full",
        "decode " + kSample + " --out " + d + "/full"}) {
    const Result r = run(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find("exists and is not empty (use --force to replace it)"), std::string::npos) << args << "\n"
                                                                                                       << r.output;
    EXPECT_EQ(lines(r.output), 1) << args << ": no work before the refusal\n" << r.output;
  }
  const Result author = run("author --procedural --out " + d + "/old.vbim");
  EXPECT_EQ(author.status, 2) << author.output;
  EXPECT_NE(author.output.find("exists (use --force to replace it)"), std::string::npos) << author.output;
  EXPECT_EQ(vbim::testing::readFileBytes(dir / "old.vbim"), "old\n");
  const Result intoDir = run("author --procedural --out " + d + "/full");
  EXPECT_EQ(intoDir.status, 2) << intoDir.output;
  EXPECT_NE(intoDir.output.find("is a directory; expected the name of the file to write"), std::string::npos)
      << intoDir.output;
  EXPECT_EQ(vbim::testing::readFileBytes(dir / "full" / "keep.txt"), "keep\n");
  fs::remove_all(dir);
}

}  // namespace

namespace {

// A ring that `vbim config --check` refuses (two banks deadlock) is refused by profile too, up front.
TEST(CliConventions, ProfileRefusesARingTheConfigCheckRefuses) {
  const Result r = run("profile " + kSample + " --ring 2:8 --out " + scratch("ring").string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("ring.bankmax = 2 is outside [3, 512]"), std::string::npos) << r.output;
  EXPECT_EQ(lines(r.output), 1) << r.output;
}

}  // namespace

namespace {

// Ctrl-C during a long command leaves no temporary file or directory behind, and the output as it was.
// vbim hands author, lightmap, render, profile and demo to vbim-full (exec). Started with SIGINT
// ignored (a background job of a script), vbim-full used to inherit the ignored SIGINT until its own
// handler was installed, after its libraries had loaded: a Ctrl-C in that time was lost, where play
// has its handler at once. vbim now catches the signals before the exec, which leaves them at their
// default action in vbim-full (execve(2): caught signals are reset, ignored ones stay ignored). A
// stand-in vbim-full beside a copy of vbim prints the dispositions it starts with.
TEST(CliConventions, CommandsRunByVbimFullDoNotStartWithSigintIgnored) {
  const fs::path dir = scratch("handover");
  fs::create_directories(dir);
  fs::copy_file(VBIM_BINARY, dir / "vbim");
  ASSERT_TRUE(vbim::testing::writeTextFile(dir / "vbim-full", "#!/bin/sh\ngrep SigIgn /proc/$$/status\n"));
  fs::permissions(dir / "vbim-full", fs::perms::owner_all);
  // SigIgn is a hexadecimal mask; SIGINT is bit 1.
  const auto sigintIgnored = [](const std::string& output) {
    const auto at = output.find("SigIgn:");
    return at != std::string::npos && (std::stoull(output.substr(at + 7), nullptr, 16) & 2U) != 0;
  };
  const Result shell = vbim::testing::runCommand("trap '' INT; sh -c 'grep SigIgn /proc/$$/status'");
  ASSERT_TRUE(sigintIgnored(shell.output)) << "the test's own start does not ignore SIGINT: " << shell.output;
  // A profile that re-encodes is handed over (vbim runs the others itself, cli/command.hpp).
  const std::string profile = "profile " + kSample + " --qscale 8 --out " + (dir / "profiled").string();
  for (const std::string& command :
       {std::string("author"), std::string("lightmap"), std::string("render"), profile, std::string("demo")}) {
    const Result r = vbim::testing::runCommand("trap '' INT; " + (dir / "vbim").string() + " " + command);
    ASSERT_NE(r.output.find("SigIgn:"), std::string::npos) << command << ": " << r.output;
    EXPECT_FALSE(sigintIgnored(r.output)) << command << ": " << r.output;
  }
  fs::remove_all(dir);
}

// Every command that writes: replay too, which once ran to its end whatever the signal (its loop is
// inside the simulated clock's processes, where no progress line looked at the flag).
TEST(CliConventions, InterruptingRemovesTemporaryFiles) {
  const fs::path dir = scratch("interrupt"), source = scratch("interrupt_source");
  fs::create_directories(dir);
  const std::string d = dir.string(), runDir = (source / "run").string();
  // 240 pictures to render: 30 took 1.1 s on a quiet machine, about when the signal comes.
  ASSERT_EQ(run("play " + kSample + " --duration 60s --every 30 --out " + runDir).status, 0);
  for (const std::string& args :
       {"author --procedural --size 512 --frame-count 400 --out " + d + "/day.vbim",
        "play " + kSample + " --duration 100000s --out " + d + "/run",
        "lightmap --size 512 --frames 400 --out " + d + "/lm",
        "replay " + kSample + " --arrivals " + runDir + "/arrivals.csv --duration 100000s --out " + d + "/replayed",
        "render " + runDir + " --out " + d + "/pictures", "demo --seconds 600 --out " + d + "/demo",
        // 6,000 s a case: 600 s took 0.98 s on a quiet machine, and finished before the signal.
        "profile " + kSample + " --ring 4:16,5:160,6:320 --duration 6000s --out " + d + "/prof"}) {
    // SIGINT once the command catches it (a background job of a script starts with SIGINT ignored,
    // so a signal sent before its handler is installed, as on a loaded machine, would be lost), then
    // a second later, well into its work. The handler shows as bit 2 (SIGINT) of SigCgt.
    // Started with SIGINT ignored, explicitly (trap), as a background job of a script is: each command
    // catches it all the same.
    const auto r = vbim::testing::runCommand(
        "trap '' INT; " + std::string(VBIM_BINARY) + " " + args +
        " 2>&1 & pid=$!; for i in $(seq 600); do c=$(awk '/^SigCgt/{print $2}' /proc/$pid/status 2>/dev/null); "
        "[ -n \"$c\" ] && [ $(( 0x$c & 2 )) -ne 0 ] && break; sleep 0.05; done; sleep 1; kill -INT $pid; wait $pid; "
        "echo status=$?");
    EXPECT_NE(r.output.find("status=130"), std::string::npos) << args << "\n" << r.output;
    EXPECT_NE(r.output.find("interrupted (Ctrl-C)"), std::string::npos) << args << "\n" << r.output;
    EXPECT_TRUE(fs::is_empty(dir)) << args << ": left " << fs::directory_iterator(dir)->path();
    for (const auto& e : fs::directory_iterator(dir)) fs::remove_all(e.path());
  }
  fs::remove_all(dir);
  fs::remove_all(source);
}

// Ctrl-C or SIGTERM at any moment (issue #33): 240 runs of play, decode and author (author is run
// by vbim-full, so its runs cross the exec from vbim), four at a time, each sent one SIGINT or one
// SIGTERM at a random moment (tests/support/random_interrupts.hpp: how the runs inherit the signals
// ignored, and how the moments are spread). Every run must end either complete (exit 0, its output
// in place) or stopped (exit 130 or 143 with the message, its output absent), and nothing else may
// be left in the directory.
// The demo after its play: the profile pass (several seconds of stall searches) and the rendering
// run inside the commit of the output, where the play's progress no longer looks at the flag; a
// Ctrl-C there once went unheard and the demo finished with status 0. The signal is sent once the
// profile pass has written its first figure.
TEST(CliConventions, TheDemoStopsOnCtrlCAfterItsPlay) {
  const fs::path dir = scratch("interrupt_demo");
  fs::create_directories(dir);
  const auto r = vbim::testing::runCommand(
      "trap '' INT; " + std::string(VBIM_BINARY) + " demo --seconds 120 --out " + (dir / "demo").string() +
      " 2>&1 & pid=$!; for i in $(seq 1200); do [ -n \"$(find " + dir.string() +
      " -name 'occupancy.svg' 2>/dev/null)\" ] && break; sleep 0.05; done; kill -INT $pid; wait $pid; echo status=$?");
  EXPECT_NE(r.output.find("status=130"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("interrupted (Ctrl-C)"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_empty(dir)) << "left " << fs::directory_iterator(dir)->path();
  fs::remove_all(dir);
}

TEST(CliConventions, InterruptsAtRandomMomentsLeaveNothingBehind) {
  const fs::path dir = scratch("random_interrupts");
  fs::create_directories(dir);
  // 240 in the Release suite; fewer in the sanitizer suite (tests/support/soak.hpp).
  const int wanted = vbim::testing::soakRepetitions(240, 48);
  const std::vector<vbim::testing::InterruptedRun> runs = vbim::testing::runWithRandomInterrupts(dir, VBIM_BINARY, R"(
  out=$D/r$1
  case $(($1 % 3)) in
    0) echo "play )" + kSample + R"( --duration 120s --every 300 --out $out" ;;
    1) echo "decode )" + kSample + R"( --format png --out $out" ;;
    2) echo "author --procedural --size 64 --sky-width 32 --frame-count 4 --out $out.vbim" ;;
  esac)",
                                                                                                 3, wanted);
  int complete = 0, byInt = 0, byTerm = 0;
  for (const vbim::testing::InterruptedRun& run : runs) {
    const int i = run.index;
    const fs::path out = dir / ("r" + std::to_string(i) + (i % 3 == 2 ? ".vbim" : ""));
    if (run.status == 0) {
      ++complete;
      EXPECT_TRUE(fs::exists(out)) << "run " << i << " exited 0 without its output\n" << run.log;
      if (i % 3 == 0) {
        EXPECT_TRUE(fs::exists(out / "stats.json")) << "run " << i;
      }
      continue;
    }
    (run.term ? byTerm : byInt) += 1;
    vbim::testing::expectStoppedCleanly(run);
    EXPECT_FALSE(fs::exists(out)) << "run " << i << " was stopped but left " << out;
  }
  EXPECT_EQ(static_cast<int>(runs.size()), wanted);
  std::cout << byInt << " stopped by SIGINT, " << byTerm << " by SIGTERM, " << complete << " complete\n";
  // The moments do reach into the work, for both signals.
  EXPECT_GT(byInt, wanted / 8) << byTerm << " by SIGTERM, " << complete << " complete";
  EXPECT_GT(byTerm, wanted / 8) << byInt << " by SIGINT, " << complete << " complete";
  vbim::testing::expectNothingHiddenLeft(dir);
  fs::remove_all(dir);
}

// A run killed outright (SIGKILL cannot be caught) leaves its temporary directory; the next run
// that writes into the same directory removes it, and leaves a live process's alone.
TEST(CliConventions, TheNextRunRemovesWhatAKilledRunLeft) {
  const fs::path dir = scratch("killed_run");
  fs::create_directories(dir);
  const std::string d = dir.string();
  const auto killed =
      vbim::testing::runCommand(std::string(VBIM_BINARY) + " play " + kSample + " --duration 86400s --out " + d +
                                "/first >/dev/null 2>&1 & pid=$!; "
                                "for i in $(seq 200); do ls -a " +
                                d +
                                " | grep -q tmp && break; sleep 0.05; done; kill -KILL $pid; wait $pid; "
                                "ls -a " +
                                d);
  ASSERT_NE(killed.output.find(".first.tmp-"), std::string::npos) << killed.output;
  fs::create_directories(dir / (".other.tmp-" + std::to_string(::getpid())));  // a live process's
  const auto next = run("play " + kSample + " --duration 2s --no-trace --out " + d + "/second");
  ASSERT_EQ(next.status, 0) << next.output;
  std::string left;
  for (const auto& e : fs::directory_iterator(dir)) left += e.path().filename().string() + " ";
  EXPECT_EQ(left.find(".first.tmp-"), std::string::npos) << left;
  EXPECT_NE(left.find(".other.tmp-"), std::string::npos) << left;
  EXPECT_TRUE(fs::exists(dir / "second" / "stats.json")) << left;
  fs::remove_all(dir);
}

// An empty value is refused before any work (issue #33: `--out ''` ran the whole job and failed only
// when the output was moved into place).
TEST(CliConventions, EmptyValuesAreRefusedBeforeAnyWork) {
  for (const std::string& args : {"play " + kSample + " --duration 2s --out ''", "decode " + kSample + " --out ''",
                                  std::string("author --procedural --size 64 --frame-count 2 --out ''"),
                                  "play " + kSample + " --seed '' --out x"}) {
    const Result r = run(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(": is empty; expected "), std::string::npos) << args << "\n" << r.output;
    EXPECT_EQ(r.output.find("cannot move"), std::string::npos) << args << "\n" << r.output;
  }
}

}  // namespace
