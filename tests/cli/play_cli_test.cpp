// `vbim play` as a user runs it (issue #7 item 3 and its bad input): the files of a run, pictures
// that hold exactly the texels the hashes were taken of, repeatable output, and clear refusals.
#include <gtest/gtest.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "player/frame_hash.hpp"
#include "runtime/image.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch.hpp"

namespace {

namespace fs = std::filesystem;
using vbim::testing::runCommand;

const std::string kSample = std::string(VBIM_SOURCE_DIR) + "/streams/samples/day_clear.vbim";

fs::path scratch(const std::string& name) {
  return vbim::testing::scratchPath("play_cli_" + name);
}

vbim::testing::CommandResult play(const std::string& args) {
  return runCommand(std::string(VBIM_BINARY) + " play " + args);
}

// The channels a picture file has: 3 (RGB) for opaque pictures, 4 with --alpha gs; 0 if unreadable.
int channelsOf(const fs::path& p) {
  auto in = OIIO::ImageInput::open(p.string());
  return in ? in->spec().nchannels : 0;
}

// The bytes as stored (OpenImageIO would otherwise multiply the colours by alpha), as RGBA: an RGB
// file (an opaque picture) with alpha 255.
vbim::Rgba8Image readPng(const fs::path& p) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(p.string(), &config);
  if (!in) return {};
  const int channels = in->spec().nchannels;
  if (channels != 3 && channels != 4) return {};
  std::vector<std::uint8_t> samples(static_cast<std::size_t>(in->spec().image_pixels()) * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, samples.data())) return {};
  vbim::Rgba8Image img(in->spec().width, in->spec().height);
  for (std::size_t i = 0; i < img.pixels.size() / 4; ++i) {
    for (std::size_t c = 0; c < 4; ++c) {
      img.pixels[i * 4 + c] = c < static_cast<std::size_t>(channels) ? samples[i * channels + c] : 255;
    }
  }
  return img;
}

// hashes.txt: "vsync seconds hash" per line.
std::vector<std::string> hashColumn(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) {
    std::istringstream f(line);
    std::string vsync, seconds, hash;
    f >> vsync >> seconds >> hash;
    out.push_back(hash);
  }
  return out;
}

