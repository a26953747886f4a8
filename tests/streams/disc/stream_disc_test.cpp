// The stream a command plays from a disc it is given (streams/disc/stream_disc.hpp): an ISO 9660
// image is told from a bare stream by its volume descriptor, not its name; the stream on it is the
// file --file names or the image's only VBIM stream; the file keeps the image's LBAs.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "iop/error.hpp"
#include "streams/disc/iso_disc.hpp"
#include "streams/disc/stream_disc.hpp"
#include "tests/iop/disc_error_of.hpp"
#include "tests/support/run_command.hpp"

namespace vbim::streams::test {
namespace {

namespace fs = std::filesystem;

const fs::path kSample = fs::path(VBIM_SOURCE_DIR) / "streams" / "samples" / "day_clear.vbim";
const fs::path kOther = fs::path(VBIM_SOURCE_DIR) / "streams" / "samples" / "day_weather.vbim";

fs::path tempDir() {
  const fs::path d = fs::temp_directory_path() / ("vbim_stream_disc_" + std::to_string(::getpid()) + "_" +
                                                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::remove_all(d);
  fs::create_directories(d / "root");
  return d;
}

// An image of d/root, named `name` (any extension: detection must not look at it).
fs::path makeIso(const fs::path& d, const std::string& name) {
  const fs::path iso = d / name;
  const std::string cmd = "xorriso -abort_on FAILURE -report_about FAILURE -as mkisofs -quiet -o '" + iso.string() +
                          "' '" + (d / "root").string() + "' >/dev/null 2>&1";
  if (std::system(cmd.c_str()) != 0) return {};
  return iso;
}

using iop::test::discErrorOf;

TEST(StreamDisc, AnImageIsKnownByItsVolumeDescriptorNotItsName) {
  const fs::path d = tempDir();
  fs::create_directories(d / "root" / "DATA");
  fs::copy_file(kSample, d / "root" / "DATA" / "DAY.VBI");
  const fs::path iso = makeIso(d, "looks_like_a.vbim");
  ASSERT_FALSE(iso.empty()) << "xorriso failed";
  fs::copy_file(kSample, d / "stream.iso");
  EXPECT_TRUE(isIsoImage(iso));
  EXPECT_FALSE(isIsoImage(d / "stream.iso"));
  EXPECT_FALSE(isIsoImage(d / "missing.iso"));

  const StreamDisc onImage = openStreamDisc(iso.string());
  EXPECT_TRUE(onImage.image);
  EXPECT_EQ(onImage.file.path, "\\DATA\\DAY.VBI;1");
  EXPECT_EQ(onImage.file.bytes, static_cast<std::int64_t>(fs::file_size(kSample)));
  // The file keeps the image's LBA (where xorriso put it), and its bytes are the stream's.
  const IsoDisc direct(iso.string());
  EXPECT_EQ(onImage.file.lba, direct.find("/data/day.vbi")->lba);
  std::ifstream in(kSample, std::ios::binary);
  const std::vector<std::uint8_t> sample((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(readDiscFile(*onImage.disc, onImage.file), sample);

  const StreamDisc bare = openStreamDisc((d / "stream.iso").string());
  EXPECT_FALSE(bare.image);
  EXPECT_EQ(bare.file.lba, 2048);
  EXPECT_EQ(readDiscFile(*bare.disc, bare.file), sample);
  const std::string m = discErrorOf([&] { openStreamDisc((d / "stream.iso").string(), "\\DATA\\DAY.VBI;1"); });
  EXPECT_NE(m.find("--file '\\DATA\\DAY.VBI;1' picks a file on an ISO 9660 disc image, but this is a bare stream"),
            std::string::npos)
      << m;
  fs::remove_all(d);
}

TEST(StreamDisc, FilesAreListedWithTheirLbas) {
  const fs::path d = tempDir();
  fs::create_directories(d / "root" / "DATA" / "SUB");
  fs::copy_file(kSample, d / "root" / "DATA" / "DAY.VBI");
  std::ofstream(d / "root" / "DATA" / "SUB" / "LEVEL2.BIN") << std::string(5000, 'x');
  const fs::path iso = makeIso(d, "disc.iso");
  ASSERT_FALSE(iso.empty()) << "xorriso failed";
  const IsoDisc disc(iso.string());
  const std::vector<iop::DiscFile> files = disc.files();
  ASSERT_EQ(files.size(), 2u);
  for (const iop::DiscFile& f : files) {
    const auto found = disc.find(f.path);  // every listed name is one find() accepts
    ASSERT_TRUE(found) << f.path;
    EXPECT_EQ(found->lba, f.lba) << f.path;
    EXPECT_EQ(found->bytes, f.bytes) << f.path;
  }
  EXPECT_EQ(files[0].path, "\\DATA\\DAY.VBI;1");
  EXPECT_EQ(files[1].path, "\\DATA\\SUB\\LEVEL2.BIN;1");
  EXPECT_EQ(files[1].bytes, 5000);
  fs::remove_all(d);
}

TEST(StreamDisc, TheStreamIsPickedByFileOrElseTheOnlyOne) {
  const fs::path d = tempDir();
  fs::create_directories(d / "root" / "DATA");
  fs::copy_file(kSample, d / "root" / "DATA" / "DAY.VBI");
  fs::copy_file(kOther, d / "root" / "DATA" / "STORM.VBI");
  std::ofstream(d / "root" / "DATA" / "LEVEL2.BIN") << std::string(9000, 'x');
  const fs::path iso = makeIso(d, "two.iso");
  ASSERT_FALSE(iso.empty()) << "xorriso failed";

  const std::string many = discErrorOf([&] { openStreamDisc(iso.string()); });
  EXPECT_NE(many.find(iso.string() + ": 2 VBIM streams on the disc image; pick one with --file"), std::string::npos)
      << many;
  EXPECT_NE(many.find("\\DATA\\DAY.VBI;1 (LBA "), std::string::npos) << many;
  EXPECT_NE(many.find("\\DATA\\STORM.VBI;1 (LBA "), std::string::npos) << many;
  EXPECT_EQ(many.find("LEVEL2"), std::string::npos) << many;  // not a stream: not a candidate

  EXPECT_EQ(openStreamDisc(iso.string(), "\\DATA\\STORM.VBI;1").file.bytes,
            static_cast<std::int64_t>(fs::file_size(kOther)));
  EXPECT_EQ(openStreamDisc(iso.string(), "/data/day.vbi").file.bytes,
            static_cast<std::int64_t>(fs::file_size(kSample)));
  const std::string missing = discErrorOf([&] { openStreamDisc(iso.string(), "\\DATA\\NIGHT.VBI;1"); });
  EXPECT_NE(missing.find(": no file '\\DATA\\NIGHT.VBI;1' on the disc image; its VBIM streams are:"), std::string::npos)
      << missing;
  EXPECT_NE(missing.find("\\DATA\\STORM.VBI;1"), std::string::npos) << missing;

  fs::remove(d / "root" / "DATA" / "DAY.VBI");
  fs::remove(d / "root" / "DATA" / "STORM.VBI");
  const fs::path none = makeIso(d, "none.iso");
  ASSERT_FALSE(none.empty()) << "xorriso failed";
  const std::string noStream = discErrorOf([&] { openStreamDisc(none.string()); });
  EXPECT_NE(noStream.find(": no VBIM stream on the disc image; its files are:\n  \\DATA\\LEVEL2.BIN;1 (LBA "),
            std::string::npos)
      << noStream;
  fs::remove_all(d);
}

}  // namespace
}  // namespace vbim::streams::test
