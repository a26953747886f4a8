// `vbim decode` end to end: elementary and program streams in, image files out, and the exit
// codes and messages for streams that cannot be decoded.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/ipu/support/libav_mpeg.hpp"
#include "tests/support/run_command.hpp"

namespace vbim::ipu {
namespace {

namespace fs = std::filesystem;

struct Result {
  int code;
  std::string output;
};

Result runTool(const std::string& args) {
  const vbim::testing::CommandResult r = vbim::testing::runCommand(std::string(VBIM_TOOL) + " " + args);
  return {r.status, r.output};
}

fs::path scratch() {
  const fs::path d = fs::temp_directory_path() / ("vbim-ipu-cli-" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

void writeFile(const fs::path& p, const std::vector<std::uint8_t>& bytes) {
  std::ofstream f(p, std::ios::binary);
  f.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

std::vector<std::uint8_t> stream(int w, int h, int frames, int gop = 1) {
  testing::EncodeOptions o;
  o.width = w;
  o.height = h;
  o.frames = frames;
  o.gopSize = gop;
  o.content = testing::Content::kPattern;
  return testing::encodeIntra(o);
}

// A minimal MPEG-2 program stream: 2048-byte packs, each a pack header and one PES packet of
// stream `id`, padded with a padding stream (0xBE) when the payload runs out.
void appendPacks(std::vector<std::uint8_t>& ps, const std::vector<std::uint8_t>& es, int id) {
  std::size_t pos = 0;
  while (pos < es.size()) {
    std::vector<std::uint8_t> pack = {0, 0, 1, 0xBA, 0x44, 0, 4, 0, 4, 1, 0x01, 0x89, 0xC3, 0xF8};
    const std::size_t room = 2048 - pack.size() - 9;
    const std::size_t n = std::min(room, es.size() - pos);
    const std::size_t pesLen = 3 + n;
    pack.insert(pack.end(), {0, 0, 1, static_cast<std::uint8_t>(id), static_cast<std::uint8_t>(pesLen >> 8),
                             static_cast<std::uint8_t>(pesLen & 0xFF), 0x80, 0x00, 0x00});
    pack.insert(pack.end(), es.begin() + static_cast<std::ptrdiff_t>(pos),
                es.begin() + static_cast<std::ptrdiff_t>(pos + n));
    pos += n;
    if (pack.size() < 2048) {
      const std::size_t pad = 2048 - pack.size() - 6;
      pack.insert(pack.end(),
                  {0, 0, 1, 0xBE, static_cast<std::uint8_t>(pad >> 8), static_cast<std::uint8_t>(pad & 0xFF)});
      pack.insert(pack.end(), pad, 0xFF);
    }
    ps.insert(ps.end(), pack.begin(), pack.end());
  }
}

TEST(IpuCli, DecodesAnElementaryStreamToPngAndYuv) {
  const fs::path d = scratch();
  writeFile(d / "a.m2v", stream(40, 24, 3));
  Result r = runTool("decode " + (d / "a.m2v").string() + " --out " + (d / "png").string());
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(fs::exists(d / "png" / "frame_00002.png")) << r.output;
  r = runTool("decode " + (d / "a.m2v").string() + " --out " + (d / "yuv").string() + " --format yuv --threads 2");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(fs::file_size(d / "yuv" / "frame_00000.yuv"), 40u * 24 + 2 * 20 * 12);
  fs::remove_all(d);
}

// More threads than the machine has is a usage error with a clear message (it used to abort in
// the worker pool once thread creation failed).
TEST(IpuCli, ThreadCountAboveTheMachineIsRefused) {
  const fs::path d = scratch();
  writeFile(d / "a.m2v", stream(40, 24, 1));
  const Result r = runTool("decode " + (d / "a.m2v").string() + " --out " + (d / "png").string() + " --threads 100000");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("--threads: 100000: this machine has"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("terminate"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(d / "png"));
  fs::remove_all(d);
}

TEST(IpuCli, DecodesTheSecondVideoStreamOfAProgramStream) {
  const fs::path d = scratch();
  std::vector<std::uint8_t> ps;
  appendPacks(ps, stream(40, 24, 2), 0xE0);
  appendPacks(ps, stream(32, 16, 4), 0xE1);
  writeFile(d / "v.vbim", ps);
  Result r =
      runTool("decode " + (d / "v.vbim").string() + " --out " + (d / "e1").string() + " --stream-id 0xE1 --format yuv");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(fs::exists(d / "e1" / "frame_00003.yuv")) << r.output;
  EXPECT_EQ(fs::file_size(d / "e1" / "frame_00000.yuv"), 32u * 16 * 3 / 2);
  r = runTool("decode " + (d / "v.vbim").string() + " --out " + (d / "e0").string() + " --format yuv");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(fs::exists(d / "e0" / "frame_00001.yuv"));
  EXPECT_FALSE(fs::exists(d / "e0" / "frame_00002.yuv"));
  fs::remove_all(d);
}

// Program streams as Debian's ffmpeg muxes them (an MPEG-2 program stream, -f vob, and an MPEG-1
// system stream, -f mpeg), from elementary streams of each: every picture of the program stream
// decodes to the same bytes as the elementary stream it was muxed from.
TEST(IpuCli, DecodesWhatFfmpegMuxesLikeItsElementaryStream) {
  const fs::path d = scratch();
  for (const bool mpeg1 : {false, true}) {
    SCOPED_TRACE(mpeg1 ? "MPEG-1 system stream" : "MPEG-2 program stream");
    testing::EncodeOptions o;
    o.width = 48;
    o.height = 32;
    o.frames = 3;
    o.mpeg1 = mpeg1;
    o.content = testing::Content::kPattern;
    const fs::path es = d / (mpeg1 ? "a.m1v" : "a.m2v");
    const fs::path ps = d / "a.mpg";
    writeFile(es, testing::encodeIntra(o));
    const std::string mux = std::string("ffmpeg -v error -nostdin -y -f mpegvideo") + " -i " + es.string() +
                            " -c copy -f " + (mpeg1 ? "mpeg " : "vob ") + ps.string();
    const vbim::testing::CommandResult muxed = vbim::testing::runCommand(mux);
    ASSERT_EQ(muxed.status, 0) << mux << "\n"
                               << muxed.output << "\n(ffmpeg comes with Debian's ffmpeg package: scripts/setup.sh)";
    for (const fs::path& in : {es, ps}) {
      const Result r =
          runTool("decode " + in.string() + " --out " + (d / in.filename()).string() + ".out --format yuv");
      ASSERT_EQ(r.code, 0) << r.output;
      EXPECT_NE(r.output.find(mpeg1 ? "MPEG-1" : "MPEG-2"), std::string::npos) << r.output;
    }
    for (int i = 0; i < 4; ++i) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%05d.yuv", i);
      const fs::path fromEs = d / (es.filename().string() + ".out") / name;
      const fs::path fromPs = d / "a.mpg.out" / name;
      EXPECT_EQ(fs::exists(fromEs), i < 3) << fromEs;
      EXPECT_EQ(fs::exists(fromPs), i < 3) << fromPs;
      if (i < 3) {
        EXPECT_EQ(vbim::testing::readFileBytes(fromEs), vbim::testing::readFileBytes(fromPs)) << name;
      }
    }
    fs::remove_all(d / "a.mpg.out");
    fs::remove_all(d / (es.filename().string() + ".out"));
  }
  fs::remove_all(d);
}

TEST(IpuCli, RefusesWhatCannotBeDecoded) {
  const fs::path d = scratch();
  // No sequence header anywhere: every 00 00 01 B3 is broken.
  std::vector<std::uint8_t> es = stream(40, 24, 2);
  for (std::size_t i = 0; i + 3 < es.size(); ++i)
    if (es[i] == 0 && es[i + 1] == 0 && es[i + 2] == 1 && es[i + 3] == 0xB3) es[i + 3] = 0xB2;  // user data
  writeFile(d / "noseq.m2v", es);
  Result r = runTool("decode " + (d / "noseq.m2v").string() + " --out " + (d / "o1").string());
  EXPECT_EQ(r.code, 2);  // bad input (docs/cli.md)
  EXPECT_NE(r.output.find("no sequence header"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(d / "o1"));
  writeFile(d / "junk.bin", {1, 2, 3, 4, 5});
  r = runTool("decode " + (d / "junk.bin").string() + " --out " + (d / "o3").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("byte 0"), std::string::npos) << r.output;
  fs::remove_all(d);
}

// Issue #29: `vbim decode --format yuv --idct libmpeg2` of an interlaced stream with GOPs and B
// pictures is bit-identical, frame by frame in display order, to libmpeg2's C decoder run as a
// program (`mpeg2dec -c -o pgm`: Y rows, then each chroma row as Cb then Cr side by side).
TEST(IpuCli, GopStreamMatchesMpeg2dec) {
  if (vbim::testing::runCommand("command -v mpeg2dec").status != 0)
    GTEST_SKIP() << "mpeg2dec is not installed (apt-get install mpeg2dec; scripts/setup.sh does)";
  const fs::path d = scratch();
  testing::EncodeOptions o;
  o.width = 352;
  o.height = 288;
  o.frames = 8;
  o.gopSize = 12;
  o.bFrames = 2;
  o.quantiser = 4;
  o.interlacedDct = true;
  o.interlacedMe = true;
  o.content = testing::Content::kPan;
  writeFile(d / "gop.m2v", testing::encodeIntra(o));
  const Result r = runTool("decode " + (d / "gop.m2v").string() + " --out " + (d / "ours").string() +
                           " --format yuv --idct libmpeg2");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("decoded 8 pictures"), std::string::npos) << r.output;
  fs::create_directories(d / "ref");
  const vbim::testing::CommandResult m =
      vbim::testing::runCommand("cd " + (d / "ref").string() + " && mpeg2dec -c -o pgm ../gop.m2v");
  ASSERT_EQ(m.status, 0) << m.output;
  // mpeg2dec stops short of the stream's last frames: libmpeg2 acts on a start code only once bytes
  // follow it, so the closing sequence_end_code never completes the last pictures (the library
  // test, tests/ipu/gop_conformance_test.cpp, feeds one more and compares all of them).
  int shown = 0;
  while (fs::exists(d / "ref" / (std::to_string(shown) + ".pgm"))) ++shown;
  EXPECT_GE(shown, 6);
  const std::size_t w = 352, h = 288, cw = w / 2, ch = h / 2;
  for (int f = 0; f < shown; ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.yuv", f);
    const std::string ours = vbim::testing::readFileBytes(d / "ours" / name);
    const std::string pgm = vbim::testing::readFileBytes(d / "ref" / (std::to_string(f) + ".pgm"));
    const std::string header = "P5\n352 432\n255\n";
    ASSERT_EQ(ours.size(), w * h + 2 * cw * ch) << name;
    ASSERT_EQ(pgm.size(), header.size() + w * (h + ch)) << f;
    ASSERT_EQ(pgm.substr(0, header.size()), header);
    const char* ref = pgm.data() + header.size();
    std::size_t different = 0;
    for (std::size_t i = 0; i < w * h; ++i) different += ours[i] != ref[i];
    for (std::size_t y = 0; y < ch; ++y) {
      for (std::size_t x = 0; x < cw; ++x) {
        different += ours[w * h + y * cw + x] != ref[w * h + y * w + x];
        different += ours[w * h + cw * ch + y * cw + x] != ref[w * h + y * w + cw + x];
      }
    }
    EXPECT_EQ(different, 0u) << "display frame " << f;
  }
  EXPECT_LE(shown, 8);
  fs::remove_all(d);
}

TEST(IpuCli, ConcealsAndReportsCorruption) {
  const fs::path d = scratch();
  std::vector<std::uint8_t> es = stream(64, 48, 2);
  for (std::size_t i = 120; i < es.size(); i += 211) es[i] ^= 0x24;
  writeFile(d / "bad.m2v", es);
  const Result r = runTool("decode " + (d / "bad.m2v").string() + " --out " + (d / "o").string());
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("macroblock"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("concealed"), std::string::npos) << r.output;
  const Result strict = runTool("decode " + (d / "bad.m2v").string() + " --out " + (d / "s").string() + " --strict");
  EXPECT_EQ(strict.code, 2);
  fs::remove_all(d);
}

}  // namespace
}  // namespace vbim::ipu
