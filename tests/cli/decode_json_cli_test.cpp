// `vbim decode --json` as a script over a damaged disc uses it (docs/cli.md, "JSON summaries"): one JSON
// document on stdout, naming each damaged picture, the frame file it became and each issue's file
// byte, macroblock and reason, for every --format; --strict prints the document and exits 2 with
// nothing written; input that cannot be decoded is exit 2 with nothing on stdout (as info --json).
// Damaged streams come from the corruption harness's generator (vbim_corrupt, seeded) and from
// bytes flipped inside one picture of an encoded GOP.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/ipu/support/libav_mpeg.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch.hpp"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using vbim::testing::readFileBytes;

const std::string kSample = std::string(VBIM_SOURCE_DIR) + "/streams/samples/day_clear.vbim";

struct Outcome {
  int status = -1;
  std::string out;  // stdout alone
  std::string err;  // stderr alone
};

class DecodeJson : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = vbim::testing::testScratchDir("decode_json"); }
  void TearDown() override { fs::remove_all(dir_); }

  Outcome vbim(const std::string& args) const {
    const fs::path out = dir_ / "stdout", err = dir_ / "stderr";
    const auto r = vbim::testing::runCommand("{ " + std::string(VBIM_BINARY) + " " + args + " > '" + out.string() +
                                             "' 2> '" + err.string() + "'; }");
    return {r.status, readFileBytes(out), readFileBytes(err)};
  }
  // The sample with the harness's seeded bit flips: pictures 0, 3, 7 and 17 concealed in part.
  fs::path damagedSample() const {
    const fs::path p = dir_ / "damaged.vbim";
    const auto r =
        vbim::testing::runCommand(std::string(VBIM_CORRUPT) + " " + kSample + " " + p.string() + " bitflips 2");
    EXPECT_EQ(r.status, 0) << r.output;
    return p;
  }
  static Json parse(const Outcome& r) {
    try {
      return Json::parse(r.out);
    } catch (const Json::exception& e) {
      ADD_FAILURE() << "not JSON on stdout (" << e.what() << "):\n" << r.out << "\nstderr:\n" << r.err;
      return Json::object();
    }
  }
  fs::path dir_;
};

std::vector<fs::path> filesIn(const fs::path& d) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(d)) files.push_back(e.path());
  return files;
}

std::uint64_t bytesIn(const fs::path& d) {
  std::uint64_t n = 0;
  for (const fs::path& f : filesIn(d)) n += fs::file_size(f);
  return n;
}

