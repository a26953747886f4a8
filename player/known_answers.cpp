#include "player/known_answers.hpp"

#include <fnmatch.h>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

#include "gs/blend.hpp"
#include "player/frame_hash.hpp"

namespace vbim::player {

namespace {

struct Entry {
  std::string key;
  std::string value;
};

// Parses KEY VALUE lines; a line without a space is returned with an empty value and a key of
// "line N: TEXT" so the comparison names it.
std::vector<Entry> parseEntries(const std::string& text) {
  std::vector<Entry> out;
  std::istringstream in(text);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const auto space = line.find(' ');
    if (space == std::string::npos || space == 0) {
      out.push_back(Entry{"line " + std::to_string(n) + ": '" + line + "'", "(not KEY VALUE)"});
    } else {
      out.push_back(Entry{line.substr(0, space), line.substr(space + 1)});
    }
  }
  return out;
}

const char* clampName(gs::ColClamp c) {
  return c == gs::ColClamp::Clamp ? "clamp" : "wrap";
}

}  // namespace

std::uint64_t hashAsImage(std::span<const std::uint8_t> bytes, int width, int height) {
  Rgba8Image img(width, height);
  img.pixels.assign(bytes.begin(), bytes.end());
  return frameHash(img, nullptr);
}

Rgba8Image patternImage(int width, int height, int seed) {
  Rgba8Image img(width, height);
  for (std::size_t i = 0; i < img.pixels.size(); ++i) {
    img.pixels[i] = static_cast<std::uint8_t>((i * 131 + static_cast<std::size_t>(seed) * 7 + (i >> 8)) & 0xFF);
  }
  return img;
}

VectorFile frameHashVectors() {
  std::string t =
      "# vbim known answers: the frame hash of hashes.txt (player/frame_hash.hpp, docs/player.md)\n"
      "# KEY frame_hash/lightmap=WxH:SEED[,sky=WxH:SEED]  VALUE the 16-hex-digit hash\n"
      "# Image bytes: byte i (R G B A order, rows top to bottom) = (i * 131 + SEED * 7 + (i >> 8)) & 0xFF\n";
  struct Case {
    int w, h, seed, sw, sh, sseed;
  };
  // Sizes whose byte count is and is not a multiple of 8 (the last word is zero-padded), the sample
  // streams' 256x256, and lightmaps with a sky.
  const Case cases[] = {{1, 1, 0, 0, 0, 0},      {1, 1, 1, 0, 0, 0},     {2, 1, 0, 0, 0, 0},
                        {3, 1, 0, 0, 0, 0},      {5, 3, 2, 0, 0, 0},     {16, 16, 3, 0, 0, 0},
                        {64, 32, 4, 16, 8, 5},   {256, 256, 0, 0, 0, 0}, {256, 256, 6, 256, 256, 7},
                        {256, 128, 8, 64, 64, 9}};
  for (const Case& c : cases) {
    const Rgba8Image lm = patternImage(c.w, c.h, c.seed);
    std::string key =
        "frame_hash/lightmap=" + std::to_string(c.w) + "x" + std::to_string(c.h) + ":" + std::to_string(c.seed);
    std::uint64_t h = 0;
    if (c.sw > 0) {
      const Rgba8Image sky = patternImage(c.sw, c.sh, c.sseed);
      key += ",sky=" + std::to_string(c.sw) + "x" + std::to_string(c.sh) + ":" + std::to_string(c.sseed);
      h = frameHash(lm, &sky);
    } else {
      h = frameHash(lm, nullptr);
    }
    t += key + " " + hashHex(h) + "\n";
  }
  return VectorFile{"frame_hash.txt", t};
}

VectorFile blendVectors() {
  std::string t =
      "# vbim known answers: the GS blend of the in-place lightmap update (gs/blend.hpp)\n"
      "# ALPHA_1 = (A Cs, B Cd, C FIX, D Cd): Cv = (((Cs - Cd) * FIX) >> 7) + Cd, then COLCLAMP\n"
      "# KEY blend/cs=CS,cd=CD,fix=FIX,colclamp=clamp|wrap  VALUE Cv (one colour channel)\n"
      "# KEY blend_steps/cs=CS,cd=CD,fix=FIX,colclamp=clamp  VALUE Cd after 1, 2, ... vsyncs of blending\n"
      "#   toward the same Cs, until it stops changing: the list ends with the first value equal to the one\n"
      "#   before it (CD for the first), that value included, or after 24 values\n";
  const int channel[] = {0, 1, 100, 127, 128, 200, 255};
  const int fixes[] = {0, 1, 0x20, 0x40, 0x80, 0xC0, 0xFF};
  for (gs::ColClamp c : {gs::ColClamp::Clamp, gs::ColClamp::Wrap}) {
    for (int fix : fixes) {
      for (int cs : channel) {
        for (int cd : channel) {
          t += "blend/cs=" + std::to_string(cs) + ",cd=" + std::to_string(cd) + ",fix=" + std::to_string(fix) +
               ",colclamp=" + clampName(c) + " " + std::to_string(gs::blendChannel(cs, cd, fix, c)) + "\n";
        }
      }
    }
  }
  const int pairs[][2] = {{200, 0}, {0, 200}, {255, 0}, {0, 255}, {37, 36}, {36, 37}, {128, 100}};
  for (int fix : {0x10, 0x40, 0x60}) {
    for (const auto& p : pairs) {
      std::string steps;
      int cd = p[1];
      for (int k = 0; k < 24; ++k) {
        const int next = gs::blendChannel(p[0], cd, fix, gs::ColClamp::Clamp);
        steps += (k ? " " : "") + std::to_string(next);
        if (next == cd) break;
        cd = next;
      }
      t += "blend_steps/cs=" + std::to_string(p[0]) + ",cd=" + std::to_string(p[1]) + ",fix=" + std::to_string(fix) +
           ",colclamp=clamp " + steps + "\n";
    }
  }
  return VectorFile{"blend.txt", t};
}

