#include "imageio/stored_png.hpp"

#include <libdeflate.h>

#include <algorithm>
#include <array>
#include <cstring>

#include "imageio/rgb_pack.hpp"

namespace vbim::imageio {

namespace {

// PNG specification (ISO/IEC 15948): 5.2 the signature, 11.2.2 the colour type by channel count
// (grey, grey + alpha, RGB, RGBA), 11.3.3.5 sRGB's rendering intent 0 (perceptual).
constexpr std::array<std::uint8_t, 8> kSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr std::array<std::uint8_t, 5> kColourType = {0, 0, 4, 2, 6};
constexpr std::size_t kChunkFraming = 12;  // length, type, CRC
constexpr std::size_t kIhdrData = 13;
constexpr std::size_t kSrgbData = 1;

// The zlib stream around the blocks (RFC 1950): a 2-byte header, the Adler-32 of the data last.
constexpr std::size_t kZlibHeader = 2;
constexpr std::size_t kAdler = 4;
// A stored block (RFC 1951, 3.2.4): a header byte (BFINAL, BTYPE 00), LEN and its complement NLEN.
constexpr std::size_t kBlockHeader = 5;
constexpr std::size_t kMaxStoredBlock = 65535;  // LEN is 16 bits

// How zlib 1.2.13 cuts the rows into stored blocks at level 0 behind libpng, which hands deflate
// one row at a time and Z_FINISH after the last (found by reading the blocks libpng wrote for many
// shapes; tests/imageio/stored_png_test.cpp checks them): the data waits until it reaches zlib's
// window (32 KiB at libpng's window bits for pictures over 16 KiB; smaller pictures fit under
// their window and never reach it), then goes out as blocks of all of it, at most 65,535 bytes
// each, for as long as 32 KiB is left; the rest is a final block, empty when nothing is left.
constexpr std::size_t kBlockThreshold = 32768;

// The zlib header libpng writes for stored data of `dataSize` bytes: CM 8 (deflate), CINFO the
// window's log2 - 8, the smallest window that holds the data up to zlib's 32 KiB (libpng shrinks
// the window, and then the header, for pictures of at most 16 KiB); FLEVEL 0 (level 0), no
// dictionary, FCHECK making the pair a multiple of 31.
std::array<std::uint8_t, kZlibHeader> zlibHeader(std::size_t dataSize) {
  unsigned cinfo = 0;
  while (cinfo < 7 && (std::size_t{256} << cinfo) < dataSize) ++cinfo;
  const unsigned cmf = (cinfo << 4) | 8u;
  const unsigned flg = 31 - (cmf * 256) % 31;  // never 0 for these eight headers
  return {static_cast<std::uint8_t>(cmf), static_cast<std::uint8_t>(flg)};
}

// The stored blocks' lengths in order (kBlockThreshold says how zlib chooses them).
class BlockLengths {
 public:
  BlockLengths(std::size_t rowBytes, std::size_t rows) : rowBytes_(rowBytes), rowsLeft_(rows) {}
  // The next block's length, and whether it is the last.
  std::size_t next(bool& last) {
    while (waiting_ < kBlockThreshold && rowsLeft_ > 0) {
      waiting_ += rowBytes_;
      --rowsLeft_;
    }
    last = waiting_ < kBlockThreshold;
    const std::size_t length = std::min(waiting_, kMaxStoredBlock);
    waiting_ -= length;
    return length;
  }

