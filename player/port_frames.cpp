#include "player/port_frames.hpp"

#include <cstdio>
#include <fstream>
#include <system_error>

#include "runtime/error.hpp"

namespace vbim::player {

namespace {

std::string expected(int width, int height) {
  return "expected " + std::to_string(width) + "x" + std::to_string(height) + " RGB32, " +
         std::to_string(static_cast<std::int64_t>(width) * height * 4) +
         " bytes (R, G, B, A per pixel, rows top to bottom: docs/porting.md, \"Replay with the port's frames\")";
}

}  // namespace

std::filesystem::path PortFrames::path(bool sky, std::int64_t picture) const {
  char name[40];
  std::snprintf(name, sizeof name, "frame_%05lld.rgba", static_cast<long long>(picture));
  return dir_ / (sky ? "sky" : "lightmap") / name;
}

void PortFrames::check(bool sky, std::int64_t picture, int width, int height, const std::string& what) const {
  const std::filesystem::path p = path(sky, picture);
  std::error_code ec;
  const bool regular = std::filesystem::is_regular_file(p, ec);
  if (!regular) {
    throw ConfigError(p.string() + ": missing: " + what + "; " + expected(width, height));
  }
  const std::uintmax_t size = std::filesystem::file_size(p, ec);
  const auto want = static_cast<std::uintmax_t>(width) * static_cast<std::uintmax_t>(height) * 4;
  if (ec || size != want) {
    throw ConfigError(p.string() + ": " + (ec ? "cannot read its size" : std::to_string(size) + " bytes") + ": " +
                      what + "; " + expected(width, height));
  }
}

Rgba8Image PortFrames::read(bool sky, std::int64_t picture, int width, int height) const {
  const std::string what = std::string(sky ? "the sky" : "the lightmap") + " picture " + std::to_string(picture);
  check(sky, picture, width, height, what);
  Rgba8Image out(width, height);
  const std::filesystem::path p = path(sky, picture);
  std::ifstream f(p, std::ios::binary);
  f.read(reinterpret_cast<char*>(out.pixels.data()), static_cast<std::streamsize>(out.pixels.size()));
  if (!f || f.gcount() != static_cast<std::streamsize>(out.pixels.size())) {
    throw ConfigError(p.string() + ": cannot read " + what + "; " + expected(width, height));
  }
  return out;
}

}  // namespace vbim::player
