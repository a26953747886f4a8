// Issue #8 item 4, in process: Technique A frames go through the stream writer frame by frame; the
// stream reads back with our reader, every picture decodes within the codec's PSNR of the frame the
// generator renders on its own, and bad settings fail before anything is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lighting/authoring/technique_a_stream.hpp"
#include "streams/authoring/error.hpp"
#include "streams/authoring/mpeg2_decoder.hpp"
#include "streams/authoring/mpeg2_encoder.hpp"
#include "streams/demuxer.hpp"
#include "streams/format.hpp"

namespace vbim::lighting {
namespace {

namespace fs = std::filesystem;
using streams::AuthoringError;

// What the codec keeps at the default quantiser (q = 3) on this content: the procedural terrain at
// 64x64 texels of 40 m has detail at the texel scale, and measured 36.1-39 dB on the Y plane (Cb/Cr
// above 39.6 dB); the smooth synthetic frames of the streams tests reach 40 dB.
constexpr double kCodecPsnrDb = 35.0;

// 64x64 procedural terrain, 64x32 sky, 5 frames from 5 h to 19 h, two weathers.
TechniqueAStreamSettings small() {
  TechniqueAStreamSettings s;
  s.terrain.procedural.size = 64;
  s.terrain.procedural.cellSize = 40;
  s.base.frames = 5;
  s.base.startHour = 5;
  s.base.endHour = 19;
  s.base.skyWidth = 64;
  s.variants = {weatherVariant("clear", s.base), weatherVariant("overcast", s.base)};
  s.stream.gameFps = {1, 1};
  return s;
}

const AuthoredStream& smallStream() {
  static const AuthoredStream stream = authorTechniqueAStream(small());
  return stream;
}

TEST(AuthorTechniqueA, DescriptorSaysWhatWasAsked) {
  const AuthoredStream& s = smallStream();
  EXPECT_EQ(s.bytes.size() % streams::kSectorBytes, 0u);
  EXPECT_EQ(s.descriptor.framesPerVariant, 5u);
  ASSERT_EQ(s.descriptor.variants.size(), 2u);
  EXPECT_EQ(s.descriptor.variants[0].name, "clear");
  EXPECT_EQ(s.descriptor.variants[1].name, "overcast");
  ASSERT_EQ(s.descriptor.streams.size(), 2u);
  EXPECT_EQ(s.descriptor.streams[0].width, 64);
  EXPECT_EQ(s.descriptor.streams[0].height, 64);
  EXPECT_EQ(s.descriptor.streams[1].width, 64);
  EXPECT_EQ(s.descriptor.streams[1].height, 32);
  EXPECT_EQ(s.maxQscaleUsed, 3);
}

TEST(AuthorTechniqueA, EveryPictureDecodesWithinTheCodecPsnrOfTheGeneratorsFrame) {
  const AuthoredStream& s = smallStream();
  streams::Demuxer dm;
  for (std::uint32_t lsn = 0; lsn * streams::kSectorBytes < s.bytes.size(); ++lsn)
    ASSERT_EQ(dm.feed(std::span(s.bytes).subspan(std::size_t{lsn} * streams::kSectorBytes, streams::kSectorBytes), lsn),
              0u);
  dm.finish();
  ASSERT_TRUE(dm.descriptor());
  ASSERT_TRUE(dm.errors().empty());

  // The reference: the generator run on its own, frame by frame, tone-mapped as the writer's input.
  const TechniqueAStreamSettings settings = small();
  std::vector<Rgba8Image> lightmaps, skies;
  for (const WeatherVariant& v : settings.variants) {
    DayCycleGenerator gen(loadTerrain(settings.terrain), v.params);
    FloatImage lm, sky;
    for (int f = 0; f < gen.frameCount(); ++f) {
      gen.renderFrame(f, lm, sky);
      lightmaps.push_back(streamFrame(lm, settings.tone));
      skies.push_back(streamFrame(sky, settings.tone));
    }
  }
  // The two weathers really differ (the overcast one is dimmer at noon).
  auto mean = [](const Rgba8Image& img) {
    double sum = 0;
    for (std::size_t i = 0; i < img.pixels.size(); i += 4) sum += img.pixels[i + 1];
    return sum / (img.pixels.size() / 4);
  };
  EXPECT_LT(mean(lightmaps[5 + 2]), mean(lightmaps[2]) - 5);

  streams::Mpeg2Decoder dec;
  std::vector<int> seen(20, 0);
  for (const streams::Picture& p : dm.pictures()) {
    ASSERT_TRUE(p.frame);
    const bool isSky = p.streamId == streams::kSkyStream;
    const Rgba8Image& want = isSky ? skies.at(*p.frame) : lightmaps.at(*p.frame);
    ++seen[(isSky ? 10 : 0) + *p.frame];
    const Yuv420Image got = dec.decodeYuv(p.data);
    ASSERT_EQ(got.width, want.width);
    ASSERT_EQ(got.height, want.height);
    const streams::PlanePsnr psnr = streams::psnrYuv(got, streams::rgbaToYuv420(want));
    EXPECT_GE(psnr.min(), kCodecPsnrDb) << (isSky ? "sky" : "lightmap") << " frame " << *p.frame << ": Y " << psnr.y
                                        << " Cb " << psnr.cb << " Cr " << psnr.cr;
    // ... and it is this frame, not a neighbour or the other weather's: every other (different)
    // frame of the stream matches worse.
    const std::vector<Rgba8Image>& all = isSky ? skies : lightmaps;
    for (std::size_t j = 0; j < all.size(); ++j) {
      if (j == *p.frame || all[j].pixels == want.pixels) continue;
      EXPECT_LT(streams::psnrYuv(got, streams::rgbaToYuv420(all[j])).min(), psnr.min())
          << (isSky ? "sky" : "lightmap") << " frame " << *p.frame << " looks more like frame " << j;
    }
  }
  for (std::size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i], 1) << "picture " << i;
}

TEST(AuthorTechniqueA, SameSettingsSameBytesWhateverTheThreads) {
  TechniqueAStreamSettings s = small();
  s.threads = 3;
  EXPECT_EQ(authorTechniqueAStream(s).bytes, smallStream().bytes);
}

TEST(AuthorTechniqueA, ProgressCountsEveryFrameOfEveryVariant) {
  TechniqueAStreamSettings s = small();
  s.variants.pop_back();
  s.base.frames = s.variants[0].params.frames = 3;
  std::vector<int> done;
  authorTechniqueAStream(s, [&](const TechniqueAProgress& p) {
    EXPECT_EQ(p.total, 3);
    EXPECT_EQ(p.variant, "clear");
    EXPECT_EQ(p.frame, p.done - 1);
    done.push_back(p.done);
  });
  EXPECT_EQ(done, (std::vector<int>{1, 2, 3}));
}

// A whole day from midnight: the first pictures are a dark night sky, small enough that several
// complete before the first lightmap picture does (the writer once failed on that).
TEST(AuthorTechniqueA, ADayStartingAtMidnightAuthors) {
  TechniqueAStreamSettings s;
  s.terrain.procedural.size = 128;
  s.base.frames = 6;
  s.base.startHour = 0;
  s.base.endHour = 24;
  s.base.skyWidth = 128;
  const AuthoredStream a = authorTechniqueAStream(s);
  EXPECT_EQ(a.descriptor.framesPerVariant, 6u);
  ASSERT_EQ(a.descriptor.index.size(), 2u);
  EXPECT_LT(a.descriptor.index[1][0].sector, a.descriptor.index[0][1].sector);
}

void expectRejected(const TechniqueAStreamSettings& s, const std::string& words) {
  const fs::path out = fs::temp_directory_path() / ("vbim_author_api_" + std::to_string(::getpid()) + ".vbim");
  fs::remove(out);
  try {
    authorTechniqueA(s, out);
    ADD_FAILURE() << "accepted; expected an error with '" << words << "'";
  } catch (const AuthoringError& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(out));
}

TEST(AuthorTechniqueA, BadSettingsFailWithTheKeyAndWriteNothing) {
  TechniqueAStreamSettings s = small();
  s.variants[1].params.latitudeDeg = 91;
  expectRejected(s, "lighting.latitude_deg");
  s = small();
  s.variants[0].params.frames = 0;
  expectRejected(s, "lighting.frames");
  s = small();
  s.variants[1].params.frames = 4;
  expectRejected(s, "equal lengths");
  s = small();
  s.variants[1].name = "clear";
  expectRejected(s, "given twice");
  s = small();
  s.variants[0].params.skyWidth = s.variants[1].params.skyWidth = 48;  // 48x24: not whole macroblocks
  expectRejected(s, "multiple of 16");
  s = small();
  s.terrain.procedural.size = 40;
  s.terrain.fit = TerrainFit::None;
  expectRejected(s, "procedural terrain: width is 40");
  s = small();
  s.terrain.heightfield = "/nonexistent/hf.png";
  expectRejected(s, "/nonexistent/hf.png");
}

TEST(AuthorTechniqueA, SidesNotWholeMacroblocksAreCroppedCentredWithANote) {
  TerrainSource src;
  src.procedural.size = 40;
  std::vector<std::string> notes;
  const Terrain t = loadTerrain(src, &notes);
  ASSERT_EQ(t.width, 32);
  ASSERT_EQ(t.height, 32);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("cropped from 40x40 to 32x32 texels"), std::string::npos) << notes[0];
  const Terrain whole = proceduralTerrain(src.procedural);
  const FloatImage albedo = proceduralAlbedo(whole);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      ASSERT_EQ(t.at(x, y), whole.at(x + 4, y + 4)) << x << ", " << y;  // 4 texels off each side
      ASSERT_EQ(t.albedo.at(x, y)[1], albedo.at(x + 4, y + 4)[1]) << x << ", " << y;
    }
  src.fit = TerrainFit::Pad;
  EXPECT_EQ(loadTerrain(src).width, 48);
}

TEST(AuthorTechniqueA, UnknownWeatherNamesThePresets) {
  try {
    weatherVariant("foggy", DayCycleParams{});
    ADD_FAILURE();
  } catch (const AuthoringError& e) {
    EXPECT_NE(std::string(e.what()).find("'foggy'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("overcast"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vbim::lighting