 private:
  std::size_t rowBytes_;
  std::size_t rowsLeft_;
  std::size_t waiting_ = 0;  // handed to zlib and not yet in a block
};

// A row in the zlib stream: its filter byte and its samples.
std::size_t rowBytes(ImageView<std::uint8_t> image) {
  return 1 + static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.channels);
}

std::size_t dataSize(ImageView<std::uint8_t> image) {
  return rowBytes(image) * static_cast<std::size_t>(image.height);
}

std::size_t idatSize(ImageView<std::uint8_t> image) {
  BlockLengths lengths(rowBytes(image), static_cast<std::size_t>(image.height));
  std::size_t blocks = 0;
  for (bool last = false; !last; ++blocks) lengths.next(last);
  return kZlibHeader + blocks * kBlockHeader + dataSize(image) + kAdler;
}

std::uint8_t* putU32(std::uint8_t* p, std::uint32_t v) {  // big-endian (PNG, 7.1)
  p[0] = static_cast<std::uint8_t>(v >> 24);
  p[1] = static_cast<std::uint8_t>(v >> 16);
  p[2] = static_cast<std::uint8_t>(v >> 8);
  p[3] = static_cast<std::uint8_t>(v);
  return p + 4;
}

// A chunk's length and type at `p`; returns where its data goes.
std::uint8_t* beginChunk(std::uint8_t* p, std::size_t length, const char (&type)[5]) {
  p = putU32(p, static_cast<std::uint32_t>(length));
  std::memcpy(p, type, 4);
  return p + 4;
}

// The CRC-32 of the chunk whose data ends at `end` (over its type and data), after it.
std::uint8_t* endChunk(std::uint8_t* chunkType, std::uint8_t* end) {
  return putU32(end, libdeflate_crc32(0, chunkType, static_cast<std::size_t>(end - chunkType)));
}

// The rows as the zlib stream's data: filter byte 0 (None) and the row's samples, row after row;
// `take` packs (RgbOfRgba) or copies the next `count` bytes of it. A piece may start or end inside
// a texel (the stored blocks are cut by byte counts).
class RowStream {
 public:
  RowStream(ImageView<std::uint8_t> image, FileChannels channels)
      : samples_(image.samples),
        packing_(channels == FileChannels::RgbOfRgba),
        sourceStride_(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.channels)),
        stride_(packing_ ? static_cast<std::size_t>(image.width) * 3 : sourceStride_) {}
  std::uint8_t* take(std::uint8_t* out, std::size_t count) {
    while (count > 0) {
      if (inRow_ == 0) {
        *out++ = 0;
        inRow_ = 1;
        --count;
        continue;
      }
      const std::size_t n = std::min(count, stride_ + 1 - inRow_);
      if (packing_) {
        packPiece(inRow_ - 1, n, out);
      } else {
        std::memcpy(out, samples_ + (inRow_ - 1), n);
      }
      out += n;
      count -= n;
      inRow_ += n;
      if (inRow_ == stride_ + 1) {
        samples_ += sourceStride_;
        inRow_ = 0;
      }
    }
    return out;
  }

 private:
  // Bytes [from, from + n) of the current row's RGB samples, from its RGBA texels.
  void packPiece(std::size_t from, std::size_t n, std::uint8_t* out) const {
    const std::uint8_t* texel = samples_ + from / 3 * 4;
    std::size_t c = from % 3;
    for (; n > 0 && c != 0; --n) {  // the end of a texel the last piece began
      *out++ = texel[c];
      if (++c == 3) {
        c = 0;
        texel += 4;
      }
    }
    const std::size_t whole = n / 3;
    packRgbOfRgba(texel, whole, out);
    out += whole * 3;
    texel += whole * 4;
    for (c = 0; c < n - whole * 3; ++c) *out++ = texel[c];  // the start of a texel the next piece ends
  }

  const std::uint8_t* samples_;  // the current row's
  bool packing_;
  std::size_t sourceStride_;  // bytes of a row of `samples_`
  std::size_t stride_;        // bytes of a row's samples in the PNG
  std::size_t inRow_ = 0;     // bytes of the current row's filter byte and samples taken
};

// The PNG's shape: RgbOfRgba's RGB (the samples pointer then is not the PNG's rows).
ImageView<std::uint8_t> pngShape(ImageView<std::uint8_t> image, FileChannels channels) {
  if (channels == FileChannels::RgbOfRgba) image.channels = 3;
  return image;
}

