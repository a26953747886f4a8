// The authoring record (streams/record_packs.hpp): packs after the last video sector that the
// reader skips, found again whole, and not found when cut short.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "streams/format.hpp"
#include "streams/pack_parser.hpp"
#include "streams/record_packs.hpp"
#include "streams/stream_stats.hpp"

namespace vbim::streams {
namespace {

// The clear-day sample's video sectors (without its own record).
std::vector<std::uint8_t> sampleVideo() {
  const char* root = std::getenv("VBIM_SOURCE_DIR");
  std::ifstream in(std::filesystem::path(root ? root : ".") / "streams" / "samples" / "day_clear.vbim",
                   std::ios::binary);
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const StreamScan scan = scanStream(bytes);
  if (!scan.descriptor) return {};
  bytes.resize(std::size_t{scan.descriptor->totalSectors} * kSectorBytes);
  return bytes;
}

TEST(AuthoringRecord, FollowsTheVideoAndReadersSkipIt) {
  const std::vector<std::uint8_t> video = sampleVideo();
  ASSERT_FALSE(video.empty());
  std::string text = "{\"record\":\"vbim-authoring\",\"frame_hours\":[";
  for (int i = 0; i < 900; ++i) text += std::to_string(i) + ",";
  text += "0]}";
  std::vector<std::uint8_t> stream = video;
  appendAuthoringRecord(stream, text);
  const std::size_t sectors = authoringRecordSectors(text.size());
  EXPECT_EQ(sectors, 2u);
  ASSERT_EQ(stream.size(), video.size() + sectors * kSectorBytes);
  EXPECT_TRUE(std::equal(video.begin(), video.end(), stream.begin()));  // nothing before it changes

  const std::span<const std::uint8_t> tail(stream.data() + video.size(), stream.size() - video.size());
  EXPECT_EQ(findAuthoringRecord(tail), text);
  EXPECT_EQ(findAuthoringRecord(stream), text);
  // Its packs continue the stream's clock at the mux rate.
  ParsedPack last, first;
  ASSERT_FALSE(parsePack(std::span(video).subspan(video.size() - kSectorBytes), 0, last));
  ASSERT_FALSE(parsePack(tail.subspan(0, kSectorBytes), 0, first));
  EXPECT_GT(first.scr27MHz, last.scr27MHz);
  EXPECT_EQ(first.muxRate, last.muxRate);

  // A reader that knows nothing of it sees the same stream: same pictures, no errors.
  const StreamScan with = scanStream(stream), without = scanStream(video);
  EXPECT_TRUE(with.errors.empty());
  EXPECT_TRUE(with.every2048);
  EXPECT_EQ(with.pictures.size(), without.pictures.size());
  EXPECT_EQ(with.descriptor, without.descriptor);

  // Cut short (the last pack lost): no record rather than part of one.
  EXPECT_FALSE(findAuthoringRecord(tail.subspan(0, kSectorBytes)));
  EXPECT_FALSE(findAuthoringRecord(video));
}

TEST(AuthoringRecord, NeedsWholePacksToFollow) {
  std::vector<std::uint8_t> notPacks(100, 0);
  EXPECT_THROW(appendAuthoringRecord(notPacks, "{}"), std::invalid_argument);
  std::vector<std::uint8_t> zeros(kSectorBytes, 0);
  EXPECT_THROW(appendAuthoringRecord(zeros, "{}"), std::invalid_argument);
}

}  // namespace
}  // namespace vbim::streams
