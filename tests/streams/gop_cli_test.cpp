// `vbim author --gop N --b-frames M` as a user runs it, and what `vbim info` and `vbim decode` make of
// the result (issue #29, item 4): the GOP structure and bits per picture type, every frame decoded
// in display order and bit-identical to libmpeg2's C decoder with --idct libmpeg2.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>

#include "imageio/image_reader.hpp"
#include "player/frame_hash.hpp"
#include "player/known_answers.hpp"
#include "streams/demuxer.hpp"
#include "tests/ipu/support/libmpeg2_decode.hpp"
#include "tests/streams/stream_fixture.hpp"
#include "tests/support/run_command.hpp"

namespace vbim::streams {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

vbim::testing::CommandResult vbim(const std::string& args) {
  return vbim::testing::runCommand(std::string(VBIM_BINARY) + " " + args);
}

// 16 synthetic frames of 128x128 (+ 64x32 sky), GOPs of 6 with 2 B pictures, loop to frame 4.
fs::path authorGop(const TempDir& dir, const std::string& extra = "") {
  const fs::path out = dir / "gop.vbim";
  const auto r = vbim(
      "author --synthetic clear --synthetic-frames 16 --synthetic-size 128x128 "
      "--synthetic-sky-size 64x32 --gop 6 --b-frames 2 --loop 4 --out " +
      out.string() + " " + extra);
  EXPECT_EQ(r.status, 0) << r.output;
  return out;
}

TEST(GopCli, AuthorRefusesImpossibleGops) {
  TempDir dir;
  const std::string base = "author --synthetic clear --synthetic-frames 4 --out " + (dir / "x.vbim").string();
  const auto b = vbim(base + " --gop 3 --b-frames 3");
  EXPECT_EQ(b.status, 2);
  EXPECT_NE(b.output.find("--b-frames 3 needs --gop above it"), std::string::npos) << b.output;
  const auto g = vbim(base + " --gop 0");
  EXPECT_EQ(g.status, 2);
  EXPECT_NE(g.output.find("--gop 0 is outside"), std::string::npos) << g.output;
  const auto o = vbim(base + " --gop 4 --open-gop");
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.output.find("--open-gop needs --b-frames"), std::string::npos) << o.output;
  EXPECT_FALSE(fs::exists(dir / "x.vbim"));
}

TEST(GopCli, InfoShowsTheGopStructureAndBitsPerPictureType) {
  TempDir dir;
  const fs::path s = authorGop(dir);
  const auto text = vbim("info " + s.string());
  ASSERT_EQ(text.status, 0) << text.output;
  EXPECT_NE(text.output.find("descriptor: version 2"), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("I pictures"), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("B pictures"), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("GOPs 3 (3 closed, 0 open)"), std::string::npos) << text.output;
  const auto js = vbim("info --json " + s.string());
  ASSERT_EQ(js.status, 0) << js.output;
  const auto j = nlohmann::json::parse(js.output);
  EXPECT_EQ(j["descriptor"]["version"], 2);
  const std::string types = j["descriptor"]["index_types"]["0xE0"];
  EXPECT_EQ(types.size(), 16u);
  EXPECT_EQ(types[0], 'i');
  EXPECT_EQ(types[4], 'i');  // the loop frame starts a GOP
  for (const auto& st : j["streams"]) {
    EXPECT_EQ(st["gops"]["count"], 3);
    EXPECT_EQ(st["gops"]["closed"], 3);
    const std::size_t n = st["picture_types"]["I"]["pictures"].get<std::size_t>() +
                          st["picture_types"]["P"]["pictures"].get<std::size_t>() +
                          st["picture_types"]["B"]["pictures"].get<std::size_t>();
    EXPECT_EQ(n, 16u);
    EXPECT_GT(st["picture_types"]["B"]["pictures"].get<int>(), 0);
    EXPECT_GT(st["picture_types"]["I"]["mean_bits"].get<double>(), 0);
    for (const auto& p : st["picture_list"]) EXPECT_TRUE(p["type"].is_string());
  }
  const std::string rec = j["authoring"]["stream"].dump();
  EXPECT_NE(rec.find("\"gop\":6"), std::string::npos) << rec;
}