// How much of the rows is packed or copied before its checksums are taken: small enough that the
// piece is still in the first-level cache (48 KiB on Ice Lake) with the texels it came from.
constexpr std::size_t kPiece = 8192;

}  // namespace

bool fitsStoredPng(ImageView<std::uint8_t> image, FileChannels channels) {
  if (channels == FileChannels::RgbOfRgba && image.channels != 4) return false;
  image = pngShape(image, channels);
  constexpr int kLibpngMaxSide = 1'000'000;      // PNG_USER_WIDTH_MAX, PNG_USER_HEIGHT_MAX (pnglibconf.h)
  constexpr std::size_t kMaxChunk = 0x7fffffff;  // PNG_UINT_31_MAX
  if (image.width <= 0 || image.height <= 0 || image.channels < 1 || image.channels > 4) return false;
  if (image.width > kLibpngMaxSide || image.height > kLibpngMaxSide) return false;
  const std::size_t rows = dataSize(image);
  return rows + rows / 4096 + 64 <= kMaxChunk;  // png_encoder.cpp's compression buffer, uncapped
}

std::size_t storedPngSize(ImageView<std::uint8_t> image, FileChannels channels) {
  image = pngShape(image, channels);
  return kSignature.size() + (kChunkFraming + kIhdrData) + (kChunkFraming + kSrgbData) +
         (kChunkFraming + idatSize(image)) + kChunkFraming;
}

void writeStoredPng(ImageView<std::uint8_t> source, std::uint8_t* out, FileChannels channels) {
  const ImageView<std::uint8_t> image = pngShape(source, channels);
  std::uint8_t* p = std::copy(kSignature.begin(), kSignature.end(), out);

  std::uint8_t* type = p + 4;
  p = beginChunk(p, kIhdrData, "IHDR");
  p = putU32(p, static_cast<std::uint32_t>(image.width));
  p = putU32(p, static_cast<std::uint32_t>(image.height));
  *p++ = 8;  // bit depth
  *p++ = kColourType[static_cast<std::size_t>(image.channels)];
  *p++ = 0;  // compression: deflate
  *p++ = 0;  // filter method: adaptive (every row None here)
  *p++ = 0;  // no interlace
  p = endChunk(type, p);

  type = p + 4;
  p = beginChunk(p, kSrgbData, "sRGB");
  *p++ = 0;  // perceptual
  p = endChunk(type, p);

  // The IDAT chunk's CRC-32 is taken piece by piece with the Adler-32, `checked` being how far.
  type = p + 4;
  p = beginChunk(p, idatSize(image), "IDAT");
  const auto header = zlibHeader(dataSize(image));
  p = std::copy(header.begin(), header.end(), p);
  BlockLengths lengths(rowBytes(image), static_cast<std::size_t>(image.height));
  RowStream rows(source, channels);
  std::uint32_t adler = 1;  // RFC 1950, 8.2: Adler-32 starts at 1
  std::uint32_t crc = 0;
  const std::uint8_t* checked = type;
  for (bool last = false; !last;) {
    const std::size_t length = lengths.next(last);
    *p++ = last ? 1 : 0;  // BFINAL, BTYPE 00 (stored)
    *p++ = static_cast<std::uint8_t>(length);
    *p++ = static_cast<std::uint8_t>(length >> 8);
    *p++ = static_cast<std::uint8_t>(~length);
    *p++ = static_cast<std::uint8_t>(~length >> 8);
    for (std::size_t left = length; left > 0;) {
      const std::size_t n = std::min(left, kPiece);
      std::uint8_t* data = p;
      p = rows.take(p, n);
      adler = libdeflate_adler32(adler, data, n);
      crc = libdeflate_crc32(crc, checked, static_cast<std::size_t>(p - checked));
      checked = p;
      left -= n;
    }
  }
  p = putU32(p, adler);
  p = putU32(p, libdeflate_crc32(crc, checked, static_cast<std::size_t>(p - checked)));

  type = p + 4;
  p = beginChunk(p, 0, "IEND");
  endChunk(type, p);
}

}  // namespace vbim::imageio
