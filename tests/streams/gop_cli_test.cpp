// `vbim author --gop N --b-frames M` as a user runs it, and what `vbim info` and `vbim decode` make of
// the result (issue #29, item 4): the GOP structure and bits per picture type, every frame decoded
// in display order and bit-identical to libmpeg2's C decoder with --idct libmpeg2.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

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

// Until the player's P/B path lands (issue #29), play, profile and replay refuse such a stream by name
// instead of playing garbage; an intra stream still plays.
TEST(GopCli, PlayProfileAndReplayRefuseGopStreamsForNow) {
  TempDir dir;
  const fs::path s = authorGop(dir);
  const std::string want = "P and B pictures are not played yet (issue #29)";
  const auto play = vbim("play " + s.string() + " --duration 2s --out " + (dir / "run").string());
  EXPECT_EQ(play.status, 2) << play.output;
  EXPECT_NE(play.output.find(want), std::string::npos) << play.output;
  EXPECT_FALSE(fs::exists(dir / "run"));
  const auto profile = vbim("profile " + s.string() + " --duration 2s --out " + (dir / "prof").string());
  EXPECT_EQ(profile.status, 2) << profile.output;
  EXPECT_NE(profile.output.find(want), std::string::npos) << profile.output;
  fs::create_directories(dir / "log");
  test::writeFile(dir / "log" / "arrivals.csv", {});
  const auto replay = vbim("replay " + s.string() + " --arrivals " + (dir / "log" / "arrivals.csv").string() +
                           " --out " + (dir / "rep").string());
  EXPECT_EQ(replay.status, 2) << replay.output;
  EXPECT_NE(replay.output.find(want), std::string::npos) << replay.output;
  const fs::path intra = dir / "intra.vbim";
  ASSERT_EQ(vbim("author --synthetic clear --synthetic-frames 4 --out " + intra.string()).status, 0);
  const auto ok = vbim("play " + intra.string() + " --duration 2s --out " + (dir / "run2").string());
  EXPECT_EQ(ok.status, 0) << ok.output;
}

}  // namespace
}  // namespace vbim::streams
