// Shared by the stream tests: a small synthetic stream authored in memory, and a temporary directory.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "runtime/image.hpp"
#include "streams/authoring/stream_writer.hpp"

namespace vbim::streams::test {

struct SmallStream {
  std::vector<std::uint8_t> bytes;
  Descriptor descriptor;
  // The 8-bit frames that went in, [variant * frames + frame].
  std::vector<Rgba8Image> lightmaps, skies;
};

// 128x128 lightmap + 64x32 sky, `frames` frames per variant, variants "clear" and (if two) "overcast",
// default quality. Cached per (frames, variants).
const SmallStream& smallStream(std::uint32_t frames = 8, int variants = 2);

class TempDir {
 public:
  TempDir();
  ~TempDir();
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

void writeFile(const std::filesystem::path& p, const std::vector<std::uint8_t>& bytes);
std::vector<std::uint8_t> readFile(const std::filesystem::path& p);

}  // namespace vbim::streams::test