// Damage in a GOP stream: info reports it through --json (valid JSON, exit 2), without crashing.
TEST(GopCli, InfoJsonOnDamagedGopStream) {
  TempDir dir;
  const fs::path s = authorGop(dir);
  std::vector<std::uint8_t> bytes = test::readFile(s);
  for (std::size_t at = 3 * 2048 + 100; at < bytes.size(); at += 5 * 2048 + 37) bytes[at] ^= 0x5A;
  test::writeFile(dir / "bad.vbim", bytes);
  // In a subshell, so that stdout and stderr go to their own files.
  const auto js =
      vbim::testing::runCommand("(" + std::string(VBIM_BINARY) + " info --json " + (dir / "bad.vbim").string() + " > " +
                                (dir / "bad.json").string() + " 2> " + (dir / "bad.err").string() + ")");
  EXPECT_EQ(js.status, 2) << js.output;
  const std::vector<std::uint8_t> err = test::readFile(dir / "bad.err");
  EXPECT_NE(std::string(err.begin(), err.end()).find("defects found"), std::string::npos);
  const std::vector<std::uint8_t> text = test::readFile(dir / "bad.json");
  const auto j = nlohmann::json::parse(text.begin(), text.end());
  EXPECT_FALSE(j["errors"].empty());
}

// The lightmap stream's pictures in stream order: its elementary stream.
std::vector<std::uint8_t> elementaryStream(const std::vector<std::uint8_t>& file, std::uint8_t id) {
  Demuxer demux;
  std::vector<std::uint8_t> es;
  for (std::size_t pos = 0; pos < file.size(); pos += 2048)
    demux.feed(std::span(file).subspan(pos, 2048), static_cast<std::uint32_t>(pos / 2048));
  demux.finish();
  for (const Picture& p : demux.pictures())
    if (p.streamId == id) es.insert(es.end(), p.data.begin(), p.data.end());
  return es;
}

TEST(GopCli, DecodeGivesEveryFrameInDisplayOrderAsLibmpeg2Does) {
  TempDir dir;
  const fs::path s = authorGop(dir);
  const auto r = vbim("decode " + s.string() + " --out " + (dir / "ours").string() + " --format yuv --idct libmpeg2");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto ref = ipu::testing::decodeWithLibmpeg2(elementaryStream(test::readFile(s), 0xE0));
  ASSERT_EQ(ref.size(), 16u);
  for (std::size_t f = 0; f < ref.size(); ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05zu.yuv", f);
    const std::vector<std::uint8_t> ours = test::readFile(dir / "ours" / name);
    std::vector<std::uint8_t> want(ref[f].y.begin(), ref[f].y.end());
    want.insert(want.end(), ref[f].cb.begin(), ref[f].cb.end());
    want.insert(want.end(), ref[f].cr.begin(), ref[f].cr.end());
    ASSERT_EQ(ours.size(), want.size()) << name;
    std::size_t different = 0;
    for (std::size_t i = 0; i < want.size(); ++i) different += ours[i] != want[i];
    EXPECT_EQ(different, 0u) << "display frame " << f;
  }
  const auto png = vbim("decode " + s.string() + " --out " + (dir / "png").string());
  ASSERT_EQ(png.status, 0) << png.output;
  EXPECT_TRUE(fs::exists(dir / "png" / "frame_00015.png")) << png.output;
}

