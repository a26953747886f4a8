// The decoded frames a port dumps for `vbim replay --frames DIR`, so the GS side can be checked
// apart from the port's decoder (docs/porting.md, "Replay with the port's frames"):
//
//   DIR/lightmap/frame_NNNNN.rgba   DIR/sky/frame_NNNNN.rgba
//
// NNNNN (5 digits or more) is the picture's number in its stream, from 0: variant x frames per
// variant + the stream frame, the number `vbim decode --format rgba` gives it. Each file is the
// picture's W x H pixels as RGB32, the IPU's output with OFM = 0 put in raster order: R, G, B, A
// bytes per pixel, rows top to bottom, alpha as the IPU writes it (0x80 = 1.0); W x H x 4 bytes, no
// header. Only the pictures the arrival log names are read.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "runtime/image.hpp"

namespace vbim::player {

class PortFrames {
 public:
  explicit PortFrames(std::filesystem::path dir) : dir_(std::move(dir)) {}

  const std::filesystem::path& dir() const { return dir_; }
  std::filesystem::path path(bool sky, std::int64_t picture) const;

  // Throws ConfigError naming the file, `what` it is (which arrival needs it) and what was expected
  // when it is missing or not width x height x 4 bytes.
  void check(bool sky, std::int64_t picture, int width, int height, const std::string& what) const;
  // The picture; throws ConfigError as check() does, or when the file cannot be read.
  Rgba8Image read(bool sky, std::int64_t picture, int width, int height) const;

 private:
  std::filesystem::path dir_;
};

}  // namespace vbim::player
