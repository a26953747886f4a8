// The porting reference end to end: `vbim vectors` regenerates exactly the committed tests/vectors
// and --check names a flipped byte; `vbim replay` of play's arrivals.csv reproduces play's
// hashes.txt (both samples, a drive stall, a branch and a loop wrap).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/random_interrupts.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch.hpp"
#include "tests/support/soak.hpp"

namespace {

namespace fs = std::filesystem;

using Result = vbim::testing::CommandResult;

// From the source tree: the tests name the samples by their paths in it.
Result run(const std::string& args) {
  return vbim::testing::runProgram(VBIM_BINARY, args, VBIM_SOURCE_DIR);
}

fs::path scratch(const std::string& name) {
  return vbim::testing::scratchPath("port_test_" + name);
}

std::string readAll(const fs::path& p) {
  return vbim::testing::readFileBytes(p);
}

const char* const kVectorFiles[] = {"frame_hash.txt", "blend.txt", "cdstread.txt", "ipu.txt",
                                    "vlc.txt",        "idct.txt",  "csc.txt",      "draw.txt"};

TEST(PortReference, GeneratedVectorsEqualTheCommittedOnes) {
  const fs::path out = scratch("vectors");
  const Result r = run("vectors --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  for (const char* f : kVectorFiles) {
    EXPECT_EQ(readAll(out / f), readAll(fs::path(VBIM_SOURCE_DIR) / "tests/vectors" / f))
        << f << " differs: regenerate with `vbim vectors --out tests/vectors --force` if the change is intended";
  }
  const Result check = run("vectors --check tests/vectors");
  EXPECT_EQ(check.status, 0) << check.output;
  fs::remove_all(out);
}

// Ctrl-C or SIGTERM at any moment of `vbim vectors`, writing (--out) or scoring (--check), four
// runs at a time (tests/support/random_interrupts.hpp), as CliConventions.InterruptsAtRandomMoments...
// does for play, decode and author: each run ends complete (exit 0: its directory in place, or the
// check's verdict) or stopped (exit 130 or 143 with the message, no directory), and nothing else is
// left beside the outputs.
TEST(PortReference, VectorsInterruptedAtRandomMomentsLeaveNothingBehind) {
  const fs::path dir = scratch("vectors_interrupts");
  const fs::path committed = dir / "committed";  // the vectors --check scores
  fs::create_directories(dir);
  ASSERT_EQ(run("vectors --out " + committed.string()).status, 0);
  // 80 in the Release suite; fewer in the sanitizer suite (tests/support/soak.hpp).
  const int wanted = vbim::testing::soakRepetitions(80, 16);
  const std::vector<vbim::testing::InterruptedRun> runs = vbim::testing::runWithRandomInterrupts(dir, VBIM_BINARY, R"(
  case $(($1 % 2)) in
    0) echo "vectors --out $D/r$1" ;;
    1) echo "vectors --check )" + committed.string() + R"(" ;;
  esac)",
                                                                                                 2, wanted);
  int complete = 0, byInt = 0, byTerm = 0;
  for (const vbim::testing::InterruptedRun& r : runs) {
    const fs::path out = dir / ("r" + std::to_string(r.index));
    if (r.status == 0) {
      ++complete;
      if (r.index % 2 == 0) {
        for (const char* f : kVectorFiles) EXPECT_TRUE(fs::exists(out / f)) << "run " << r.index << " lacks " << f;
      } else {
        EXPECT_NE(r.log.find("vector files present in " + committed.string() + " match"), std::string::npos)
            << "run " << r.index << "\n"
            << r.log;
      }
      continue;
    }
    (r.term ? byTerm : byInt) += 1;
    vbim::testing::expectStoppedCleanly(r);
    EXPECT_FALSE(fs::exists(out)) << "run " << r.index << " was stopped but left " << out;
  }
  EXPECT_EQ(static_cast<int>(runs.size()), wanted);
  std::cout << byInt << " stopped by SIGINT, " << byTerm << " by SIGTERM, " << complete << " complete\n";
  // The moments do reach into the work, for both signals.
  EXPECT_GT(byInt, 0) << byTerm << " by SIGTERM, " << complete << " complete";
  EXPECT_GT(byTerm, 0) << byInt << " by SIGINT, " << complete << " complete";
  vbim::testing::expectNothingHiddenLeft(dir);
  fs::remove_all(dir);
}

