#include "imageio/png_encoder.hpp"

#include <fcntl.h>
#include <png.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <csetjmp>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>
#include <system_error>
#include <vector>

#include "imageio/error.hpp"
#include "imageio/replace_file.hpp"
#include "imageio/rgb_pack.hpp"
#include "imageio/stored_png.hpp"
#include "runtime/error.hpp"

namespace vbim::imageio {

namespace fs = std::filesystem;

namespace {

// PNG specification (ISO/IEC 15948), 11.2.2: colour type by channel count.
constexpr std::array<int, 5> kColourType = {0, PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                            PNG_COLOR_TYPE_RGB_ALPHA};

// The blocks libpng and zlib allocate for one picture (the write struct, the deflate state, the
// compression buffer, the row buffers), kept by each thread for the next picture of the same size
// instead of going back to malloc (blocks of 64 KiB to 1 MiB, which glibc maps or trims as fresh
// pages): 12-15 % less CPU at level 0 (0.46-0.48 against 0.53-0.55 ms a lightmap + sky pair of
// the demo, written to tmpfs, best of five, 2026-12-03).
// Plain data only: its functions run inside libpng, between setjmp and a possible longjmp.
class BlockPool {
 public:
  BlockPool() = default;
  BlockPool(const BlockPool&) = delete;
  BlockPool& operator=(const BlockPool&) = delete;
  ~BlockPool() {
    for (std::size_t i = 0; i < count_; ++i) {
      std::free(static_cast<std::byte*>(blocks_[i].memory) - sizeof(std::max_align_t));
    }
  }
  void* allocate(std::size_t size) {
    for (std::size_t i = 0; i < count_; ++i) {
      if (blocks_[i].size == size) {
        void* memory = blocks_[i].memory;
        std::copy(blocks_.begin() + static_cast<std::ptrdiff_t>(i + 1),
                  blocks_.begin() + static_cast<std::ptrdiff_t>(count_),
                  blocks_.begin() + static_cast<std::ptrdiff_t>(i));
        --count_;
        return memory;
      }
    }
    void* memory = std::malloc(size + sizeof(std::max_align_t));
    if (memory == nullptr) return nullptr;
    std::memcpy(memory, &size, sizeof size);  // the size, for release()
    return static_cast<std::byte*>(memory) + sizeof(std::max_align_t);
  }
  void release(void* block) {
    if (block == nullptr) return;
    void* memory = static_cast<std::byte*>(block) - sizeof(std::max_align_t);
    std::size_t size = 0;
    std::memcpy(&size, memory, sizeof size);
    if (count_ == blocks_.size()) {  // full: the oldest goes (blocks of a picture size no longer written)
      std::free(static_cast<std::byte*>(blocks_[0].memory) - sizeof(std::max_align_t));
      std::copy(blocks_.begin() + 1, blocks_.end(), blocks_.begin());
      --count_;
    }
    blocks_[count_++] = {block, size};
  }