std::vector<VectorFile> knownAnswerVectors(const std::vector<VectorStream>& streams, ipu::IdctKind idct) {
  return {frameHashVectors(),        blendVectors(),      streamReadVectors(),
          ipuVectors(streams, idct), vlcVectors(streams), idctVectors(streams, idct),
          cscVectors(streams, idct), drawVectors()};
}

std::string vectorStage(const VectorFile& f) {
  return f.name.ends_with(".txt") ? f.name.substr(0, f.name.size() - 4) : f.name;
}

bool vectorKeySelected(const std::string& key, const std::vector<std::string>& only) {
  // POSIX shell patterns; without FNM_PATHNAME a `*` also spans `/`.
  return only.empty() || std::any_of(only.begin(), only.end(),
                                     [&](const std::string& p) { return ::fnmatch(p.c_str(), key.c_str(), 0) == 0; });
}

VectorScore scoreVectors(const VectorFile& expected, const std::string* found, const std::vector<std::string>& only) {
  VectorScore score;
  score.file = expected.name;
  const std::vector<Entry> all = parseEntries(expected.text);
  std::vector<Entry> want = all;
  std::erase_if(want, [&](const Entry& e) { return !vectorKeySelected(e.key, only); });
  score.checked = want.size();
  if (found == nullptr) {
    score.found = false;
    score.missing = want.size();
    if (!want.empty()) {
      score.differences.push_back(
          VectorDifference{expected.name, want.front().key, want.front().value, "(no such file)", {}, {}, {}});
    }
    return score;
  }
  const std::vector<Entry> got = parseEntries(*found);
  std::map<std::string, std::string> byKey;
  for (const Entry& e : got) byKey.emplace(e.key, e.value);
  for (const Entry& e : want) {
    const auto it = byKey.find(e.key);
    if (it == byKey.end()) {
      ++score.missing;
      score.differences.push_back(VectorDifference{expected.name, e.key, e.value, "(missing)", {}, {}, {}});
    } else if (it->second != e.value) {
      ++score.differ;
      VectorDifference d{expected.name, e.key, e.value, it->second, {}, {}, {}};
      locateDifference(d);
      score.differences.push_back(std::move(d));
    } else {
      ++score.matched;
    }
  }
  std::set<std::string> known;
  for (const Entry& e : all) known.insert(e.key);
  for (const Entry& e : got) {
    if (known.contains(e.key) || !vectorKeySelected(e.key, only)) continue;
    ++score.extra;
    score.differences.push_back(VectorDifference{expected.name, e.key, "(no such entry)", e.value, {}, {}, {}});
  }
  return score;
}

namespace {

std::vector<std::string> splitOn(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t at = s.find(sep, start);
    out.push_back(s.substr(start, at - start));
    if (at == std::string::npos) return out;
    start = at + 1;
  }
}

bool isHex(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
  });
}

}  // namespace

void locateDifference(VectorDifference& d) {
  const std::string& a = d.expected;
  const std::string& b = d.found;
  // Long hex strings (pixels, YCbCr): the first differing byte.
  constexpr std::size_t kHashDigits = 16;
  if (a.size() > kHashDigits && a.size() % 2 == 0 && isHex(a) && isHex(b)) {
    std::size_t i = 0;
    while (i + 1 < a.size() && i + 1 < b.size() && a.compare(i, 2, b, i, 2) == 0) i += 2;
    d.place = "byte " + std::to_string(i / 2) + " of " + std::to_string(a.size() / 2);
    d.expectedElement = a.substr(i, 2);
    d.foundElement = i + 1 < b.size() ? b.substr(i, 2) : "(end)";
    return;
  }
  // Lists: comma-separated numbers, or space-separated tokens (run/level pairs).
  for (const char sep : {',', ' '}) {
    const std::vector<std::string> x = splitOn(a, sep);
    if (x.size() < 2) continue;
    const std::vector<std::string> y = splitOn(b, sep);
    std::size_t i = 0;
    while (i < x.size() && i < y.size() && x[i] == y[i]) ++i;
    d.place = "element " + std::to_string(i) + " of " + std::to_string(x.size());
    d.expectedElement = i < x.size() ? x[i] : "(end)";
    d.foundElement = i < y.size() ? y[i] : "(end)";
    return;
  }
}

std::optional<VectorDifference> compareVectors(const VectorFile& expected, const std::string* found) {
  VectorScore score = scoreVectors(expected, found);
  if (score.differences.empty()) return std::nullopt;
  return std::move(score.differences.front());
}

}  // namespace vbim::player
