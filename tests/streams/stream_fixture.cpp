#include "tests/streams/stream_fixture.hpp"

#include <unistd.h>

#include <fstream>
#include <map>
#include <stdexcept>

#include "streams/authoring/synthetic_day.hpp"

namespace vbim::streams::test {

const SmallStream& smallStream(std::uint32_t frames, int variants) {
  static std::map<std::pair<std::uint32_t, int>, SmallStream> cache;
  auto [it, fresh] = cache.try_emplace({frames, variants});
  if (!fresh) return it->second;
  SmallStream& s = it->second;
  AuthorSettings settings;
  settings.gameFps = {2, 1};
  settings.loopFrame = 1;
  StreamWriter w(settings);
  SyntheticDay day;
  day.width = 128;
  day.height = 128;
  day.skyWidth = 64;
  day.skyHeight = 32;
  day.frames = frames;
  const char* names[] = {"clear", "overcast"};
  for (int v = 0; v < variants; ++v) {
    day.weather = names[v];
    w.beginVariant(names[v]);
    for (std::uint32_t f = 0; f < frames; ++f) {
      s.lightmaps.push_back(toneMap(syntheticLightmap(day, f), ToneMapping{}));
      s.skies.push_back(toneMap(syntheticSky(day, f), ToneMapping{}));
      w.addFrame(s.lightmaps.back(), &s.skies.back());
    }
  }
  s.bytes = w.finish();
  s.descriptor = w.descriptor();
  return s;
}

TempDir::TempDir() {
  path_ = std::filesystem::temp_directory_path() / ("vbim-streams-test-" + std::to_string(::getpid()) + "-" +
                                                    std::to_string(reinterpret_cast<std::uintptr_t>(this)));
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

void writeFile(const std::filesystem::path& p, const std::vector<std::uint8_t>& bytes) {
  std::ofstream out(p, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + p.string());
}

std::vector<std::uint8_t> readFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + p.string());
  return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), {});
}

}  // namespace vbim::streams::test