// A stream with P and B pictures: vlc.txt and idct.txt add non-intra macroblocks of its first P and
// first B picture (their coded blocks: run/level from scan position 0, the residual without
// pixels), and --check scores them.
TEST(PortReference, VectorsOfAGopStreamCoverNonIntraBlocks) {
  const fs::path dir = scratch("gop_vectors");
  fs::create_directories(dir);
  const std::string stream = (dir / "gop.vbim").string();
  const Result a =
      run("author --synthetic clear,overcast --synthetic-frames 8 --synthetic-size 64x64 --synthetic-sky-size 32x16 "
          "--q 2 --gop 4 --b-frames 1 --out " +
          stream);
  ASSERT_EQ(a.status, 0) << a.output;
  const Result r = run("vectors --stream " + stream + " --out " + (dir / "v").string());
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string vlc = readAll(dir / "v/vlc.txt");
  const std::string idct = readAll(dir / "v/idct.txt");
  // The macroblock lines of P and B pictures: vlc/gop/lightmap/frame=F/mb=M VALUE,macroblock_type=T,...
  std::vector<std::string> keys;
  std::istringstream lines(vlc);
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] == '#' || line.find(",macroblock_type=") == std::string::npos) continue;
    keys.push_back(line.substr(0, line.find(' ')));
  }
  ASSERT_GE(keys.size(), 2u) << vlc;
  const std::string& key = keys.front();
  const std::string idctKey = "idct" + key.substr(3);
  EXPECT_NE(idct.find(idctKey + "/block="), std::string::npos) << idctKey;
  // The non-intra blocks have in and result, no pixels.
  const std::size_t in = idct.find(idctKey + "/block=");
  const std::string block = idct.substr(in, idct.find("/in ", in) - in);
  EXPECT_NE(idct.find(block + "/result "), std::string::npos);
  EXPECT_EQ(idct.find(block + "/pixels "), std::string::npos);
  const Result check = run("vectors --stream " + stream + " --check " + (dir / "v").string());
  EXPECT_EQ(check.status, 0) << check.output;
  // A port whose non-intra run/level differs fails vlc.txt at that entry.
  std::string changed = vlc;
  const std::size_t rl = changed.find(key + "/block=");
  ASSERT_NE(rl, std::string::npos);
  const std::size_t value = changed.find(' ', rl) + 1;
  changed.insert(value, "0:7 ");
  std::ofstream(dir / "v/vlc.txt", std::ios::binary | std::ios::trunc) << changed;
  const Result fail = run("vectors --stream " + stream + " --check " + (dir / "v").string() + " --only vlc");
  EXPECT_EQ(fail.status, 1) << fail.output;
  EXPECT_NE(fail.output.find(key + "/block="), std::string::npos) << fail.output;
  fs::remove_all(dir);
}

// The default streams (the samples) do not depend on the directory vbim is run from.
TEST(PortReference, DefaultStreamsAreFoundFromAnyDirectory) {
  const fs::path cwd = scratch("vectors_cwd");
  fs::create_directories(cwd);
  const vbim::testing::CommandResult r = vbim::testing::runProgram(VBIM_BINARY, "vectors --out vec", cwd);
  ASSERT_EQ(r.status, 0) << r.output;
  for (const char* f : kVectorFiles) {
    EXPECT_EQ(readAll(cwd / "vec" / f), readAll(fs::path(VBIM_SOURCE_DIR) / "tests/vectors" / f)) << f;
  }
  fs::remove_all(cwd);
}

// An installed vbim (PREFIX/bin/vbim) takes the samples installed with it (PREFIX/share/vbim/samples,
// cmake/Install.cmake) before the source tree's: here the installed day_clear.vbim is day_weather's
// bytes, so the vectors are those of the installed files, and differ from the committed ones.
TEST(PortReference, AnInstalledVbimReadsTheInstalledSamples) {
  const fs::path prefix = scratch("installed");
  const fs::path samples = prefix / "share/vbim/samples";
  fs::create_directories(prefix / "bin");
  fs::create_directories(samples);
  fs::copy_file(VBIM_BINARY, prefix / "bin/vbim");
  const fs::path weather = fs::path(VBIM_SOURCE_DIR) / "streams/samples/day_weather.vbim";
  fs::copy_file(weather, samples / "day_clear.vbim");
  fs::copy_file(weather, samples / "day_weather.vbim");
  const std::string vbim = (prefix / "bin/vbim").string();
  const vbim::testing::CommandResult byDefault = vbim::testing::runProgram(vbim, "vectors --out by-default", prefix);
  ASSERT_EQ(byDefault.status, 0) << byDefault.output;
  const vbim::testing::CommandResult named = vbim::testing::runProgram(
      vbim,
      "vectors --stream share/vbim/samples/day_clear.vbim --stream share/vbim/samples/day_weather.vbim --out named",
      prefix);
  ASSERT_EQ(named.status, 0) << named.output;
  for (const char* f : kVectorFiles) EXPECT_EQ(readAll(prefix / "by-default" / f), readAll(prefix / "named" / f)) << f;
  EXPECT_NE(readAll(prefix / "by-default/ipu.txt"), readAll(fs::path(VBIM_SOURCE_DIR) / "tests/vectors/ipu.txt"));
  fs::remove_all(prefix);
}

