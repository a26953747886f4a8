// Re-encoding a VBIM stream at another quantiser or bitrate (streams/authoring/transcode.hpp, used by
// `vbim profile --qscale/--bitrate`): the same frames, variants and timing, other pictures.
#include <gtest/gtest.h>

#include <string>

#include "streams/authoring/error.hpp"
#include "streams/authoring/transcode.hpp"
#include "streams/stream_stats.hpp"
#include "tests/streams/stream_fixture.hpp"

namespace vbim::streams {
namespace {

using test::smallStream;
using test::TempDir;

TEST(StreamsTranscode, KeepsTheDescriptorAndChangesThePictures) {
  const auto& original = smallStream(4, 2);
  TempDir dir;
  test::writeFile(dir / "in.vbim", original.bytes);
  EncoderSettings coarse;
  coarse.qscale = 20;
  const std::vector<std::uint8_t> out = transcodeStream(dir / "in.vbim", coarse);
  const StreamScan scan = scanStream(out);
  ASSERT_TRUE(scan.errors.empty()) << scan.errors.front().describe();
  ASSERT_TRUE(scan.descriptor);
  const Descriptor& d = *scan.descriptor;
  EXPECT_EQ(d.framesPerVariant, original.descriptor.framesPerVariant);
  ASSERT_EQ(d.variants.size(), 2u);
  EXPECT_EQ(d.variants[1].name, original.descriptor.variants[1].name);
  EXPECT_EQ(d.gameFps, original.descriptor.gameFps);
  EXPECT_EQ(d.ptsPerFrame, original.descriptor.ptsPerFrame);
  EXPECT_EQ(d.streams.size(), original.descriptor.streams.size());
  EXPECT_EQ(scan.pictures.size(), 2u * 2 * 4);
  EXPECT_LT(out.size(), original.bytes.size());  // a coarser quantiser: fewer bytes
}

TEST(StreamsTranscode, NamesTheFileItCannotReEncode) {
  TempDir dir;
  test::writeFile(dir / "junk.vbim", std::vector<std::uint8_t>(4096, 0x47));
  const auto message = [](const std::filesystem::path& p) {
    try {
      transcodeStream(p, {});
    } catch (const AuthoringError& e) {
      return std::string(e.what());
    }
    return std::string("(re-encoded)");
  };
  EXPECT_EQ(message(dir / "junk.vbim"),
            (dir / "junk.vbim").string() + ": not a VBIM stream (no playback descriptor); cannot re-encode");
  EXPECT_EQ(message(dir / "absent.vbim"), (dir / "absent.vbim").string() + ": cannot open the stream to re-encode");
}

}  // namespace
}  // namespace vbim::streams