// The lightmap a play shows at each vsync, with ALPHA.FIX = 128 (each vsync copies its target frame
// in), is the frame timeline.csv names as the target, decoded by `vbim decode` (itself bit-identical
// to libmpeg2 above): the player's decode order, display reordering, loop wrap to an I picture and a
// branch into the middle of a GOP (decoded from its I picture) all end in the right pixels.
TEST(GopCli, PlayShowsTheFrameItTargetsThroughLoopAndBranch) {
  TempDir dir;
  const fs::path s = dir / "gop2.vbim";
  const auto a = vbim(
      "author --synthetic clear,overcast --synthetic-frames 16 --synthetic-size 128x128 "
      "--synthetic-sky-size 64x32 --gop 6 --b-frames 2 --loop 4 --out " +
      s.string());
  ASSERT_EQ(a.status, 0) << a.output;
  {
    std::ofstream fix(dir / "fix.toml");
    fix << "[gs]\nfix = 128\n";
  }
  // Frame 7 (a B picture of the GOP opened by I 6) is due at 7 s: the branch resumes at that I.
  const auto play = vbim("play " + s.string() + " --config " + (dir / "fix.toml").string() +
                         " --duration 40s --branch 7.2s=1 --every 29 --no-trace --out " + (dir / "run").string());
  ASSERT_EQ(play.status, 0) << play.output;
  const auto dec = vbim("decode " + s.string() + " --out " + (dir / "dec").string());
  ASSERT_EQ(dec.status, 0) << dec.output;
  const auto json = nlohmann::json::parse(std::ifstream(dir / "run" / "stats.json"));
  EXPECT_EQ(json["damage"]["frames_lost"], 0);
  EXPECT_EQ(json["damage"]["pictures_with_broken_reference"], 0);
  EXPECT_EQ(json["gop"]["pictures_for_reference_only"], 2);  // I 6 of the new variant, lightmap and sky
  EXPECT_GT(json["ipu_commands"]["bdec"], 0);
  // timeline.csv: vsync, ..., target_seq (column 5), variant (column 6).
  std::map<std::int64_t, std::pair<std::int64_t, std::int64_t>> target;
  std::ifstream rows(dir / "run" / "timeline.csv");
  std::string row;
  std::getline(rows, row);
  while (std::getline(rows, row)) {
    std::vector<std::string> f;
    std::istringstream cells(row);
    for (std::string c; std::getline(cells, c, ',');) f.push_back(c);
    target[std::stoll(f[0])] = {std::stoll(f[4]), std::stoll(f[5])};
  }
  int compared = 0;
  std::set<std::int64_t> variants;
  for (const auto& e : fs::directory_iterator(dir / "run" / "frames")) {
    const std::string name = e.path().filename().string();
    if (name.rfind("lightmap_", 0) != 0) continue;
    const std::int64_t vsync = std::stoll(name.substr(9, 6));
    const auto [seq, variant] = target.at(vsync);
    if (seq < 0) continue;
    const std::int64_t frame = seq < 16 ? seq : 4 + (seq - 16) % 12;
    char want[32];
    std::snprintf(want, sizeof want, "frame_%05lld.png", static_cast<long long>(variant * 16 + frame));
    const Rgba8Image shown = imageio::readRgba8(e.path());
    const Rgba8Image decoded = imageio::readRgba8(dir / "dec" / want);
    EXPECT_EQ(shown.pixels, decoded.pixels) << name << ": seq " << seq << " of variant " << variant << ", " << want;
    variants.insert(variant);
    ++compared;
  }
  EXPECT_GT(compared, 60);
  EXPECT_EQ(variants.size(), 2u);
}

// Replay of a play's arrivals on a stream with P and B pictures gives the play's hashes: replay
// decodes each frame as the player's BDEC flow does (from its GOP's I picture, in decode order).
// Profile takes such a stream too.
TEST(GopCli, ReplayReproducesThePlayAndProfileRuns) {
  TempDir dir;
  const fs::path s = authorGop(dir);
  const auto play =
      vbim("play " + s.string() + " --duration 30s --branch 9.5s=0 --no-trace --out " + (dir / "run").string());
  ASSERT_EQ(play.status, 0) << play.output;
  const auto replay = vbim("replay " + s.string() + " --arrivals " + (dir / "run" / "arrivals.csv").string() +
                           " --compare " + (dir / "run").string() + " --out " + (dir / "rep").string());
  EXPECT_EQ(replay.status, 0) << replay.output;
  EXPECT_NE(replay.output.find("every hash equals"), std::string::npos) << replay.output;
  const auto profile = vbim("profile " + s.string() + " --duration 4s --out " + (dir / "prof").string());
  EXPECT_EQ(profile.status, 0) << profile.output;
}