TEST(PortReference, CheckNamesTheFirstDifference) {
  const fs::path dir = scratch("check");
  fs::create_directories(dir);
  for (const char* f : kVectorFiles) fs::copy_file(fs::path(VBIM_SOURCE_DIR) / "tests/vectors" / f, dir / f);
  // Flip one byte of one answer: the last hex digit of the first RGB32 hash.
  std::string ipu = readAll(dir / "ipu.txt");
  const std::string key = "ipu/day_clear/lightmap/frame=0/rgb32/raster ";
  const auto at = ipu.find(key);
  ASSERT_NE(at, std::string::npos);
  const std::size_t digit = at + key.size() + 15;
  const std::string expected = ipu.substr(at + key.size(), 16);
  ipu[digit] = ipu[digit] == '0' ? '1' : '0';
  const std::string found = ipu.substr(at + key.size(), 16);
  std::ofstream(dir / "ipu.txt", std::ios::binary) << ipu;
  const Result r = run("vectors --check " + dir.string());
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("ipu.txt: entry 'ipu/day_clear/lightmap/frame=0/rgb32/raster': expected '" + expected +
                          "', found '" + found + "'"),
            std::string::npos)
      << r.output;
  fs::remove(dir / "blend.txt");
  const Result missing = run("vectors --check " + dir.string());
  EXPECT_EQ(missing.status, 1);  // ipu.txt still differs
  EXPECT_NE(missing.output.find("blend.txt: no such file, absent"), std::string::npos) << missing.output;
  fs::remove_all(dir);
}

// One line per stage: pass, fail with where the value differs, or absent; absent stages do not
// fail the check (a port in bring-up has not captured them yet), a present one that differs does.
TEST(PortReference, CheckScoresEachStageAndSkipsAbsentOnes) {
  const fs::path dir = scratch("stages");
  fs::create_directories(dir);
  for (const char* f : kVectorFiles) fs::copy_file(fs::path(VBIM_SOURCE_DIR) / "tests/vectors" / f, dir / f);
  fs::remove(dir / "draw.txt");
  fs::remove(dir / "cdstread.txt");
  const Result absent = run("vectors --check " + dir.string());
  EXPECT_EQ(absent.status, 0) << absent.output;
  EXPECT_NE(absent.output.find("the 6 vector files present"), std::string::npos) << absent.output;
  EXPECT_NE(absent.output.find("draw.txt: no such file, absent (52 entries not checked)"), std::string::npos)
      << absent.output;
  EXPECT_NE(absent.output.find("idct.txt: 276 of 276 match (pass)"), std::string::npos) << absent.output;

  // Element 3 of an IDCT result off by one: the entry and the element are named.
  std::string idct = readAll(dir / "idct.txt");
  const std::string key = "idct/ieee1180/-5..5/sign=+1/0/result ";
  const auto at = idct.find(key);
  ASSERT_NE(at, std::string::npos);
  std::size_t p = at + key.size();
  for (int comma = 0; comma < 3; ++comma) p = idct.find(',', p) + 1;
  const std::size_t end = idct.find(',', p);
  const std::string element = idct.substr(p, end - p);
  const std::string changed = std::to_string(std::stoi(element) + 1);
  idct.replace(p, end - p, changed);
  std::ofstream(dir / "idct.txt", std::ios::binary) << idct;
  // A byte of a CSC output changed: its place is the byte.
  std::string csc = readAll(dir / "csc.txt");
  const std::string cscKey = "csc/synthetic/ramps/rgb32 ";
  const auto cscAt = csc.find(cscKey);
  ASSERT_NE(cscAt, std::string::npos);
  const std::size_t digit = cscAt + cscKey.size() + 2 * 130;
  csc[digit] = csc[digit] == 'f' ? 'e' : 'f';
  std::ofstream(dir / "csc.txt", std::ios::binary) << csc;
  const Result fail = run("vectors --check " + dir.string());
  EXPECT_EQ(fail.status, 1) << fail.output;
  EXPECT_NE(fail.output.find("idct.txt: 275 of 276 match, 1 differ (fail)"), std::string::npos) << fail.output;
  EXPECT_NE(fail.output.find("entry 'idct/ieee1180/-5..5/sign=+1/0/result': element 3 of 64: expected '" + element +
                             "', found '" + changed + "'"),
            std::string::npos)
      << fail.output;
  EXPECT_NE(fail.output.find("entry 'csc/synthetic/ramps/rgb32': byte 130 of 1024"), std::string::npos) << fail.output;
  EXPECT_NE(fail.output.find("vlc.txt: 130 of 130 match (pass)"), std::string::npos) << fail.output;

  // --only by stage names: the failing stages left out, the check passes.
  const Result some = run("vectors --check " + dir.string() + " --only vlc,ipu --only blend");
  EXPECT_EQ(some.status, 0) << some.output;
  EXPECT_NE(some.output.find("vlc.txt: 130 of 130 match (pass)"), std::string::npos) << some.output;
  EXPECT_NE(some.output.find("idct.txt: no entry selected"), std::string::npos) << some.output;
  EXPECT_EQ(run("vectors --check " + dir.string() + " --only idct").status, 1);
  // A stage name and a key pattern together.
  EXPECT_EQ(run("vectors --check " + dir.string() + " --only vlc --only 'idct/saturating/*'").status, 0);
  // Nothing present: not a pass.
  for (const char* f : kVectorFiles) fs::remove(dir / f);
  const Result none = run("vectors --check " + dir.string());
  EXPECT_EQ(none.status, 1) << none.output;
  fs::remove_all(dir);
}

