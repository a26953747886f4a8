// libFuzzer target: every picture loader (imageio's reader and lighting's heightfield, colour and
// density maps) on any bytes. The first byte picks the file name's extension, which decides the
// OpenImageIO plug-in tried first; the rest is the file. A loader may refuse the file with its own
// error (vbim::Error); any other exception, crash or sanitizer report is a finding.
#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "imageio/image_reader.hpp"
#include "lighting/image_files.hpp"
#include "runtime/error.hpp"

namespace {

constexpr std::array<const char*, 6> kExtensions{".png", ".exr", ".tif", ".hdr", ".ppm", ".jpg"};
constexpr std::uint64_t kLargeSamples = std::uint64_t{1} << 22;

// The loaders read files by name: one scratch file per process, in memory where the system has it.
std::filesystem::path scratchFile(const char* extension) {
  const std::filesystem::path dir = std::filesystem::is_directory("/dev/shm") ? std::filesystem::path("/dev/shm")
                                                                              : std::filesystem::temp_directory_path();
  return dir / ("vbim-image-fuzz-" + std::to_string(::getpid()) + extension);
}

template <typename Load>
void tryLoad(Load load) {
  try {
    load();
  } catch (const vbim::Error&) {
    // a clear refusal is the expected outcome for most inputs
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // Only the plug-ins built into OpenImageIO: no search for format plug-ins on disk per file.
  OIIO::attribute("plugin_searchpath", "");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::filesystem::path path = scratchFile(kExtensions[data[0] % kExtensions.size()]);
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  const std::string name = path.string();
  // Headers up to the loaders' limit are legal; reading a multi-megapixel claim costs a large zeroed
  // allocation per input, which would slow the search for decoder bugs a hundredfold. Such inputs
  // stop after the header (the size check itself is in the constructor, and unit-tested).
  bool large = false;
  tryLoad([&] {
    const vbim::imageio::ImageReader in(path, "image");
    const vbim::imageio::ImageInfo& info = in.info();
    large = static_cast<std::uint64_t>(info.width) * static_cast<std::uint64_t>(info.height) *
                static_cast<std::uint64_t>(info.channels) >
            kLargeSamples;
  });
  if (large) {
    std::filesystem::remove(path);
    return 0;
  }
  tryLoad([&] { (void)vbim::imageio::readRgba8(path); });
  tryLoad([&] { (void)vbim::imageio::readFloatRgb(path); });
  tryLoad([&] { (void)vbim::lighting::readHeightfield(name, 10.0, 1000.0); });
  tryLoad([&] { (void)vbim::lighting::readColourMap(name); });
  tryLoad([&] { (void)vbim::lighting::readDensityMap(name); });
  std::filesystem::remove(path);
  return 0;
}