// `vbim vectors` on a stream with P and B pictures: a B picture's and the last P picture's RGB32
// outputs are the hashes of those frames as `vbim decode` shows them (not the picture decoded alone,
// which has no references), and the header says so.
TEST(GopCli, VectorsHashEachFrameAsShown) {
  TempDir dir;
  const fs::path s = authorGop(dir);
  const auto vec = vbim("vectors --stream " + s.string() + " --out " + (dir / "vec").string());
  ASSERT_EQ(vec.status, 0) << vec.output;
  const auto dec = vbim("decode " + s.string() + " --out " + (dir / "dec").string());
  ASSERT_EQ(dec.status, 0) << dec.output;
  std::ifstream in(dir / "vec" / "ipu.txt");
  std::map<std::string, std::string> values;
  bool noted = false;
  for (std::string line; std::getline(in, line);) {
    if (line.find("gop has P and B pictures") != std::string::npos) noted = true;
    const auto space = line.find(' ');
    if (line.rfind("ipu/", 0) == 0 && space != std::string::npos)
      values[line.substr(0, space)] = line.substr(space + 1);
  }
  EXPECT_TRUE(noted);
  for (const int frame : {1, 15}) {  // frame 1 is a B picture, 15 the last P picture
    char png[32];
    std::snprintf(png, sizeof png, "frame_%05d.png", frame);
    const Rgba8Image decoded = imageio::readRgba8(dir / "dec" / png);
    const std::string key = "ipu/gop/lightmap/frame=" + std::to_string(frame) + "/rgb32/raster";
    ASSERT_EQ(values.count(key), 1u) << key;
    EXPECT_EQ(values[key], player::hashHex(player::hashAsImage(decoded.pixels, decoded.width, decoded.height))) << key;
  }
}

// A damaged P picture (bytes flipped in its slice data: it disagrees with the index) is decoded
// with concealment, and every P or B picture that predicts from it, up to the next I picture, is
// counted as decoded from a broken reference; the play completes.
TEST(GopCli, ADamagedReferenceIsConcealedAndCountedUntilTheNextI) {
  TempDir dir;
  const fs::path s = authorGop(dir);
  std::vector<std::uint8_t> bytes = test::readFile(s);
  std::size_t at = 2048;  // after the descriptor's sector: the first P picture's start code
  for (; at + 6 < bytes.size(); ++at) {
    if (bytes[at] == 0 && bytes[at + 1] == 0 && bytes[at + 2] == 1 && bytes[at + 3] == 0 &&
        ((bytes[at + 5] >> 3) & 7) == 2) {
      break;
    }
  }
  ASSERT_LT(at + 62, bytes.size());
  bytes[at + 60] ^= 0xFF;
  bytes[at + 61] ^= 0x55;
  const fs::path damaged = dir / "damaged.vbim";
  test::writeFile(damaged, bytes);
  const auto play = vbim("play " + damaged.string() + " --duration 20s --no-trace --out " + (dir / "run").string());
  ASSERT_EQ(play.status, 0) << play.output;
  const auto json = nlohmann::json::parse(std::ifstream(dir / "run" / "stats.json"));
  EXPECT_GE(json["damage"]["pictures_damaged"], 1);
  EXPECT_GE(json["damage"]["pictures_with_broken_reference"], 2);
  const auto clean = vbim("play " + s.string() + " --duration 20s --no-trace --out " + (dir / "clean").string());
  ASSERT_EQ(clean.status, 0) << clean.output;
  const auto ok = nlohmann::json::parse(std::ifstream(dir / "clean" / "stats.json"));
  EXPECT_EQ(ok["damage"]["pictures_with_broken_reference"], 0);
}

}  // namespace
}  // namespace vbim::streams