// A partial bring-up: cdstread.txt not captured yet and one RGB32-with-thresholds hash wrong. The
// check scores every file (not only the first difference), and --only scores what the port has
// done: RGB32 without thresholds and the blend pass.
TEST(PortReference, CheckScoresAPartialBringUpAndOnlySelectsWhatItHas) {
  const fs::path dir = scratch("partial");
  fs::create_directories(dir);
  for (const char* f : kVectorFiles) fs::copy_file(fs::path(VBIM_SOURCE_DIR) / "tests/vectors" / f, dir / f);
  fs::remove(dir / "cdstread.txt");
  std::string ipu = readAll(dir / "ipu.txt");
  const std::string key = "ipu/day_clear/lightmap/frame=1/rgb32_th/raster ";
  const auto at = ipu.find(key);
  ASSERT_NE(at, std::string::npos);
  ipu[at + key.size()] = ipu[at + key.size()] == '0' ? '1' : '0';
  std::ofstream(dir / "ipu.txt", std::ios::binary) << ipu;
  const Result all = run("vectors --check " + dir.string());
  EXPECT_EQ(all.status, 1) << all.output;
  EXPECT_NE(all.output.find("frame_hash.txt: 10 of 10 match"), std::string::npos) << all.output;
  EXPECT_NE(all.output.find("blend.txt: 707 of 707 match"), std::string::npos) << all.output;
  EXPECT_NE(all.output.find("cdstread.txt: no such file"), std::string::npos) << all.output;
  EXPECT_NE(all.output.find("1 differ"), std::string::npos) << all.output;
  EXPECT_NE(all.output.find("entry 'ipu/day_clear/lightmap/frame=1/rgb32_th/raster'"), std::string::npos) << all.output;
  const Result some = run("vectors --check " + dir.string() + " --only 'ipu/*/rgb32/*' --only 'blend/*'");
  EXPECT_EQ(some.status, 0) << some.output;
  EXPECT_NE(some.output.find("blend.txt: 686 of 686 match"), std::string::npos) << some.output;
  EXPECT_NE(some.output.find("cdstread.txt: no entry selected"), std::string::npos) << some.output;
  const Result wrong = run("vectors --check " + dir.string() + " --only 'ipu/*/rgb32_th/*'");
  EXPECT_EQ(wrong.status, 1) << wrong.output;
  EXPECT_EQ(run("vectors --check " + dir.string() + " --only 'no/such/*'").status, 2);
  fs::remove_all(dir);
}

// play, then replay of its arrivals: the same hashes.txt, byte for byte.
void expectReplayMatchesPlay(const std::string& stream, const std::string& extra) {
  const fs::path dir = scratch("replay");
  fs::create_directories(dir);
  {
    std::ofstream plan(dir / "stall.toml");
    plan << "[[fault]]\nkind = \"stall\"\nat = \"5s\"\nduration = \"9s\"\n";
  }
  const Result p = run("play " + stream + " --faults " + (dir / "stall.toml").string() + " " + extra +
                       " --duration 30s --no-trace --out " + (dir / "play").string());
  ASSERT_EQ(p.status, 0) << p.output;
  EXPECT_NE(p.output.find("1 loop wrap(s)"), std::string::npos) << p.output;
  // No --duration: the end row of arrivals.csv gives the run's length.
  const Result r = run("replay " + stream + " --arrivals " + (dir / "play/arrivals.csv").string() + " --out " +
                       (dir / "replay").string());
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string played = readAll(dir / "play/hashes.txt");
  EXPECT_GT(played.size(), 1000u);
  EXPECT_EQ(readAll(dir / "replay/hashes.txt"), played) << stream;
  fs::remove_all(dir);
}

