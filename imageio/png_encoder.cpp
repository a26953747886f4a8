#include "imageio/png_encoder.hpp"

#include <libdeflate.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

#include "imageio/error.hpp"
#include "imageio/replace_file.hpp"

namespace vbim::imageio {

namespace fs = std::filesystem;

namespace {

// PNG specification (ISO/IEC 15948), 11.2.2: colour type by channel count.
constexpr std::array<std::uint8_t, 5> kColourType = {0, 0, 4, 2, 6};
constexpr std::uint8_t kFilterNone = 0;
constexpr std::uint8_t kFilterUp = 2;
constexpr std::array<std::uint8_t, 8> kSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
// A chunk's length is a 31-bit number (PNG 5.3); images whose IDAT would not fit are refused.
constexpr std::size_t kMaxChunk = 0x7fffffff;
// Signature, IHDR (12 + 13), sRGB (12 + 1), IDAT's length, type and CRC, IEND.
constexpr std::size_t kContainerBytes = 8 + 25 + 13 + 12 + 12;

// The buffers of one encoding, kept by each thread between pictures: buffers this size (256 KiB
// and up) come from fresh pages each time otherwise (glibc maps them, or trims them off the heap
// when freed), and faulting those pages in cost more than the encoding itself (0.66 against
// 0.15 ms for a 256x256 RGBA picture at level 0).
class Scratch {
 public:
  Scratch() = default;
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
  ~Scratch() {
    if (compressor_ != nullptr) libdeflate_free_compressor(compressor_);
  }
  libdeflate_compressor* compressor(int level, const fs::path& name) {
    if (compressor_ == nullptr || level_ != level) {
      if (compressor_ != nullptr) libdeflate_free_compressor(compressor_);
      compressor_ = libdeflate_alloc_compressor(level);
      level_ = level;
      if (compressor_ == nullptr)
        throw ImageIoError(name.string() + ": cannot start the PNG compressor (out of memory)");
    }
    return compressor_;
  }
  std::vector<std::uint8_t> rows;  // deflate's input: the filtered rows
  std::vector<std::uint8_t> png;   // the file; its first `size` bytes
  std::size_t size = 0;

 private:
  libdeflate_compressor* compressor_ = nullptr;
  int level_ = -1;
};

thread_local Scratch tScratch;

void grow(std::vector<std::uint8_t>& v, std::size_t n) {
  if (v.size() < n) v.resize(n);
}

std::uint8_t* put32(std::uint8_t* p, std::size_t v) {
  p[0] = static_cast<std::uint8_t>(v >> 24);
  p[1] = static_cast<std::uint8_t>(v >> 16);
  p[2] = static_cast<std::uint8_t>(v >> 8);
  p[3] = static_cast<std::uint8_t>(v);
  return p + 4;
}

// A chunk at `p` whose `length` data bytes are already in place 8 bytes on: its length, type and
// CRC-32 of type and data (PNG 5.3). Returns the end of the chunk.
std::uint8_t* closeChunk(std::uint8_t* p, const char* type, std::size_t length) {
  put32(p, length);
  std::memcpy(p + 4, type, 4);
  return put32(p + 8 + length, libdeflate_crc32(0, p + 4, length + 4));
}

// The rows as deflate's input: a filter byte, then the row (None) or its difference from the row
// above (Up; the row above the first is zeros, PNG 9.2).
void filterRows(ImageView<std::uint8_t> image, bool up, std::vector<std::uint8_t>& out) {
  const std::size_t stride = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.channels);
  const std::size_t rows = static_cast<std::size_t>(image.height);
  grow(out, rows * (stride + 1));
  for (std::size_t y = 0; y < rows; ++y) {
    std::uint8_t* o = out.data() + y * (stride + 1);
    const std::uint8_t* row = image.samples + y * stride;
    o[0] = up ? kFilterUp : kFilterNone;
    if (!up || y == 0) {
      std::memcpy(o + 1, row, stride);
    } else {
      const std::uint8_t* above = row - stride;
      for (std::size_t i = 0; i < stride; ++i) o[1 + i] = static_cast<std::uint8_t>(row[i] - above[i]);
    }
  }
}

void encodeInto(ImageView<std::uint8_t> image, int level, const fs::path& name, Scratch& s) {
  if (image.width <= 0 || image.height <= 0) {
    throw ImageIoError(name.string() + ": cannot write a " + std::to_string(image.width) + "x" +
                       std::to_string(image.height) + " image (expected a positive size)");
  }
  if (image.channels < 1 || image.channels > 4) {
    throw ImageIoError(name.string() + ": cannot write " + std::to_string(image.channels) +
                       " channel(s) as a PNG (expected 1 to 4)");
  }
  if (level < 0 || level > kMaxPngLevel) {
    throw ImageIoError(name.string() + ": PNG compression level " + std::to_string(level) + " (expected 0 to " +
                       std::to_string(kMaxPngLevel) + ")");
  }
  const std::size_t rowBytes = static_cast<std::size_t>(image.height) *
                               (static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.channels) + 1);
  libdeflate_compressor* compressor = s.compressor(level, name);
  const std::size_t bound = libdeflate_zlib_compress_bound(compressor, rowBytes);
  if (bound > kMaxChunk) {
    throw ImageIoError(name.string() + ": " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                       " is too large for one PNG data chunk (expected at most 2 GiB of samples)");
  }
  filterRows(image, level > 0, s.rows);
  grow(s.png, kContainerBytes + bound);

