// decodeStream, the body of `vbim decode`: the same video decodes to the same frames whatever carries
// it (raw elementary stream, MPEG-2 packs of any size, MPEG-1 system stream); damage and failures are
// reported with file byte offsets.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "ipu/csc.hpp"
#include "streams/decode/frame_files.hpp"
#include "streams/decode/stream_decode.hpp"
#include "streams/video_elementary_stream.hpp"
#include "tests/ipu/support/field_picture_writer.hpp"
#include "tests/ipu/support/libav_mpeg.hpp"
#include "tests/streams/program_stream_builder.hpp"

namespace vbim::streams {
namespace {

using testing::append;
using testing::Bytes;

Bytes encode(bool mpeg1, int frames = 3, int w = 48, int h = 32) {
  ipu::testing::EncodeOptions o;
  o.width = w;
  o.height = h;
  o.frames = frames;
  o.mpeg1 = mpeg1;
  o.content = ipu::testing::Content::kPattern;
  return ipu::testing::encodeIntra(o);
}

struct Decoded {
  DecodeSummary summary;
  std::vector<Bytes> frames;  // Y, Cb, Cr of each
  std::vector<std::string> lines;
};

Decoded decode(const Bytes& file, DecodeOptions options = {}) {
  Decoded d;
  Yuv420Image yuv;
  d.summary = decodeStream(
      file, "in.mpg", options,
      [&](int frame, const ipu::Decoder& dec) {
        EXPECT_EQ(frame, static_cast<int>(d.frames.size()));
        // The frame due for display, as FrameFileWriter takes it (frame() is the one decoded last).
        ASSERT_NE(dec.displayFrame(), nullptr);
        ipu::copyToYuv420(*dec.displayFrame(), dec.displayWidth(), dec.displayHeight(), yuv);
        Bytes b = yuv.y;
        append(b, yuv.cb);
        append(b, yuv.cr);
        d.frames.push_back(std::move(b));
      },
      [&](const std::string& line) { d.lines.push_back(line); });
  return d;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l + "\n";
  return s;
}

TEST(StreamsDecode, EveryContainerGivesTheFramesOfItsElementaryStream) {
  for (const bool mpeg1 : {false, true}) {
    SCOPED_TRACE(mpeg1 ? "MPEG-1" : "MPEG-2");
    const Bytes es = encode(mpeg1);
    const Decoded raw = decode(es);
    ASSERT_EQ(raw.frames.size(), 3u);
    EXPECT_EQ(raw.summary.frames, 3);
    EXPECT_EQ(raw.summary.width, 48);
    EXPECT_EQ(raw.summary.height, 32);
    EXPECT_EQ(raw.summary.mpeg2, !mpeg1);
    EXPECT_EQ(raw.summary.streamLabel, "");
    EXPECT_EQ(raw.summary.issues, 0u);
    const Bytes containers[] = {testing::muxMpeg2(es, 0xE0, 1000), testing::muxMpeg2(es, 0xE0, 333),
                                testing::muxMpeg1(es, 0xE0, 2048), testing::muxMpeg1(es, 0xE0, 501)};
    for (const Bytes& ps : containers) {
      const Decoded d = decode(ps, {std::nullopt, 2});
      EXPECT_TRUE(d.lines.empty()) << joined(d.lines);
      EXPECT_EQ(d.summary.streamLabel, " (video stream 0xE0)");
      EXPECT_EQ(d.frames, raw.frames);
    }
  }
}

TEST(StreamsDecode, DecodesTheVideoStreamAskedFor) {
  Bytes ps = testing::muxMpeg2(encode(false, 2, 40, 24), 0xE0, 2048);
  append(ps, testing::muxMpeg2(encode(false, 4, 32, 16), 0xE1, 2048));
  const Decoded e1 = decode(ps, {0xE1, 0});
  EXPECT_EQ(e1.summary.frames, 4);
  EXPECT_EQ(e1.summary.width, 32);
  EXPECT_EQ(e1.summary.streamLabel, " (video stream 0xE1)");
  EXPECT_EQ(decode(ps).summary.frames, 2);
  try {
    decode(ps, {0xE2, 0});
    FAIL() << "no stream 0xE2";
  } catch (const vbim::Error& e) {
    EXPECT_STREQ(e.what(), "in.mpg: MPEG program stream without video stream 0xE2");
  }
}

TEST(StreamsDecode, ReportsIssuesAtTheirFileOffsets) {
  Bytes es = encode(false, 2, 64, 48);
  for (std::size_t i = 120; i < es.size(); i += 211) es[i] ^= 0x24;
  const Bytes ps = testing::muxMpeg2(es, 0xE0, 700);
  const Decoded fromEs = decode(es);
  const Decoded fromPs = decode(ps);
  EXPECT_GT(fromEs.summary.issues, 0u);
  EXPECT_GT(fromEs.summary.concealedMacroblocks, 0);
  EXPECT_EQ(fromPs.frames, fromEs.frames);
  ASSERT_EQ(fromPs.lines.size(), fromEs.lines.size());
  // Each line names the byte: in the program stream, the file byte that holds the same ES byte.
  const VideoElementaryStream video = readVideoStream(ps);
  const std::string prefix = "in.mpg: byte ";
  for (std::size_t i = 0; i < fromEs.lines.size(); ++i) {
    const std::string& l = fromEs.lines[i];
    if (l.rfind(prefix, 0) != 0) continue;  // "... and N more issues"
    const std::size_t esByte = std::stoull(l.substr(prefix.size()));
    const std::string rest = l.substr(l.find_first_not_of("0123456789", prefix.size()));
    EXPECT_EQ(fromPs.lines[i], "in.mpg (video stream 0xE0): byte " + std::to_string(video.fileOffsetOf(esByte)) + rest);
    if (esByte == es.size()) {  // "at the end of the data": just past the last byte
      EXPECT_EQ(video.fileOffsetOf(esByte), video.fileOffsetOf(esByte - 1) + 1);
      continue;
    }
    ASSERT_LT(esByte, es.size()) << l;
    EXPECT_EQ(ps[video.fileOffsetOf(esByte)], es[esByte]) << l;
  }
}

TEST(StreamsDecode, ATruncatedStreamDecodesWhatIsThereWithAWarning) {
  const Bytes es = encode(false, 3);
  const Bytes whole = testing::muxMpeg2(es, 0xE0, 1000);
  const Bytes cut(whole.begin(), whole.end() - 700);
  const Decoded d = decode(cut);
  ASSERT_FALSE(d.lines.empty());
  EXPECT_EQ(d.lines[0].rfind("warning: in.mpg: byte ", 0), 0u) << d.lines[0];
  EXPECT_NE(d.lines[0].find("truncated"), std::string::npos) << d.lines[0];
  EXPECT_GE(d.summary.frames, 2);
}

TEST(StreamsDecode, RefusesWhatIsNotAVideoStream) {
  const auto message = [](const Bytes& file) {
    try {
      decode(file);
    } catch (const vbim::Error& e) {
      return std::string(e.what());
    }
    return std::string("(decoded)");
  };
  EXPECT_EQ(message({1, 2, 3, 4, 5}),
            "in.mpg: byte 0: not an MPEG program stream or video elementary stream (expected 00 00 01 BA or 00 00 01 "
            "B3)");
  Bytes audio = testing::mpeg2PackHeader(0, 2500);
  append(audio, testing::mpeg2Pes(0xC0, Bytes(10, 0x55)));
  EXPECT_EQ(message(audio), "in.mpg: MPEG program stream without a video stream (PES id 0xE0..0xEF)");
  Bytes noSequence = encode(false, 2);
  for (std::size_t i = 0; i + 3 < noSequence.size(); ++i)
    if (noSequence[i] == 0 && noSequence[i + 1] == 0 && noSequence[i + 2] == 1 && noSequence[i + 3] == 0xB3)
      noSequence[i + 3] = 0xB2;
  EXPECT_EQ(message(noSequence), "in.mpg: byte 0: cannot decode: no sequence header before the picture");
}

// The picture coding extensions of `file` (00 00 01 B5, extension id 8), in order.
std::vector<std::size_t> codingExtensions(const Bytes& file) {
  std::vector<std::size_t> at;
  for (std::size_t i = 0; i + 4 < file.size(); ++i)
    if (file[i] == 0 && file[i + 1] == 0 && file[i + 2] == 1 && file[i + 3] == 0xB5 && (file[i + 4] >> 4) == 8)
      at.push_back(i);
  return at;
}

TEST(StreamsDecode, APictureThatCannotBeDecodedIsSkippedAndTheRestDecoded) {
  const Bytes whole = encode(false, 4);
  const Decoded good = decode(whole);
  ASSERT_EQ(good.frames.size(), 4u);
  for (std::size_t i = 1; i < 4; ++i) ASSERT_NE(good.frames[i - 1], good.frames[i]) << "the content must move";
  Bytes damaged = whole;
  const std::vector<std::size_t> ext = codingExtensions(damaged);
  ASSERT_EQ(ext.size(), 4u);
  damaged[ext[1] + 3] = 0xB2;  // picture 1 loses its coding extension (user data instead)
  const Decoded d = decode(damaged);
  EXPECT_EQ(d.summary.skippedPictures, 1);
  EXPECT_GE(d.summary.issues, 1u);
  ASSERT_EQ(d.frames.size(), 3u);
  // Intra pictures: the others decode exactly as in the whole stream.
  EXPECT_EQ(d.frames[0], good.frames[0]);
  EXPECT_EQ(d.frames[1], good.frames[2]);
  EXPECT_EQ(d.frames[2], good.frames[3]);
  const std::string text = joined(d.lines);
  EXPECT_NE(text.find("cannot decode: MPEG-2 picture without a picture coding extension; picture skipped"),
            std::string::npos)
      << text;

  // Many such pictures: the first 20 are named, the rest counted.
  Bytes many = encode(false, 24);
  const std::vector<std::size_t> all = codingExtensions(many);
  ASSERT_EQ(all.size(), 24u);
  for (std::size_t i = 1; i < all.size(); ++i) many[all[i] + 3] = 0xB2;
  const Decoded m = decode(many);
  EXPECT_EQ(m.summary.skippedPictures, 23);
  EXPECT_EQ(m.frames.size(), 1u);
  std::size_t named = 0;
  for (const std::string& l : m.lines) named += l.find("; picture skipped") != std::string::npos;
  EXPECT_EQ(named, 20u) << joined(m.lines);
  EXPECT_NE(joined(m.lines).find("counted, not listed"), std::string::npos);
}

// The picture start codes (00 00 01 00) of an elementary stream, in file order.
std::vector<std::size_t> pictureStarts(const Bytes& es) {
  std::vector<std::size_t> at;
  for (std::size_t i = 0; i + 3 < es.size(); ++i)
    if (es[i] == 0 && es[i + 1] == 0 && es[i + 2] == 1 && es[i + 3] == 0) at.push_back(i);
  return at;
}

// The summary keeps each damaged picture with the frame it was written as: two field pictures make
// one frame, so either field's damage is that frame's, and the pictures after it keep counting.
TEST(StreamsDecode, ADamagedFieldIsNamedByTheFrameItCompletes) {
  ipu::testing::FieldStreamOptions o;
  o.dualPrime = false;
  o.pictures = 2;  // an I frame, then two P frames of two fields each: five pictures, three frames
  const Bytes clean = ipu::testing::makeFieldStream(o);
  const std::vector<std::size_t> starts = pictureStarts(clean);
  ASSERT_EQ(starts.size(), 5u);
  const Decoded whole = decode(clean);
  EXPECT_EQ(whole.summary.pictures, 5);
  EXPECT_EQ(whole.summary.frames, 3);
  EXPECT_TRUE(whole.summary.damaged.empty()) << joined(whole.lines);
  for (const std::size_t field : {1u, 2u, 3u, 4u}) {
    SCOPED_TRACE("field picture " + std::to_string(field));
    Bytes bad = clean;
    const std::size_t mid = (starts[field] + (field + 1 < starts.size() ? starts[field + 1] : bad.size())) / 2;
    for (std::size_t i = mid; i < mid + 6; ++i) bad[i] ^= 0xFF;
    const Decoded d = decode(bad);
    ASSERT_EQ(d.summary.damaged.size(), 1u) << joined(d.lines);
    const DamagedPicture& p = d.summary.damaged[0];
    EXPECT_EQ(p.picture, static_cast<int>(field));
    EXPECT_EQ(p.codingType, 2);
    EXPECT_EQ(p.fileOffset, starts[field]);
    EXPECT_EQ(p.frame, static_cast<int>(field + 1) / 2);  // fields 1 and 2 make frame 1, 3 and 4 frame 2
    EXPECT_FALSE(p.skipped);
    ASSERT_FALSE(p.issues.empty());
    EXPECT_EQ(p.issueCount, p.issues.size());
    for (const LocatedIssue& i : p.issues) {
      EXPECT_GE(i.fileOffset, mid);
      EXPECT_NE(joined(d.lines).find("byte " + std::to_string(i.fileOffset) + ", picture " + std::to_string(field)),
                std::string::npos)
          << joined(d.lines);
    }
    // The frame named is the first that differs from the undamaged decode.
    ASSERT_GE(p.frame, 0);
    ASSERT_LT(p.frame, static_cast<int>(d.frames.size()));
    for (std::size_t f = 0; f < static_cast<std::size_t>(p.frame); ++f) EXPECT_EQ(d.frames[f], whole.frames[f]) << f;
    EXPECT_NE(d.frames[static_cast<std::size_t>(p.frame)], whole.frames[static_cast<std::size_t>(p.frame)]);
  }
}

TEST(StreamsDecode, WritesFramesAsFiles) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("vbim-stream-decode-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const Bytes es = encode(false, 2, 40, 24);
  for (const FrameFileFormat f : {FrameFileFormat::Yuv, FrameFileFormat::Png, FrameFileFormat::Rgba}) {
    FrameFileWriter writer(dir, f);
    decodeStream(
        es, "a.m2v", {}, [&](int frame, const ipu::Decoder& d) { writer.write(frame, d); }, [](const std::string&) {});
  }
  EXPECT_EQ(std::filesystem::file_size(dir / "frame_00001.yuv"), 40u * 24 * 3 / 2);
  // Raw RGB32 of the 40x24 display size (vbim replay --frames): the converted pixels, alpha 0x80.
  EXPECT_EQ(std::filesystem::file_size(dir / "frame_00001.rgba"), 40u * 24 * 4);
  {
    std::ifstream rgba(dir / "frame_00001.rgba", std::ios::binary);
    rgba.seekg(3);
    EXPECT_EQ(rgba.get(), 0x80);
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "frame_00001.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "frame_00002.png"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace vbim::streams