// "frame_00042.png", as vbim decode names its files.
std::string frameFile(int frame, const std::string& extension) {
  std::string digits = std::to_string(frame);
  return "frame_" + std::string(5 - std::min<std::size_t>(5, digits.size()), '0') + digits + "." + extension;
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST_F(DecodeJson, ACleanStreamsDocumentHoldsWhatTheSummaryLineSays) {
  const Outcome text = vbim("decode " + kSample + " --format yuv -o " + (dir_ / "text").string());
  ASSERT_EQ(text.status, 0) << text.err;
  const Outcome r =
      vbim("decode " + kSample + " --format yuv --idct exact --th0 3 --json -o " + (dir_ / "json").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const Json j = parse(r);
  EXPECT_EQ(j["input"]["path"], kSample);
  EXPECT_EQ(j["input"]["file"], nullptr);
  EXPECT_EQ(j["input"]["video_stream"], "0xE0");
  EXPECT_EQ(j["input"]["bytes"], fs::file_size(kSample));
  EXPECT_EQ(j["options"],
            Json::parse(R"({"format":"yuv","png_level":null,"idct":"exact","th0":3,"th1":0,"strict":false})"));
  EXPECT_EQ(j["video"], Json::parse(R"({"width":256,"height":256,"mpeg":2})"));
  const int frames = j["frames"].get<int>();
  EXPECT_TRUE(has(text.out, "decoded " + std::to_string(frames) + " pictures 256x256 (MPEG-2) (video stream 0xE0)"))
      << text.out;
  EXPECT_EQ(j["pictures"], frames);
  EXPECT_EQ(j["issues"], 0);
  EXPECT_EQ(j["concealed_macroblocks"], 0);
  EXPECT_EQ(j["skipped_pictures"], 0);
  EXPECT_EQ(j["damaged_pictures"], Json::array());
  EXPECT_EQ(j["container_defects"], Json::array());
  EXPECT_EQ(j["strict_failed"], false);
  const Json& o = j["output"];
  EXPECT_EQ(o["directory"], (dir_ / "json").string());
  EXPECT_EQ(o["written"], true);
  EXPECT_EQ(o["files"], filesIn(dir_ / "json").size());
  EXPECT_EQ(o["files"], frames);
  EXPECT_EQ(o["bytes"], bytesIn(dir_ / "json"));
  EXPECT_EQ(o["bytes"], static_cast<std::uint64_t>(frames) * 256 * 256 * 3 / 2);
  EXPECT_EQ(o["file_pattern"], "frame_%05d.yuv");

  // Nothing in it depends on the machine or the thread count: the same bytes at --threads 2.
  const Outcome again = vbim("decode " + kSample + " --format yuv --idct exact --th0 3 --json --threads 2 --force -o " +
                             (dir_ / "json").string());
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(again.out, r.out);
}

// Each damaged picture is named with the frame file it became, which differs from the undamaged
// stream's, and stderr's lines say the same picture, byte and macroblock.
TEST_F(DecodeJson, ADamagedStreamListsEachConcealedPictureAndIssue) {
  ASSERT_EQ(vbim("decode " + kSample + " --format rgba -o " + (dir_ / "clean").string()).status, 0);
  const Outcome r = vbim("decode " + damagedSample().string() + " --format rgba --json -o " + (dir_ / "bad").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = parse(r);
  ASSERT_EQ(j["damaged_pictures"].size(), 4u) << j.dump(2);
  std::set<std::string> damagedFiles;
  std::size_t issues = 0;
  int concealed = 0;
  for (const Json& p : j["damaged_pictures"]) {
    SCOPED_TRACE(p.dump());
    EXPECT_EQ(p["type"], "I");
    EXPECT_EQ(p["frame"], p["picture"]);  // intra only: display order is file order
    EXPECT_EQ(p["skipped"], false);
    EXPECT_EQ(p["macroblocks"], 256);
    EXPECT_GT(p["concealed_macroblocks"].get<int>(), 0);
    ASSERT_FALSE(p["issues"].empty());
    EXPECT_EQ(p["issue_count"], p["issues"].size());
    EXPECT_EQ(p["issues_not_listed"], 0);
    const std::string file = p["file"].get<std::string>();
    EXPECT_EQ(file, frameFile(p["frame"].get<int>(), "rgba"));
    damagedFiles.insert(file);
    issues += p["issue_count"].get<std::size_t>();
    concealed += p["concealed_macroblocks"].get<int>();
    for (const Json& i : p["issues"]) {
      // Found at or after the picture's first byte, inside the macroblocks of a 256x256 picture.
      EXPECT_GE(i["byte"].get<std::uint64_t>(), p["byte"].get<std::uint64_t>());
      ASSERT_TRUE(i["macroblock"].is_object()) << i;
      EXPECT_LT(i["macroblock"]["column"].get<int>(), 16);
      EXPECT_LT(i["macroblock"]["row"].get<int>(), 16);
      EXPECT_FALSE(i["kind"].get<std::string>().empty());
      const std::string line = "byte " + std::to_string(i["byte"].get<std::uint64_t>()) + ", picture " +
                               std::to_string(p["picture"].get<int>()) + " macroblock (" +
                               std::to_string(i["macroblock"]["column"].get<int>()) + "," +
                               std::to_string(i["macroblock"]["row"].get<int>()) +
                               "): " + i["reason"].get<std::string>();
      EXPECT_TRUE(has(r.err, line)) << line << "\n" << r.err;
    }
  }
  EXPECT_EQ(j["issues"], issues);
  EXPECT_EQ(j["concealed_macroblocks"], concealed);
  // Each picture named shows its concealment. (Flipped bits that still make valid codes change other
  // frames without an issue the decoder could find: ADamagedBPictureIsNamedByItsDisplayFrame damages
  // one picture only and checks that no other frame changes.)
  ASSERT_EQ(j["frames"], filesIn(dir_ / "clean").size());
  for (const std::string& f : damagedFiles)
    EXPECT_NE(readFileBytes(dir_ / "clean" / f), readFileBytes(dir_ / "bad" / f)) << f;
}

// In a GOP with B pictures the file order is not the display order: the damaged picture is named by
// its place in the file and by the frame it is shown as (its temporal_reference in a single GOP).
TEST_F(DecodeJson, ADamagedBPictureIsNamedByItsDisplayFrame) {
  vbim::ipu::testing::EncodeOptions o;
  o.width = 176;
  o.height = 144;
  o.frames = 7;
  o.gopSize = 12;
  o.bFrames = 2;
  o.quantiser = 2;
  o.content = vbim::ipu::testing::Content::kPattern;
  const std::vector<std::uint8_t> clean = vbim::ipu::testing::encodeIntra(o);
  // Picture start codes (00 00 01 00), their temporal_reference and picture_coding_type (§6.2.3).
  struct Picture {
    std::size_t at;
    int temporalReference;
    int type;
  };
  std::vector<Picture> pictures;
  for (std::size_t i = 0; i + 5 < clean.size(); ++i) {
    if (clean[i] == 0 && clean[i + 1] == 0 && clean[i + 2] == 1 && clean[i + 3] == 0)
      pictures.push_back({i, (clean[i + 4] << 2) | (clean[i + 5] >> 6), (clean[i + 5] >> 3) & 7});
  }
  ASSERT_EQ(pictures.size(), 7u);
  std::size_t k = 0;  // the first B picture in file order
  while (k < pictures.size() && pictures[k].type != 3) ++k;
  ASSERT_LT(k + 1, pictures.size());
  ASSERT_NE(pictures[k].temporalReference, static_cast<int>(k)) << "file order must differ from display order";
  std::vector<std::uint8_t> bad = clean;
  const std::size_t mid = (pictures[k].at + pictures[k + 1].at) / 2;
  for (std::size_t i = mid; i < mid + 12; ++i) bad[i] ^= 0xFF;
  const auto write = [](const fs::path& p, const std::vector<std::uint8_t>& bytes) {
    std::ofstream(p, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  };
  write(dir_ / "clean.m2v", clean);
  write(dir_ / "bad.m2v", bad);
  ASSERT_EQ(vbim("decode " + (dir_ / "clean.m2v").string() + " --format yuv -o " + (dir_ / "c").string()).status, 0);
  const Outcome r = vbim("decode " + (dir_ / "bad.m2v").string() + " --format yuv --json -o " + (dir_ / "b").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = parse(r);
  EXPECT_EQ(j["input"]["video_stream"], nullptr);  // an elementary stream
  ASSERT_EQ(j["damaged_pictures"].size(), 1u) << j.dump(2);
  const Json& p = j["damaged_pictures"][0];
  EXPECT_EQ(p["picture"], k);
  EXPECT_EQ(p["type"], "B");
  EXPECT_EQ(p["byte"], pictures[k].at);
  EXPECT_EQ(p["frame"], pictures[k].temporalReference);
  for (const Json& i : p["issues"]) {
    EXPECT_GE(i["byte"].get<std::size_t>(), mid) << i;
    EXPECT_LE(i["byte"].get<std::size_t>(), pictures[k + 1].at) << i;
  }
  // A B picture is no reference: only its own frame differs from the undamaged decode.
  for (const fs::path& f : filesIn(dir_ / "c")) {
    EXPECT_EQ(readFileBytes(f) != readFileBytes(dir_ / "b" / f.filename()),
              f.filename() == p["file"].get<std::string>())
        << f.filename();
  }
}

TEST_F(DecodeJson, EveryFormatGivesTheDocumentOfADamagedStream) {
  const fs::path damaged = damagedSample();
  Json first;
  for (const std::string format : {"png", "exr", "yuv", "rgba"}) {
    SCOPED_TRACE(format);
    const fs::path out = dir_ / format;
    const Outcome r = vbim("decode " + damaged.string() + " --format " + format + " --json -o " + out.string());
    ASSERT_EQ(r.status, 0) << r.err;
    const Json j = parse(r);
    EXPECT_EQ(j["options"]["format"], format);
    EXPECT_EQ(j["output"]["files"], j["frames"]);
    EXPECT_EQ(j["output"]["files"], filesIn(out).size());
    EXPECT_EQ(j["output"]["bytes"], bytesIn(out));
    EXPECT_EQ(j["output"]["file_pattern"], "frame_%05d." + format);
    ASSERT_EQ(j["damaged_pictures"].size(), 4u);
    for (const Json& p : j["damaged_pictures"]) EXPECT_TRUE(fs::exists(out / p["file"].get<std::string>())) << p;
    // The damage found does not depend on the format the frames are written in.
    if (first.is_null()) first = j["damaged_pictures"];
    for (Json& p : first) p["file"] = p["file"].get<std::string>().substr(0, 12) + format;  // "frame_00003."
    EXPECT_EQ(j["damaged_pictures"], first);
  }
}

TEST_F(DecodeJson, StrictPrintsTheDocumentWritesNothingAndExitsTwo) {
  const fs::path damaged = damagedSample();
  const Outcome loose = vbim("decode " + damaged.string() + " --json -o " + (dir_ / "loose").string());
  ASSERT_EQ(loose.status, 0) << loose.err;
  const Outcome r = vbim("decode " + damaged.string() + " --strict --json -o " + (dir_ / "strict").string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(has(r.err, "vbim decode: " + damaged.string() + " (video stream 0xE0): 9 issues (--strict)")) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "strict"));
  const Json j = parse(r);
  EXPECT_EQ(j["strict_failed"], true);
  EXPECT_EQ(j["options"]["strict"], true);
  EXPECT_EQ(j["output"]["written"], false);
  EXPECT_EQ(j["output"]["files"], 0);
  EXPECT_EQ(j["issues"], 9);
  // The same damage as without --strict; no file is named, as none was written.
  const Json l = parse(loose);
  ASSERT_EQ(j["damaged_pictures"].size(), l["damaged_pictures"].size());
  for (std::size_t i = 0; i < l["damaged_pictures"].size(); ++i) {
    Json p = l["damaged_pictures"][i];
    p["file"] = nullptr;
    EXPECT_EQ(j["damaged_pictures"][i], p);
  }
  // Without --json the summary line is not printed: it would name a directory that was not written.
  const Outcome text = vbim("decode " + damaged.string() + " --strict -o " + (dir_ / "strict").string());
  EXPECT_EQ(text.status, 2);
  EXPECT_EQ(text.out, "");
  // A clean stream passes --strict with its document.
  const Outcome clean = vbim("decode " + kSample + " --strict --json -o " + (dir_ / "clean").string());
  EXPECT_EQ(clean.status, 0) << clean.err;
  EXPECT_EQ(parse(clean)["strict_failed"], false);
}

// As info --json: what cannot be read as a stream at all is exit 2 with its message and nothing on
// stdout; a stream cut short decodes what is there, and the document says where it was cut.
TEST_F(DecodeJson, BadInputIsExitTwoWithoutADocumentAndATruncatedStreamIsReported) {
  const Outcome missing = vbim("decode " + (dir_ / "missing.vbim").string() + " --json -o " + (dir_ / "o1").string());
  EXPECT_EQ(missing.status, 2);
  EXPECT_EQ(missing.out, "");
  EXPECT_TRUE(has(missing.err, "missing.vbim: no such file")) << missing.err;
  std::ofstream(dir_ / "junk.bin") << "not a stream";
  const Outcome junk = vbim("decode " + (dir_ / "junk.bin").string() + " --json -o " + (dir_ / "o2").string());
  EXPECT_EQ(junk.status, 2);
  EXPECT_EQ(junk.out, "");
  EXPECT_TRUE(has(junk.err, "junk.bin: byte 0: not an MPEG program stream")) << junk.err;
  const std::string sample = readFileBytes(kSample);
  std::ofstream(dir_ / "descriptor_only.vbim", std::ios::binary) << sample.substr(0, 2048);
  const Outcome empty =
      vbim("decode " + (dir_ / "descriptor_only.vbim").string() + " --json -o " + (dir_ / "o3").string());
  EXPECT_EQ(empty.status, 2);
  EXPECT_EQ(empty.out, "");
  EXPECT_TRUE(has(empty.err, "without a video stream")) << empty.err;
  for (const char* o : {"o1", "o2", "o3"}) EXPECT_FALSE(fs::exists(dir_ / o)) << o;

  std::ofstream(dir_ / "cut.vbim", std::ios::binary) << sample.substr(0, 100000);
  const Outcome cut = vbim("decode " + (dir_ / "cut.vbim").string() + " --json -o " + (dir_ / "o4").string());
  ASSERT_EQ(cut.status, 0) << cut.err;
  const Json j = parse(cut);
  ASSERT_EQ(j["container_defects"].size(), 1u) << j.dump(2);
  EXPECT_TRUE(has(j["container_defects"][0]["message"].get<std::string>(), "truncated stream?"));
  EXPECT_LT(j["container_defects"][0]["byte"].get<std::uint64_t>(), 100000u);
  ASSERT_FALSE(j["damaged_pictures"].empty());
  const Json& last = j["damaged_pictures"].back();
  EXPECT_EQ(last["frame"].get<int>() + 1, j["frames"].get<int>());
  EXPECT_EQ(last["issues"][0]["kind"], "truncated_slice");
}

TEST_F(DecodeJson, QuietKeepsTheDocumentAndVerboseListsFilesOnStderr) {
  const Outcome quiet = vbim("decode " + kSample + " --format yuv --json -q -o " + (dir_ / "q").string());
  ASSERT_EQ(quiet.status, 0) << quiet.err;
  EXPECT_EQ(parse(quiet)["output"]["files"], filesIn(dir_ / "q").size());
  const Outcome verbose = vbim("decode " + kSample + " --format yuv --json -v -o " + (dir_ / "v").string());
  ASSERT_EQ(verbose.status, 0) << verbose.err;
  Json expected = parse(quiet);
  expected["output"]["directory"] = (dir_ / "v").string();
  EXPECT_EQ(parse(verbose), expected);
  EXPECT_TRUE(has(verbose.err, "vbim decode: wrote " + (dir_ / "v" / "frame_00000.yuv").string())) << verbose.err;
}

TEST_F(DecodeJson, NamesThatAreNotUtf8BecomeReplacementCharacters) {
  const fs::path odd = dir_ / std::string("day\xff\xfe.vbim");
  fs::copy_file(kSample, odd);
  const Outcome r = vbim("decode '" + odd.string() + "' --format yuv --json -o " + (dir_ / "o").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(has(r.err, "vbim decode: warning: text from the input is not UTF-8")) << r.err;
  const Json j = parse(r);
  EXPECT_TRUE(has(j["input"]["path"].get<std::string>(), "day\xef\xbf\xbd")) << j["input"];
}

TEST_F(DecodeJson, OnADiscImageTheFileIsNamedApart) {
  fs::create_directories(dir_ / "root" / "DATA");
  fs::copy_file(kSample, dir_ / "root" / "DATA" / "DAY.VBI");
  const fs::path iso = dir_ / "disc.iso";
  const auto mk = vbim::testing::runCommand("xorriso -as mkisofs -quiet -o '" + iso.string() + "' '" +
                                            (dir_ / "root").string() + "'");
  ASSERT_EQ(mk.status, 0) << mk.output;
  const Outcome r = vbim("decode " + iso.string() + " --format yuv --json -o " + (dir_ / "o").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = parse(r);
  EXPECT_EQ(j["input"]["path"], iso.string());
  EXPECT_EQ(j["input"]["file"], "\\DATA\\DAY.VBI;1");
  EXPECT_EQ(j["input"]["bytes"], fs::file_size(kSample));
  // From stdin the path is <stdin>.
  const Outcome piped = vbim("decode - --format yuv --json -o " + (dir_ / "p").string() + " < " + kSample);
  ASSERT_EQ(piped.status, 0) << piped.err;
  EXPECT_EQ(parse(piped)["input"]["path"], "<stdin>");
}

}  // namespace
