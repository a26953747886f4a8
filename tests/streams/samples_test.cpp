// The committed sample streams are well formed and say what their README says.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>

#include "streams/format.hpp"
#include "streams/record_packs.hpp"
#include "streams/stream_stats.hpp"

namespace vbim::streams {
namespace {

std::filesystem::path samples() {
  const char* root = std::getenv("VBIM_SOURCE_DIR");
  return std::filesystem::path(root ? root : ".") / "streams" / "samples";
}

void expectSample(const char* name, std::uint32_t frames, std::vector<std::string> variants) {
  const StreamScan scan = scanStreamFile(samples() / name);
  EXPECT_TRUE(scan.every2048) << name;
  ASSERT_TRUE(scan.errors.empty()) << name << ": " << scan.errors.front().describe();
  ASSERT_TRUE(scan.descriptor) << name;
  const Descriptor& d = *scan.descriptor;
  EXPECT_EQ(d.framesPerVariant, frames);
  ASSERT_EQ(d.variants.size(), variants.size());
  for (std::size_t v = 0; v < variants.size(); ++v) EXPECT_EQ(d.variants[v].name, variants[v]);
  ASSERT_EQ(d.streams.size(), 2u);
  EXPECT_EQ(d.streams[0].width, 256);
  EXPECT_EQ(d.streams[1].width, 128);
  // The video ends at total_sectors; the authoring record (how the sample was made) follows it.
  std::ifstream in(samples() / name, std::ios::binary);
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t videoBytes = std::size_t{d.totalSectors} * kSectorBytes;
  ASSERT_LE(videoBytes, bytes.size()) << name;
  const std::span<const std::uint8_t> tail(bytes.data() + videoBytes, bytes.size() - videoBytes);
  const auto record = findAuthoringRecord(tail);
  ASSERT_TRUE(record) << name;
  EXPECT_NE(record->find("\"source\":\"technique-a\""), std::string::npos) << *record;
  EXPECT_EQ(d.totalSectors + authoringRecordSectors(record->size()), scan.sectors) << name;
  EXPECT_FALSE(findAuthoringRecord(std::span(bytes.data(), videoBytes))) << name << ": a record among the video";
  EXPECT_EQ(scan.pictures.size(), 2 * d.totalFrames());
  for (const PictureRecord& p : scan.pictures) {
    ASSERT_TRUE(p.frame);
    EXPECT_FALSE(p.damaged);
  }
}

TEST(StreamsSamples, DayClear) {
  expectSample("day_clear.vbim", 24, {"clear"});
}
TEST(StreamsSamples, DayWeather) {
  expectSample("day_weather.vbim", 12, {"clear", "overcast"});
}

}  // namespace
}  // namespace vbim::streams