 private:
  struct Block {
    void* memory;  // what allocate() returned
    std::size_t size;
  };
  // One picture takes about ten blocks; two picture sizes (lightmap and sky) alternate.
  std::array<Block, 32> blocks_{};
  std::size_t count_ = 0;
};

// What one encoding hands libpng: plain data only (see BlockPool), the PNG's bytes go to `out`.
struct Job {
  ImageView<std::uint8_t> image;
  int level = 0;
  std::vector<std::uint8_t>* out = nullptr;
  std::size_t size = 0;                // bytes of *out written
  std::array<char, 200> message = {};  // libpng's error, or ours from writeBytes
};

png_voidp poolAllocate(png_structp png, png_alloc_size_t size) {
  return static_cast<BlockPool*>(png_get_mem_ptr(png))->allocate(size);
}

void poolRelease(png_structp png, png_voidp block) {
  static_cast<BlockPool*>(png_get_mem_ptr(png))->release(block);
}

[[noreturn]] void onError(png_structp png, png_const_charp message) {
  Job& job = *static_cast<Job*>(png_get_error_ptr(png));
  if (job.message[0] == '\0') std::snprintf(job.message.data(), job.message.size(), "%s", message);
  // libpng's documented way out of an error (libpng-manual, "Setting up error handling"): back to
  // the setjmp in encodeWithLibpng, over frames that hold no object with a destructor.
  std::longjmp(png_jmpbuf(png), 1);
}

void onWarning(png_structp /*png*/, png_const_charp /*message*/) {}  // none expected; not for stderr

void writeBytes(png_structp png, png_bytep data, std::size_t length) {
  Job& job = *static_cast<Job*>(png_get_io_ptr(png));
  bool grown = true;
  if (job.out->size() < job.size + length) {
    try {
      job.out->resize(std::max(job.size + length, job.out->size() * 2));
    } catch (const std::bad_alloc&) {
      grown = false;
    }
  }
  if (!grown) png_error(png, "out of memory for the PNG's bytes");  // outside the catch: it longjmps
  std::memcpy(job.out->data() + job.size, data, length);
  job.size += length;
}

void flushBytes(png_structp /*png*/) {}

// Everything libpng does for one picture: the calls that may longjmp back to encodeWithLibpng.
void writeAll(png_structp png, png_infop info, Job& job) {
  const ImageView<std::uint8_t>& image = job.image;
  const std::size_t stride = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.channels);
  png_set_write_fn(png, &job, writeBytes, flushBytes);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
               kColourType[static_cast<std::size_t>(image.channels)], PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);  // what libpng's simplified API writes for 8 bits
  // Level 0 stores the rows: filtering would only cost time. Otherwise Up: the smallest files of the
  // lightmaps at levels 1 to 3 (Sub, Paeth and libpng's adaptive choice of all five were 2-6 %
  // larger or slower; bench/player/image_share.sh's frames), and zlib's default strategy, not the
  // Z_FILTERED libpng picks for filtered rows: the same bytes at 1 to 3, 5 % smaller at 6.
  png_set_filter(png, PNG_FILTER_TYPE_BASE, job.level == 0 ? PNG_FILTER_NONE : PNG_FILTER_UP);
  png_set_compression_level(png, job.level);
  png_set_compression_strategy(png, Z_DEFAULT_STRATEGY);
  // One IDAT chunk for the whole picture, as the simplified API wrote: the compression buffer holds
  // every row stored (plus deflate's 5 bytes a block), capped where a chunk's length would not fit.
  const std::size_t rows = static_cast<std::size_t>(image.height) * (stride + 1);
  png_set_compression_buffer_size(png, std::min<std::size_t>(rows + rows / 4096 + 64, PNG_UINT_31_MAX));
  png_write_info(png, info);
  for (std::size_t y = 0; y < static_cast<std::size_t>(image.height); ++y) {
    png_write_row(png, image.samples + y * stride);
  }
  png_write_end(png, nullptr);
}

// False with job.message set when libpng (or writeBytes) reported an error.
bool encodeWithLibpng(Job& job, BlockPool& pool) {
  png_structp png =
      png_create_write_struct_2(PNG_LIBPNG_VER_STRING, &job, onError, onWarning, &pool, poolAllocate, poolRelease);
  if (png == nullptr) {
    std::snprintf(job.message.data(), job.message.size(), "cannot start libpng (out of memory)");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    std::snprintf(job.message.data(), job.message.size(), "cannot start libpng (out of memory)");
    return false;
  }
  if (setjmp(png_jmpbuf(png)) != 0) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  writeAll(png, info, job);
  png_destroy_write_struct(&png, &info);
  return true;
}

void checkShape(ImageView<std::uint8_t> image, int level, const fs::path& name, FileChannels channels) {
  if (image.width <= 0 || image.height <= 0) {
    throw ImageIoError(name.string() + ": cannot write a " + std::to_string(image.width) + "x" +
                       std::to_string(image.height) + " image (expected a positive size)");
  }
  if (image.channels < 1 || image.channels > 4) {
    throw ImageIoError(name.string() + ": cannot write " + std::to_string(image.channels) +
                       " channel(s) as a PNG (expected 1 to 4)");
  }
  if (channels == FileChannels::RgbOfRgba && image.channels != 4) {
    throw ImageIoError(name.string() + ": cannot write the RGB of " + std::to_string(image.channels) +
                       " channel(s) (expected RGBA, 4)");
  }
  if (level < 0 || level > kMaxPngLevel) {
    throw ImageIoError(name.string() + ": PNG compression level " + std::to_string(level) + " (expected 0 to " +
                       std::to_string(kMaxPngLevel) + ")");
  }
}