// A duration past the tick counter used to wrap ("played 19.8 s") or hang; now it is refused.
TEST(PlayCli, DurationBeyondTheTickCounterIsRefused) {
  const fs::path out = scratch("huge");
  for (const char* d : {"125099989669s", "999999999999.999999999s"}) {
    const auto r = play(kSample + " --duration " + d + " --out " + out.string());
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find(std::string("--duration '") + d + "': longer than the simulated clock can count"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(out));
  }
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The trace is streamed; by default the ipu track has one span per busy stretch and signals.vcd
// leaves out same-instant toggles. --trace-detail full keeps both; the hashes do not depend on it.
TEST(PlayCli, TraceDetailFullKeepsMacroblockSpansAndEveryToggle) {
  const fs::path a = scratch("coarse");
  const fs::path b = scratch("full");
  ASSERT_EQ(play(kSample + " --duration 3s --out " + a.string()).status, 0);
  ASSERT_EQ(play(kSample + " --duration 3s --trace-detail full --out " + b.string()).status, 0);
  const std::string coarse = slurp(a / "trace.json");
  const std::string full = slurp(b / "trace.json");
  EXPECT_NE(coarse.find(R"("name":"decode","ph":"X")"), std::string::npos);
  EXPECT_EQ(coarse.find(R"("name":"idec")"), std::string::npos);
  EXPECT_NE(full.find(R"("name":"idec","ph":"X")"), std::string::npos);
  EXPECT_LT(fs::file_size(a / "signals.vcd"), fs::file_size(b / "signals.vcd"));
  EXPECT_EQ(slurp(a / "hashes.txt"), slurp(b / "hashes.txt"));
  EXPECT_EQ(full.substr(full.size() - 4), "\n]}\n");
  const auto r = play(kSample + " --duration 3s --trace-detail some --out " + a.string() + "x");
  EXPECT_EQ(r.status, 2) << r.output;
  fs::remove_all(a);
  fs::remove_all(b);
}

// --trace-detail ipu (issue #30): the coalesced trace plus ipu_commands.csv, one row per IPU command;
// nothing else changes, and without it there is no such file.
TEST(PlayCli, TraceDetailIpuLogsEveryIpuCommand) {
  const fs::path a = scratch("plain");
  const fs::path b = scratch("ipu");
  ASSERT_EQ(play(kSample + " --duration 3s --out " + a.string()).status, 0);
  ASSERT_EQ(play(kSample + " --duration 3s --trace-detail ipu --out " + b.string()).status, 0);
  EXPECT_FALSE(fs::exists(a / "ipu_commands.csv"));
  for (const char* f : {"hashes.txt", "timeline.csv", "arrivals.csv", "trace.json", "signals.vcd"})
    EXPECT_EQ(slurp(a / f), slurp(b / f)) << f;
  std::istringstream log(slurp(b / "ipu_commands.csv"));
  std::string line;
  std::getline(log, line);
  EXPECT_EQ(line, "stream,picture,frame,type,command,word,fields,ctrl,begin_tick,end_tick");
  int bclr = 0;
  int idec = 0;
  while (std::getline(log, line)) {
    if (line.find(",BCLR,") != std::string::npos) ++bclr;
    if (line.find(",IDEC,") == std::string::npos) continue;
    ++idec;
    // The samples' slices: FB = 39 (start code, scale code, extra_bit_slice, address increment 1).
    EXPECT_NE(line.find(",FB=39 QSC="), std::string::npos) << line;
    EXPECT_NE(line.find(" DTD=0 SGN=0 DTE=0 OFM=0,0x01000000,"), std::string::npos) << line;
  }
  // 3 s: lightmap frames 0-3 (16 slices each) and sky frames 0-3 (4 each), a BCLR per picture.
  EXPECT_EQ(bclr, 8);
  EXPECT_EQ(idec, 4 * 16 + 4 * 4);
  fs::remove_all(a);
  fs::remove_all(b);
}

TEST(PlayCli, WritesEveryFileAndPicturesMatchTheirHashes) {
  const fs::path out = scratch("run");
  // --alpha gs: the texels as they are in VRAM, the bytes the hashes hash.
  const auto r = play(kSample + " --duration 10s --every 120 --alpha gs --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  for (const char* f : {"hashes.txt", "stats.json", "trace.json", "signals.vcd", "timeline.csv"})
    EXPECT_TRUE(fs::is_regular_file(out / f)) << f;
  const std::vector<std::string> hashes = hashColumn(out / "hashes.txt");
  ASSERT_EQ(hashes.size(), 600u);  // 10 s at 59.94 Hz
  for (int vsync : {0, 120, 240, 360, 480}) {
    char name[32];
    std::snprintf(name, sizeof name, "%06d.png", vsync);
    const vbim::Rgba8Image lightmap = readPng(out / "frames" / (std::string("lightmap_") + name));
    const vbim::Rgba8Image sky = readPng(out / "frames" / (std::string("sky_") + name));
    ASSERT_GT(lightmap.width, 0) << vsync;
    ASSERT_GT(sky.width, 0) << vsync;
    EXPECT_EQ(vbim::player::hashHex(vbim::player::frameHash(lightmap, &sky)), hashes[static_cast<std::size_t>(vsync)])
        << "the pictures of vsync " << vsync << " are not the texels that were hashed";
  }
  fs::remove_all(out);
}

// Without --out (issue #33), play runs and prints the summary a run with --out prints, and writes
// nothing: no directory, no hidden temporary one, in the directory it runs from. --every and --at,
// which ask for pictures, are refused.
TEST(PlayCli, WithoutOutPrintsTheSummaryAndWritesNothing) {
  const fs::path cwd = scratch("no_out");
  fs::create_directories(cwd);
  const auto r = vbim::testing::runProgram(VBIM_BINARY, "play " + kSample + " --duration 10s", cwd);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("played 10.0 s of " + kSample + " (600 vsyncs)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("  frames: 10 shown"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("images written 0"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_empty(cwd)) << fs::begin(fs::directory_iterator(cwd))->path();
  // The same frames, pop and lag as the run that writes its directory (the host times differ).
  const fs::path out = cwd / "run";
  const auto with = play(kSample + " --duration 10s --out " + out.string());
  ASSERT_EQ(with.status, 0) << with.output;
  const auto afterHostTime = [](const std::string& s) { return s.substr(s.find('\n')); };
  EXPECT_EQ(afterHostTime(r.output), afterHostTime(with.output));
  for (const char* asks : {" --every 60", " --at 5s"}) {
    const auto refused = vbim::testing::runProgram(VBIM_BINARY, "play " + kSample + " --duration 10s" + asks, cwd);
    EXPECT_EQ(refused.status, 2) << asks << ": " << refused.output;
    EXPECT_NE(refused.output.find("writes pictures into the run directory: give --out DIR"), std::string::npos)
        << refused.output;
  }
  fs::remove_all(out);
  EXPECT_TRUE(fs::is_empty(cwd));
  fs::remove_all(cwd);
}

// `--out run/` (as the README writes it) and `--out ./run` name the directory `run`, and the files
// are those of `--out run`.
TEST(PlayCli, OutAcceptsATrailingSlashAndDotSlash) {
  const fs::path base = scratch("slash");
  fs::create_directories(base);
  const std::string args = kSample + " --duration 2s --every 60 --seed 5 --no-trace --out ";
  ASSERT_EQ(play(args + (base / "plain").string()).status, 0);
  const auto slash = play(args + (base / "slash").string() + "/");
  ASSERT_EQ(slash.status, 0) << slash.output;
  const auto dot = runCommand("cd " + base.string() + " && " + std::string(VBIM_BINARY) + " play " + args + "./dot");
  ASSERT_EQ(dot.status, 0) << dot.output;
  for (const char* d : {"slash", "dot"}) {
    for (const char* f : {"hashes.txt", "timeline.csv", "stats.json"}) {
      EXPECT_EQ(vbim::testing::readFileBytes(base / d / f), vbim::testing::readFileBytes(base / "plain" / f))
          << d << "/" << f;
    }
  }
  for (const auto& e : fs::directory_iterator(base)) {
    EXPECT_NE(e.path().filename().string().rfind('.', 0), 0u) << "left behind: " << e.path();
  }
  fs::remove_all(base);
}

TEST(PlayCli, SameRunSameBytes) {
  const fs::path a = scratch("a"), b = scratch("b");
  ASSERT_EQ(play(kSample + " --duration 6s --seed 3 --out " + a.string()).status, 0);
  ASSERT_EQ(play(kSample + " --duration 6s --seed 3 --out " + b.string()).status, 0);
  for (const char* f : {"hashes.txt", "trace.json", "signals.vcd", "timeline.csv"})
    EXPECT_EQ(vbim::testing::readFileBytes(a / f), vbim::testing::readFileBytes(b / f)) << f;
  fs::remove_all(a);
  fs::remove_all(b);
}

TEST(PlayCli, ThreadsSplitTheDecodeAndChangeNoByte) {
  const fs::path a = scratch("t1"), b = scratch("t2");
  ASSERT_EQ(play(kSample + " --duration 6s --out " + a.string()).status, 0);
  const auto two = play(kSample + " --duration 6s --threads 2 --out " + b.string());
  ASSERT_EQ(two.status, 0) << two.output;
  for (const char* f : {"hashes.txt", "trace.json", "signals.vcd", "timeline.csv", "stats.json", "arrivals.csv"})
    EXPECT_EQ(vbim::testing::readFileBytes(a / f), vbim::testing::readFileBytes(b / f)) << f;
  const auto many = play(kSample + " --duration 1s --threads 100000 --out " + scratch("tmany").string());
  EXPECT_EQ(many.status, 2);
  EXPECT_NE(many.output.find("hardware threads; use at most"), std::string::npos) << many.output;
  fs::remove_all(a);
  fs::remove_all(b);
}

// The pictures are written on a thread of their own (issue #31): the same files at any --threads,
// run after run; --png-level compresses them and keeps the texels; the summary says what they cost.
TEST(PlayCli, PicturesAreTheSameBytesAtAnyThreadCountAndLevelKeepsTheTexels) {
  const fs::path a = scratch("pa"), b = scratch("pb"), c = scratch("pc");
  const std::string args = kSample + " --duration 4s --every 30 --at 1.6s ";
  const auto first = play(args + "--out " + a.string());
  ASSERT_EQ(first.status, 0) << first.output;
  EXPECT_NE(first.output.find("of CPU time on their own thread"), std::string::npos) << first.output;
  EXPECT_NE(first.output.find("PNG level 0"), std::string::npos) << first.output;
  ASSERT_EQ(play(args + "--threads 2 --out " + b.string()).status, 0);
  const auto level = play(args + "--png-level 1 --out " + c.string());
  ASSERT_EQ(level.status, 0) << level.output;
  EXPECT_NE(level.output.find("PNG level 1"), std::string::npos) << level.output;
  int files = 0;
  for (const auto& e : fs::directory_iterator(a / "frames")) {
    const std::string name = e.path().filename().string();
    EXPECT_EQ(vbim::testing::readFileBytes(e.path()), vbim::testing::readFileBytes(b / "frames" / name)) << name;
    const vbim::Rgba8Image stored = readPng(e.path());
    const vbim::Rgba8Image compressed = readPng(c / "frames" / name);
    ASSERT_GT(stored.width, 0) << name;
    EXPECT_EQ(stored.pixels, compressed.pixels) << name;
    if (name.starts_with("lightmap_")) {
      EXPECT_LT(fs::file_size(c / "frames" / name), fs::file_size(e.path())) << name;
    }
    ++files;
  }
  EXPECT_EQ(files, 2 * 9);  // vsyncs 0, 30, ..., 210 and 96 (1.6 s)
  for (const fs::path& d : {a, b, c}) fs::remove_all(d);
}

// vbim decode's PNGs (here beside play's for the PNG reader): written at --png-level, by default
// play's level 0, where libpng's default level took 87 % of a decode's CPU; every level keeps the
// pixels, which are the IPU's RGB32 output (--format rgba) with the GS alpha doubled.
TEST(DecodeCli, PngLevelKeepsThePixelsOfTheRgbaFrames) {
  const fs::path stored = scratch("dec0"), compressed = scratch("dec6"), raw = scratch("decraw");
  const std::string vbimDecode = std::string(VBIM_BINARY) + " decode " + kSample;
  const auto first = runCommand(vbimDecode + " --out " + stored.string());
  ASSERT_EQ(first.status, 0) << first.output;
  EXPECT_NE(first.output.find("as png (level 0)"), std::string::npos) << first.output;
  const auto level = runCommand(vbimDecode + " --png-level 6 --out " + compressed.string());
  ASSERT_EQ(level.status, 0) << level.output;
  EXPECT_NE(level.output.find("as png (level 6)"), std::string::npos) << level.output;
  ASSERT_EQ(runCommand(vbimDecode + " --format rgba --out " + raw.string()).status, 0);
  int files = 0;
  for (const auto& e : fs::directory_iterator(stored)) {
    const std::string name = e.path().filename().string();
    const vbim::Rgba8Image a = readPng(e.path());
    const vbim::Rgba8Image b = readPng(compressed / name);
    ASSERT_GT(a.width, 0) << name;
    EXPECT_EQ(a.pixels, b.pixels) << name;
    EXPECT_LT(fs::file_size(compressed / name), fs::file_size(e.path())) << name;
    const std::string rgba = vbim::testing::readFileBytes(raw / (name.substr(0, name.size() - 3) + "rgba"));
    ASSERT_EQ(rgba.size(), a.pixels.size()) << name;
    for (std::size_t i = 0; i < rgba.size(); ++i) {
      const auto byte = static_cast<std::uint8_t>(rgba[i]);
      const int want = i % 4 == 3 ? std::min(255, 2 * byte) : byte;
      if (a.pixels[i] != want) {
        ADD_FAILURE() << name << ": byte " << i << " is " << int{a.pixels[i]} << ", the RGBA frame says " << want;
        break;
      }
    }
    ++files;
  }
  EXPECT_EQ(files, 24);  // the sample's 24 lightmap pictures (its first video stream)
  const fs::path bad = scratch("dec10");
  const auto refused = runCommand(vbimDecode + " --png-level 10 --out " + bad.string());
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find("--png-level 10: expected 0 (stored) to 9"), std::string::npos) << refused.output;
  EXPECT_FALSE(fs::exists(bad));
  for (const fs::path& d : {stored, compressed, raw}) fs::remove_all(d);
}

TEST(PlayCli, ExrFramesAreWritten) {
  const fs::path out = scratch("exr");
  const auto r = play(kSample + " --duration 2s --at 1s --format exr --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  auto in = OIIO::ImageInput::open((out / "frames" / "lightmap_000060.exr").string());
  ASSERT_TRUE(in) << OIIO::geterror();
  EXPECT_EQ(in->spec().nchannels, 3);  // opaque: RGB, as the PNGs
  EXPECT_EQ(in->spec().format, OIIO::TypeDesc::HALF);
  fs::remove_all(out);
}

// The progress line (cli/progress.hpp) is drawn on a terminal only: never into a pipe or a log.
// `script` (util-linux, in every Debian) gives the second run a terminal.
TEST(PlayCli, ProgressLineOnlyOnATerminal) {
  const fs::path out = scratch("progress");
  const std::string args = kSample + " --duration 2s --no-trace --force --out " + out.string();
  const auto piped = play(args);
  ASSERT_EQ(piped.status, 0) << piped.output;
  EXPECT_EQ(piped.output.find('\r'), std::string::npos) << piped.output;
  if (runCommand("command -v script >/dev/null").status != 0) GTEST_SKIP() << "no `script` to run vbim on a terminal";
  const auto terminal = runCommand("script -qec '" + std::string(VBIM_BINARY) + " play " + args + "' /dev/null");
  ASSERT_EQ(terminal.status, 0) << terminal.output;
  EXPECT_NE(terminal.output.find("\rvbim play [##############################] 2/2 s"), std::string::npos)
      << terminal.output;
  fs::remove_all(out);
}

struct Refusal {
  std::string args;      // after "vbim play"
  std::string expected;  // in the message
};

TEST(PlayCli, BadInputIsRefusedClearlyAndLeavesNoOutput) {
  const fs::path dir = scratch("bad");
  fs::create_directories(dir);
  std::ofstream(dir / "not.vbim") << "x";
  std::ofstream(dir / "bad.toml") << "ring.bankmax = \"x\"\n";
  const fs::path full = dir / "full";
  fs::create_directories(full);
  std::ofstream(full / "keep.txt") << "mine";
  const std::string out = " --out " + (dir / "out").string();
  const std::vector<Refusal> cases = {
      {kSample + " --duration 10s --at 12s" + out, "--at 12s is outside the run"},
      {(dir / "not.vbim").string() + " --duration 2s" + out, "not.vbim"},
      {kSample + " --config " + (dir / "bad.toml").string() + " --duration 2s" + out, "bad.toml:1: key 'ring.bankmax'"},
      {kSample + " --policy bogus --duration 2s" + out, "--policy 'bogus'"},
      {kSample + " --duration 2s --out " + full.string(), "exists and is not empty (use --force"},
      {(dir / "missing.vbim").string() + " --duration 2s" + out, "missing.vbim"},
      {kSample + " --duration 2s --png-level 10" + out, "--png-level 10: expected 0 (stored) to 9"},
      {kSample + " --duration 2s --png-level -1" + out, "--png-level -1: expected 0 (stored) to 9"},
  };
  for (const Refusal& c : cases) {
    const auto r = play(c.args);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_FALSE(fs::exists(dir / "out")) << c.args;
  }
  EXPECT_TRUE(fs::is_regular_file(full / "keep.txt"));
  // --force replaces it.
  const auto forced = play(kSample + " --duration 2s --force --out " + full.string());
  EXPECT_EQ(forced.status, 0) << forced.output;
  EXPECT_FALSE(fs::exists(full / "keep.txt"));
  EXPECT_TRUE(fs::is_regular_file(full / "hashes.txt"));
  fs::remove_all(dir);
}

}  // namespace

// By default the pictures are opaque, as viewers expect: RGB files, no alpha channel (issue #31: a
// quarter fewer bytes to write than alpha 255 everywhere); their colours are the texels'.
TEST(PlayCli, PicturesAreOpaqueByDefaultWithTheTexelsColours) {
  const fs::path gs = scratch("alpha_gs");
  const fs::path opaque = scratch("alpha_opaque");
  ASSERT_EQ(play(kSample + " --duration 2s --every 60 --alpha gs --out " + gs.string()).status, 0);
  ASSERT_EQ(play(kSample + " --duration 2s --every 60 --out " + opaque.string()).status, 0);
  for (const char* name : {"lightmap_000060.png", "sky_000060.png"}) {
    EXPECT_EQ(channelsOf(gs / "frames" / name), 4) << name;
    EXPECT_EQ(channelsOf(opaque / "frames" / name), 3) << name;
    const vbim::Rgba8Image a = readPng(gs / "frames" / name);
    const vbim::Rgba8Image b = readPng(opaque / "frames" / name);
    ASSERT_GT(a.width, 0) << name;
    ASSERT_EQ(a.pixels.size(), b.pixels.size()) << name;
    bool gsAlphaSeen = false;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
      if (i % 4 == 3) {
        EXPECT_EQ(b.pixels[i], 255) << name << " byte " << i;
        gsAlphaSeen = gsAlphaSeen || a.pixels[i] == 0x80;
      } else {
        ASSERT_EQ(a.pixels[i], b.pixels[i]) << name << " byte " << i;
      }
    }
    EXPECT_TRUE(gsAlphaSeen) << name << ": --alpha gs should keep the GS's 0x80";
  }
  fs::remove_all(gs);
  fs::remove_all(opaque);
}

// stats.json says where the run came from: the version and each input with its SHA-256 (the digest
// `sha256sum` prints), with or without tracing.
TEST(PlayCli, StatsRecordTheInputsAndTheirDigests) {
  const fs::path out = scratch("provenance");
  const std::string plan = std::string(VBIM_SOURCE_DIR) + "/examples/fault-plans/stall.toml";
  const auto r = play(kSample + " --duration 2s --no-trace --faults " + plan + " --seed 9 --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string stats = slurp(out / "stats.json");
  const auto sha = [](const std::string& path) {
    const auto s = runCommand("sha256sum " + path);
    return s.output.substr(0, 64);
  };
  EXPECT_NE(stats.find("\"sha256\": \"" + sha(kSample) + "\""), std::string::npos) << stats;
  EXPECT_NE(stats.find("\"sha256\": \"" + sha(plan) + "\""), std::string::npos) << stats;
  EXPECT_NE(stats.find("\"vbim_version\": \""), std::string::npos) << stats;
  EXPECT_NE(stats.find("\"config\": \"defaults\""), std::string::npos) << stats;
  EXPECT_NE(stats.find("\"seed\": 9"), std::string::npos) << stats;
  fs::remove_all(out);
}

namespace {

// busy_share.drive comes from the drive's own counter: present and equal with or without tracing,
// here with a stall still going on when the run ends (the example's stall runs from 20 s to 30 s).
TEST(PlayCli, DriveBusyShareIsTheSameWithOrWithoutTracing) {
  const fs::path traced = scratch("busy_traced"), bare = scratch("busy_bare");
  const std::string plan = std::string(VBIM_SOURCE_DIR) + "/examples/fault-plans/stall.toml";
  const std::string args = kSample + " --duration 25s --every 0 --faults " + plan + " --out ";
  ASSERT_EQ(play(args + traced.string()).status, 0);
  ASSERT_EQ(play(args + bare.string() + " --no-trace").status, 0);
  const auto driveShare = [](const std::string& stats) {
    const auto at = stats.find("\"drive\": ", stats.find("\"busy_share\""));
    return at == std::string::npos ? std::string("<none>") : stats.substr(at, stats.find('\n', at) - at);
  };
  const std::string a = driveShare(slurp(traced / "stats.json")), b = driveShare(slurp(bare / "stats.json"));
  EXPECT_EQ(a, b);
  EXPECT_EQ(b.find("null"), std::string::npos) << b;
  EXPECT_NE(b, "\"drive\": 0.0,") << b;
  fs::remove_all(traced);
  fs::remove_all(bare);
}

// The README's stall example does what its comment promises: on the sample day with the default
// ring, frames arrive late, the GS catches up, and the lightmap lags the fault-free run.
TEST(PlayCli, TheStallExampleMakesLateFramesAndACatchUp) {
  const fs::path out = scratch("stall_example");
  const std::string plan = std::string(VBIM_SOURCE_DIR) + "/examples/fault-plans/stall.toml";
  const auto r =
      play(kSample + " --faults " + plan + " --seed 7 --duration 60s --every 0 --no-trace --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string stats = slurp(out / "stats.json");
  const auto number = [&stats](const std::string& key) {
    const auto at = stats.find("\"" + key + "\": ");
    return at == std::string::npos ? -1L : std::stol(stats.substr(at + key.size() + 4));
  };
  EXPECT_GE(number("frames_late"), 3) << stats;
  EXPECT_GE(number("frames_caught_up"), 3) << stats;
  EXPECT_NE(r.output.find("lag max "), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("lag max 0 "), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("the faults changed nothing"), std::string::npos) << r.output;
  fs::remove_all(out);
}

// The flaky-drive example does what its comment promises: with --seed 7 on the sample day its
// random stalls and read errors meet the drive's reads (5 retries, 0.48 s stalled) and a frame comes
// late; the same seed gives the same run.
TEST(PlayCli, TheFlakyDriveExampleMeetsTheDrivesReads) {
  const fs::path a = scratch("flaky_a"), b = scratch("flaky_b");
  const std::string args =
      kSample + " --faults " + std::string(VBIM_SOURCE_DIR) +
      "/examples/fault-plans/flaky-drive.toml --seed 7 --duration 150s --every 0 --no-trace --out ";
  const auto r = play(args + a.string());
  ASSERT_EQ(r.status, 0) << r.output;
  ASSERT_EQ(play(args + b.string()).status, 0);
  const std::string stats = slurp(a / "stats.json");
  const auto number = [&stats](const std::string& key) {
    const auto at = stats.find("\"" + key + "\": ");
    return at == std::string::npos ? -1L : std::stol(stats.substr(at + key.size() + 4));
  };
  EXPECT_EQ(number("retries"), 5) << stats;
  EXPECT_EQ(number("stalled_ticks"), 70516548) << stats;  // 0.478 s at 147.456 MHz
  EXPECT_EQ(number("frames_late"), 1) << stats;
  EXPECT_EQ(r.output.find("the faults changed nothing"), std::string::npos) << r.output;
  EXPECT_EQ(slurp(a / "hashes.txt"), slurp(b / "hashes.txt"));
  fs::remove_all(a);
  fs::remove_all(b);
}

// A stall that the buffers absorb (the sample day is in the EE's buffers by 8 s) changes nothing,
// and the summary says so instead of letting it pass for a survived fault.
TEST(PlayCli, FaultsThatChangeNothingAreNamedInTheSummary) {
  const fs::path out = scratch("absorbed_stall");
  const fs::path plan = scratch("absorbed_stall.toml");
  std::ofstream(plan) << "[[fault]]\nkind = \"stall\"\nat = \"8s\"\nduration = \"6s\"\n";
  const auto r =
      play(kSample + " --faults " + plan.string() + " --duration 30s --every 0 --no-trace --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("the faults changed nothing on screen"), std::string::npos) << r.output;
  const auto clean = play(kSample + " --duration 5s --every 0 --no-trace --out " + out.string() + " --force");
  ASSERT_EQ(clean.status, 0) << clean.output;
  EXPECT_EQ(clean.output.find("the faults changed nothing"), std::string::npos) << clean.output;  // no faults at all
  fs::remove_all(out);
  fs::remove(plan);
}

}  // namespace