  std::uint8_t* p = s.png.data();
  std::memcpy(p, kSignature.data(), kSignature.size());
  p += kSignature.size();
  std::uint8_t* data =
      put32(put32(p + 8, static_cast<std::size_t>(image.width)), static_cast<std::size_t>(image.height));
  const std::array<std::uint8_t, 5> ihdrRest = {8, kColourType[static_cast<std::size_t>(image.channels)], 0, 0, 0};
  std::memcpy(data, ihdrRest.data(), ihdrRest.size());
  p = closeChunk(p, "IHDR", 13);
  p[8] = 0;  // sRGB's rendering intent: perceptual, as libpng's simplified API writes it
  p = closeChunk(p, "sRGB", 1);
  const std::size_t packed = libdeflate_zlib_compress(compressor, s.rows.data(), rowBytes, p + 8, bound);
  if (packed == 0) throw ImageIoError(name.string() + ": the PNG compressor ran out of room (expected none)");
  p = closeChunk(p, "IDAT", packed);
  p = closeChunk(p, "IEND", 0);
  s.size = static_cast<std::size_t>(p - s.png.data());
}

std::string lastError() {
  return std::error_code(errno, std::generic_category()).message();
}

}  // namespace

std::vector<std::uint8_t> encodePng(ImageView<std::uint8_t> image, int level, const fs::path& name) {
  Scratch s;
  encodeInto(image, level, name, s);
  s.png.resize(s.size);
  return std::move(s.png);
}

void writePngAtLevel(const fs::path& path, ImageView<std::uint8_t> image, int level) {
  Scratch& s = tScratch;
  encodeInto(image, level, path, s);
  writeThenRename(path, [&](const fs::path& temporary) {
    std::FILE* f = std::fopen(temporary.c_str(), "wb");
    if (f == nullptr) throw ImageIoError(path.string() + ": cannot create the file: " + lastError());
    const bool written = std::fwrite(s.png.data(), 1, s.size, f) == s.size;
    const std::string writeError = written ? "" : lastError();
    const bool closed = std::fclose(f) == 0;
    if (!written || !closed) {
      throw ImageIoError(path.string() + ": cannot write the PNG: " + (written ? lastError() : writeError));
    }
  });
}

}  // namespace vbim::imageio