void encodeWithLibpngInto(ImageView<std::uint8_t> image, int level, const fs::path& name,
                          std::vector<std::uint8_t>& out, std::size_t& size, BlockPool& pool) {
  Job job;
  job.image = image;
  job.level = level;
  job.out = &out;
  if (!encodeWithLibpng(job, pool)) {
    throw ImageIoError(name.string() + ": cannot encode the PNG: " + std::string(job.message.data()));
  }
  size = job.size;
}

// Level 0 without libpng where stored_png.hpp can (same bytes, stored_png.hpp says why). Otherwise
// libpng, given RgbOfRgba's samples packed into `rgb` first.
void encodeInto(ImageView<std::uint8_t> image, int level, const fs::path& name, FileChannels channels,
                std::vector<std::uint8_t>& out, std::size_t& size, BlockPool& pool, std::vector<std::uint8_t>& rgb) {
  checkShape(image, level, name, channels);
  if (level == 0 && fitsStoredPng(image, channels)) {
    size = storedPngSize(image, channels);
    if (out.size() < size) out.resize(size);
    writeStoredPng(image, out.data(), channels);
    return;
  }
  if (channels == FileChannels::RgbOfRgba) {
    const std::size_t texels = image.sampleCount() / 4;
    rgb.resize(texels * 3);
    packRgbOfRgba(image.samples, texels, rgb.data());
    image = {image.width, image.height, 3, rgb.data()};
  }
  encodeWithLibpngInto(image, level, name, out, size, pool);
}

// The bytes and blocks of one thread's pictures, kept between them (BlockPool says why).
struct Scratch {
  BlockPool pool;
  std::vector<std::uint8_t> png;
  std::vector<std::uint8_t> rgb;  // RgbOfRgba's samples for libpng
};

thread_local Scratch tScratch;

std::string lastError() {
  return std::error_code(errno, std::generic_category()).message();
}

}  // namespace

void checkPngLevelOption(int level) {
  if (level < 0 || level > kMaxPngLevel) {
    throw Error("--png-level " + std::to_string(level) + ": expected 0 (stored) to " + std::to_string(kMaxPngLevel));
  }
}

std::vector<std::uint8_t> encodePng(ImageView<std::uint8_t> image, int level, const fs::path& name,
                                    FileChannels channels) {
  BlockPool pool;
  std::vector<std::uint8_t> png;
  std::vector<std::uint8_t> rgb;
  std::size_t size = 0;
  encodeInto(image, level, name, channels, png, size, pool, rgb);
  png.resize(size);
  return png;
}

std::vector<std::uint8_t> encodePngWithLibpng(ImageView<std::uint8_t> image, int level, const fs::path& name) {
  BlockPool pool;
  std::vector<std::uint8_t> png;
  std::size_t size = 0;
  checkShape(image, level, name, FileChannels::AsGiven);
  encodeWithLibpngInto(image, level, name, png, size, pool);
  png.resize(size);
  return png;
}

void writePngAtLevel(const fs::path& path, ImageView<std::uint8_t> image, int level, FileChannels channels,
                     FilePlacement placement) {
  Scratch& s = tScratch;
  std::size_t size = 0;
  encodeInto(image, level, path, channels, s.png, size, s.pool, s.rgb);
  // One write() of the whole file (stdio wrote its last bytes by a second one at fclose).
  writePlaced(path, placement, [&](const fs::path& file) {
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) throw ImageIoError(path.string() + ": cannot create the file: " + lastError());
    std::size_t done = 0;
    std::string writeError;
    while (done < size) {
      const ssize_t n = ::write(fd, s.png.data() + done, size - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        writeError = n < 0 ? lastError() : "nothing written";
        break;
      }
      done += static_cast<std::size_t>(n);
    }
    const bool closed = ::close(fd) == 0;
    if (writeError.empty() && !closed) writeError = lastError();
    if (!writeError.empty()) throw ImageIoError(path.string() + ": cannot write the PNG: " + writeError);
  });
}

}  // namespace vbim::imageio
