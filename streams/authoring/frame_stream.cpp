#include "streams/authoring/frame_stream.hpp"

#include <cstdio>
#include <filesystem>
#include <optional>
#include <utility>

#include <nlohmann/json.hpp>

#include "imageio/error.hpp"
#include "imageio/image_reader.hpp"
#include "streams/authoring/error.hpp"
#include "streams/authoring/frame_pattern.hpp"
#include "streams/record_packs.hpp"

namespace vbim::streams {

namespace {

// One input frame file to 8-bit (tone_map.hpp); a file that cannot be read is an AuthoringError
// naming it.
Rgba8Image loadFrame(const std::filesystem::path& path, InputEncoding enc, const ToneMapping& tone) {
  imageio::FloatRgbFrame frame;
  try {
    frame = imageio::readFloatRgb(path);
  } catch (const imageio::ImageIoError& e) {
    throw AuthoringError(e.what());
  }
  FloatRgbImage rgb(frame.rgb.width, frame.rgb.height);
  rgb.rgb = std::move(frame.rgb.samples);
  return encodeFrame(rgb, frame.floatingPoint, enc, tone);
}

struct VariantFiles {
  std::string name;
  std::vector<FrameFile> lightmaps, skies;
};

// The authoring record of a stream made from image files or by the synthetic day generator: what is
// known of it (the source, the frame sizes and times, the encoder settings), in the form Technique A
// streams carry (lighting/authoring/technique_a_record.hpp) but without a terrain, which these sources
// do not have. `vbim info` shows it, `vbim play` copies it, `vbim render` notes that no terrain is
// recorded and keeps its defaults. Appended after the video, so players never read it.
std::string frameStreamRecord(const std::string& source, const AuthorSettings& s, std::uint32_t framesPerVariant,
                              std::pair<int, int> lightmap, std::optional<std::pair<int, int>> sky,
                              nlohmann::ordered_json variants) {
  nlohmann::ordered_json j;
  j["record"] = "vbim-authoring";
  j["record_version"] = 1;
  j["vbim_version"] = VBIM_VERSION_STRING;
  j["source"] = source;
  j["stream"] = {{"game_fps", {s.gameFps.num, s.gameFps.den}},
                 {"loop_frame", s.loopFrame},
                 {"frames_per_variant", framesPerVariant},
                 {"frame_period_s", static_cast<double>(s.gameFps.den) / static_cast<double>(s.gameFps.num)},
                 {"qscale", s.encoder.qscale},
                 {"bitrate", s.encoder.bitrate}};
  if (s.encoder.gop > 1) {  // intra-only records keep their bytes
    j["stream"]["gop"] = s.encoder.gop;
    j["stream"]["b_frames"] = s.encoder.bFrames;
    j["stream"]["closed_gop"] = !s.encoder.openGop;
  }
  j["frames"] = {{"lightmap", {lightmap.first, lightmap.second}}};
  j["frames"]["sky"] = sky ? nlohmann::ordered_json{sky->first, sky->second} : nlohmann::ordered_json();
  j["variants"] = std::move(variants);
  return j.dump();
}

// Every variant's files, checked against the first: skies for all or none, as many as lightmaps.
std::vector<VariantFiles> expandVariants(const ImageSequences& in, bool& withSky) {
  std::vector<VariantFiles> files;
  for (const SequenceVariant& v : in.variants) {
    VariantFiles f{v.name, expandFramePattern(v.lightmaps), {}};
    if (!v.skies.empty()) f.skies = expandFramePattern(v.skies);
    files.push_back(std::move(f));
  }
  if (files.empty()) throw AuthoringError("no image sequence to author");
  withSky = !files[0].skies.empty();
  for (const VariantFiles& v : files) {
    if (withSky && v.skies.empty()) {
      throw AuthoringError("variant '" + v.name + "' has no sky sequence (give --variant-sky " + v.name +
                           "=PATTERN, or no sky for any variant)");
    }
    if (!withSky && !v.skies.empty())
      throw AuthoringError("variant '" + v.name + "' has a sky sequence but the first variant has none");
    if (withSky && v.skies.size() != v.lightmaps.size()) {
      throw AuthoringError("variant '" + v.name + "': " + std::to_string(v.lightmaps.size()) + " lightmap frames but " +
                           std::to_string(v.skies.size()) + " sky frames (first sky file " +
                           v.skies.front().path.string() + ")");
    }
  }
  return files;
}

}  // namespace

FrameStream authorSyntheticStream(SyntheticDay day, const std::vector<std::string>& weathers, AuthorSettings settings,
                                  const ToneMapping& tone, const FrameAuthorProgressFn& progress) {
  quietLibavLog();
  settings.withSky = day.skyWidth > 0;
  StreamWriter writer(settings);
  FrameAuthorProgress p;
  p.total = weathers.size() * day.frames;
  for (const std::string& w : weathers) {
    day.weather = w;
    checkSyntheticDay(day);
    writer.beginVariant(w);
    for (std::uint32_t f = 0; f < day.frames; ++f) {
      const Rgba8Image lm = toneMap(syntheticLightmap(day, f), tone);
      if (settings.withSky) {
        const Rgba8Image sky = toneMap(syntheticSky(day, f), tone);
        writer.addFrame(lm, &sky);
      } else {
        writer.addFrame(lm);
      }
      ++p.done;
      p.label = w + " " + std::to_string(f);
      if (progress) progress(p);
    }
  }
  FrameStream out{writer.finish(), writer.containerStretch()};
  nlohmann::ordered_json variants = nlohmann::ordered_json::array();
  for (const std::string& w : weathers) variants.push_back({{"name", w}, {"weather", w}});
  std::optional<std::pair<int, int>> sky;
  if (settings.withSky) sky = std::pair<int, int>(day.skyWidth, day.skyHeight);
  appendAuthoringRecord(out.bytes, frameStreamRecord("synthetic", settings, day.frames, {day.width, day.height}, sky,
                                                     std::move(variants)));
  return out;
}

FrameStream authorImageSequences(const ImageSequences& in, AuthorSettings settings, const ToneMapping& tone,
                                 const FrameAuthorProgressFn& progress) {
  quietLibavLog();
  const std::vector<VariantFiles> files = expandVariants(in, settings.withSky);
  FrameAuthorProgress p;
  for (const VariantFiles& v : files) p.total += v.lightmaps.size();
  StreamWriter writer(settings);
  std::pair<int, int> lmSize{0, 0};  // of the first frames, for the authoring record
  std::optional<std::pair<int, int>> skySize;
  for (const VariantFiles& v : files) {
    writer.beginVariant(v.name);
    for (std::size_t i = 0; i < v.lightmaps.size(); ++i) {
      const auto& lmPath = v.lightmaps[i].path;
      const Rgba8Image lm = loadFrame(lmPath, in.input, tone);
      std::optional<Rgba8Image> sky;
      if (settings.withSky) sky = loadFrame(v.skies[i].path, in.input, tone);
      if (p.done == 0) {
        lmSize = {lm.width, lm.height};
        if (sky) skySize = std::pair<int, int>(sky->width, sky->height);
      }
      try {
        writer.addFrame(lm, sky ? &*sky : nullptr);
      } catch (const AuthoringError& e) {
        const bool skyFault = std::string(e.what()).rfind("sky", 0) == 0;
        throw AuthoringError((skyFault ? v.skies[i].path : lmPath).string() + ": " + e.what());
      }
      ++p.done;
      p.label = lmPath.filename().string();
      if (progress) progress(p);
    }
  }
  FrameStream out{writer.finish(), writer.containerStretch()};
  nlohmann::ordered_json variants = nlohmann::ordered_json::array();
  for (const VariantFiles& v : files) {
    nlohmann::ordered_json names = {{"name", v.name},
                                    {"first_lightmap", v.lightmaps.front().path.filename().string()},
                                    {"last_lightmap", v.lightmaps.back().path.filename().string()}};
    if (!v.skies.empty()) names["first_sky"] = v.skies.front().path.filename().string();
    variants.push_back(std::move(names));
  }
  appendAuthoringRecord(out.bytes, frameStreamRecord("image-sequence", settings,
                                                     static_cast<std::uint32_t>(files.front().lightmaps.size()), lmSize,
                                                     skySize, std::move(variants)));
  return out;
}

std::string containerStretchNote(std::uint32_t stretch, Rational containerFps) {
  if (stretch <= 1) return {};
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.3g", static_cast<double>(stretch) * containerFps.den / containerFps.num);
  return "container time: frames " + std::to_string(stretch) + " periods apart (" + seconds +
         " s): the largest frame holds more than the DVD mux rate sends in one period at " +
         std::to_string(containerFps.num) + (containerFps.den == 1 ? "" : "/" + std::to_string(containerFps.den)) +
         " fps; playback follows the game rate in the descriptor, ffplay shows each frame that long\n";
}

}  // namespace vbim::streams