TEST(PortReference, ReplayOfPlaysArrivalsReproducesItsHashesDayClear) {
  expectReplayMatchesPlay("streams/samples/day_clear.vbim", "");
}

TEST(PortReference, ReplayOfPlaysArrivalsReproducesItsHashesDayWeatherWithBranch) {
  expectReplayMatchesPlay("streams/samples/day_weather.vbim", "--branch 8s=1");
}

// A short play: its arrivals.csv ends with the end row, so replay without --duration presents the
// run's vsyncs, no more (it once replayed 60 s: play's hashes.txt was only a prefix of replay's).
TEST(PortReference, ReplayEndsWherePlaysArrivalsEnd) {
  const fs::path dir = scratch("replay_end");
  fs::create_directories(dir);
  const std::string stream = "streams/samples/day_clear.vbim";
  const Result p = run("play " + stream + " --duration 5s --no-trace --out " + (dir / "play").string());
  ASSERT_EQ(p.status, 0) << p.output;
  const Result r = run("replay " + stream + " --arrivals " + (dir / "play/arrivals.csv").string() + " --out " +
                       (dir / "replay").string());
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string played = readAll(dir / "play/hashes.txt");
  const std::string replayed = readAll(dir / "replay/hashes.txt");
  const auto rows = std::count(played.begin(), played.end(), '\n');
  EXPECT_EQ(rows, 300);  // 5 s of NTSC vsyncs
  EXPECT_EQ(std::count(replayed.begin(), replayed.end(), '\n'), rows);
  EXPECT_TRUE(replayed == played) << "hashes.txt of replay differs from play's";
  // The end row is the last line: the number of vsyncs in hashes.txt, no frame.
  const std::string arrivals = readAll(dir / "play/arrivals.csv");
  EXPECT_TRUE(arrivals.ends_with("\n" + std::to_string(rows) + ",end,\n")) << arrivals.substr(arrivals.size() - 40);
  // --duration, when given, wins over the end row.
  const Result longer = run("replay " + stream + " --arrivals " + (dir / "play/arrivals.csv").string() +
                            " --duration 6s --out " + (dir / "longer").string());
  ASSERT_EQ(longer.status, 0) << longer.output;
  const std::string longer6s = readAll(dir / "longer/hashes.txt");
  EXPECT_EQ(std::count(longer6s.begin(), longer6s.end(), '\n'), 360);
  EXPECT_TRUE(longer6s.starts_with(played));
  fs::remove_all(dir);
}

TEST(PortReference, ReplayNamesABadArrivalLine) {
  const fs::path dir = scratch("badarrivals");
  fs::create_directories(dir);
  std::ofstream(dir / "a.csv") << "vsync,stream,frame\n3,lightmap:0,1\n4,moon:0,2\n";
  const Result r = run("replay streams/samples/day_clear.vbim --arrivals " + (dir / "a.csv").string() + " --out " +
                       (dir / "out").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("a.csv:3: stream 'moon:0'"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
  // The end row: a number of vsyncs, no frame, and nothing after it.
  std::ofstream(dir / "b.csv") << "vsync,stream,frame\n3,lightmap:0,1\n300,end,7\n";
  const Result frame = run("replay streams/samples/day_clear.vbim --arrivals " + (dir / "b.csv").string() + " --out " +
                           (dir / "out").string());
  EXPECT_EQ(frame.status, 2);
  EXPECT_NE(frame.output.find("b.csv:3: end row '300,end,7' with a frame"), std::string::npos) << frame.output;
  std::ofstream(dir / "c.csv") << "vsync,stream,frame\n300,end,\n3,lightmap:0,1\n";
  const Result after = run("replay streams/samples/day_clear.vbim --arrivals " + (dir / "c.csv").string() + " --out " +
                           (dir / "out").string());
  EXPECT_EQ(after.status, 2);
  EXPECT_NE(after.output.find("c.csv:3: '3,lightmap:0,1' after the end row"), std::string::npos) << after.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
  fs::remove_all(dir);
}

}  // namespace
