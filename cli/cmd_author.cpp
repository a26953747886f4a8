// vbim author: image sequences, Technique A (author_terrain.cpp) or the synthetic day generator ->
// one VBIM stream file.
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <utility>

#include <nlohmann/json.hpp>
#include "cli/author_common.hpp"
#include "cli/author_terrain.hpp"
#include "cli/command.hpp"
#include "cli/output_dir.hpp"
#include "cli/progress.hpp"
#include "imageio/error.hpp"
#include "imageio/image_reader.hpp"
#include "iop/error.hpp"

#include "streams/authoring/error.hpp"
#include "streams/authoring/frame_pattern.hpp"
#include "streams/authoring/stream_writer.hpp"
#include "streams/authoring/synthetic_day.hpp"
#include "streams/authoring/tone_map.hpp"
#include "streams/authoring_record.hpp"
#include "streams/disc/iso_disc.hpp"
#include "streams/disc/iso_writer.hpp"

extern "C" {
#include <libavutil/log.h>
}

namespace vbim::cli {

namespace {

using namespace vbim::streams;

struct AuthorOptions {
  std::string frames, sky, name = "default";
  std::vector<std::string> variants, variantSkies;
  EncodeOptions encode;
  std::string input = "auto";
  std::string synthetic;
  std::uint32_t syntheticFrames = 48;
  std::string syntheticSize = "256x256", syntheticSkySize = "128x64";
  std::string out;
  bool force = false;
  std::string iso, isoFile = "\\DATA\\DAY.VBI;1";  // --iso: also a disc image holding the stream
};

// --iso: the stream just written, on an ISO 9660 image at --iso-file.
void writeDiscImage(const AuthorOptions& o) {
  try {
    writeIsoImage(o.iso, {{o.isoFile, o.out}});
    const auto f = IsoDisc(o.iso).find(o.isoFile);
    std::cout << o.iso << ": ISO 9660 image, " << o.isoFile << " at LBA " << f->lba << " ("
              << "vbim play " << o.iso << ")\n";
  } catch (const iop::DiscError& e) {
    throw Exit(1, e.what());
  }
}

// NAME=VALUE options, in order of first appearance.
std::vector<std::pair<std::string, std::string>> parsePairs(const std::vector<std::string>& in, const char* what) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const std::string& s : in) {
    const std::size_t eq = s.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == s.size())
      throw Exit(2, std::string(what) + " '" + s + "': expected NAME=PATTERN");
    out.emplace_back(s.substr(0, eq), s.substr(eq + 1));
  }
  return out;
}

// One input frame file to 8-bit (streams/authoring/tone_map.hpp); a file that cannot be read is an
// AuthoringError naming it.
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

struct VariantInput {
  std::string name;
  std::vector<FrameFile> lightmaps, skies;
};

// The authoring record of a stream made from image files or by the synthetic day generator: what is
// known of it (the source, the frame sizes and times, the encoder settings), in the form Technique A
// streams carry (lighting/authoring/authoring_record.hpp) but without a terrain, which these sources
// do not have. `vbim info` shows it, `vbim play` copies it, `vbim render` notes that no terrain is
// recorded and keeps its defaults. Appended after the video, so players never read it.
std::string frameStreamRecord(const std::string& source, const AuthorSettings& s, std::uint32_t framesPerVariant,
                              std::pair<int, int> lightmap, std::optional<std::pair<int, int>> sky,
                              nlohmann::ordered_json variants) {
  nlohmann::ordered_json j;
  j["record"] = "vbim-authoring";
  j["record_version"] = 1;
  j["vbim_version"] = VBIM_VERSION;
  j["source"] = source;
  j["stream"] = {{"game_fps", {s.gameFps.num, s.gameFps.den}},
                 {"loop_frame", s.loopFrame},
                 {"frames_per_variant", framesPerVariant},
                 {"frame_period_s", static_cast<double>(s.gameFps.den) / static_cast<double>(s.gameFps.num)},
                 {"qscale", s.encoder.qscale},
                 {"bitrate", s.encoder.bitrate}};
  j["frames"] = {{"lightmap", {lightmap.first, lightmap.second}}};
  j["frames"]["sky"] = sky ? nlohmann::ordered_json{sky->first, sky->second} : nlohmann::ordered_json();
  j["variants"] = std::move(variants);
  return j.dump();
}

void runAuthor(const AuthorOptions& o) {
  AuthorSettings settings = streamSettings(o.encode);
  const ToneMapping tone = toneMapping(o.encode);
  InputEncoding enc = InputEncoding::Auto;
  if (o.input == "linear") {
    enc = InputEncoding::Linear;
  } else if (o.input == "encoded") {
    enc = InputEncoding::Encoded;
  } else if (o.input != "auto") {
    throw Exit(2, "--input '" + o.input + "': expected auto, linear or encoded");
  }

  av_log_set_level(AV_LOG_ERROR);
  std::vector<std::uint8_t> bytes;
  std::string stretchNote;
  if (!o.synthetic.empty()) {
    if (!o.frames.empty() || !o.variants.empty())
      throw Exit(2, "--synthetic replaces --frames and --variant; give one or the other");
    SyntheticDay day;
    day.frames = o.syntheticFrames;
    parseSize(o.syntheticSize, day.width, day.height, "--synthetic-size");
    parseSize(o.syntheticSkySize, day.skyWidth, day.skyHeight, "--synthetic-sky-size");
    settings.withSky = day.skyWidth > 0;
    std::vector<std::string> weathers;
    std::stringstream list(o.synthetic);
    for (std::string w; std::getline(list, w, ',');) weathers.push_back(w);
    StreamWriter writer(settings);
    const std::size_t total = weathers.size() * day.frames;
    std::size_t done = 0;
    Progress progress("vbim author", "frames");
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
        progress.show(static_cast<double>(++done), static_cast<double>(total), w + " " + std::to_string(f));
      }
    }
    progress.finish();
    bytes = writer.finish();
    stretchNote = containerStretchNote(writer.containerStretch(), settings.encoder.containerFps);
    nlohmann::ordered_json variants = nlohmann::ordered_json::array();
    for (const std::string& w : weathers) variants.push_back({{"name", w}, {"weather", w}});
    std::optional<std::pair<int, int>> sky;
    if (settings.withSky) sky = std::pair<int, int>(day.skyWidth, day.skyHeight);
    streams::appendAuthoringRecord(
        bytes, frameStreamRecord("synthetic", settings, day.frames, {day.width, day.height}, sky, std::move(variants)));
  } else {
    if (o.frames.empty()) {
      throw Exit(2,
                 "give a source: --frames PATTERN, --terrain FILE or --procedural (Technique A), or "
                 "--synthetic");
    }
    std::vector<VariantInput> inputs;
    inputs.push_back(VariantInput{o.name, expandFramePattern(o.frames), {}});
    if (!o.sky.empty()) inputs[0].skies = expandFramePattern(o.sky);
    const auto skies = parsePairs(o.variantSkies, "--variant-sky");
    for (const auto& [name, pattern] : parsePairs(o.variants, "--variant")) {
      VariantInput v{name, expandFramePattern(pattern), {}};
      for (const auto& [skyName, skyPattern] : skies)
        if (skyName == name) v.skies = expandFramePattern(skyPattern);
      inputs.push_back(std::move(v));
    }
    for (const auto& [skyName, skyPattern] : skies) {
      bool known = false;
      for (const VariantInput& v : inputs) known |= v.name == skyName;
      if (!known) throw Exit(2, "--variant-sky " + skyName + "=...: no --variant named '" + skyName + "'");
    }
    settings.withSky = !inputs[0].skies.empty();
    std::size_t total = 0;
    for (const VariantInput& v : inputs) {
      if (settings.withSky && v.skies.empty()) {
        throw Exit(2, "variant '" + v.name + "' has no sky sequence (give --variant-sky " + v.name +
                          "=PATTERN, or no sky for any variant)");
      }
      if (!settings.withSky && !v.skies.empty())
        throw Exit(2, "variant '" + v.name + "' has a sky sequence but the first variant has none");
      if (settings.withSky && v.skies.size() != v.lightmaps.size()) {
        throw Exit(2, "variant '" + v.name + "': " + std::to_string(v.lightmaps.size()) + " lightmap frames but " +
                          std::to_string(v.skies.size()) + " sky frames (first sky file " +
                          v.skies.front().path.string() + ")");
      }
      total += v.lightmaps.size();
    }
    StreamWriter writer(settings);
    std::size_t done = 0;
    std::pair<int, int> lmSize{0, 0};  // of the first frames, for the authoring record
    std::optional<std::pair<int, int>> skySize;
    Progress progress("vbim author", "frames");
    for (const VariantInput& v : inputs) {
      writer.beginVariant(v.name);
      for (std::size_t i = 0; i < v.lightmaps.size(); ++i) {
        const auto& lmPath = v.lightmaps[i].path;
        const Rgba8Image lm = loadFrame(lmPath, enc, tone);
        std::optional<Rgba8Image> sky;
        if (settings.withSky) sky = loadFrame(v.skies[i].path, enc, tone);
        if (done == 0) {
          lmSize = {lm.width, lm.height};
          if (sky) skySize = std::pair<int, int>(sky->width, sky->height);
        }
        try {
          writer.addFrame(lm, sky ? &*sky : nullptr);
        } catch (const AuthoringError& e) {
          const bool skyFault = std::string(e.what()).rfind("sky", 0) == 0;
          throw AuthoringError((skyFault ? v.skies[i].path : lmPath).string() + ": " + e.what());
        }
        progress.show(static_cast<double>(++done), static_cast<double>(total), lmPath.filename().string());
      }
    }
    progress.finish();
    bytes = writer.finish();
    stretchNote = containerStretchNote(writer.containerStretch(), settings.encoder.containerFps);
    nlohmann::ordered_json variants = nlohmann::ordered_json::array();
    for (const VariantInput& v : inputs) {
      nlohmann::ordered_json files = {{"name", v.name},
                                      {"first_lightmap", v.lightmaps.front().path.filename().string()},
                                      {"last_lightmap", v.lightmaps.back().path.filename().string()}};
      if (!v.skies.empty()) files["first_sky"] = v.skies.front().path.filename().string();
      variants.push_back(std::move(files));
    }
    streams::appendAuthoringRecord(bytes, frameStreamRecord("image-sequence", settings,
                                                            static_cast<std::uint32_t>(inputs.front().lightmaps.size()),
                                                            lmSize, skySize, std::move(variants)));
  }
  writeStreamFile(o.out, bytes);
  std::cout << o.out << ": " << bytes.size() / 2048 << " sectors (" << bytes.size() << " bytes)\n" << stretchNote;
}

}  // namespace

void addAuthor(CLI::App& app) {
  auto* cmd = app.add_subcommand(kAuthorCommand.name, kAuthorCommand.summary);
  auto o = std::make_shared<AuthorOptions>();
  cmd->add_option("--frames", o->frames, "Lightmap frames, e.g. 'dir/lightmap_%04d.exr' (any OpenImageIO format)");
  cmd->add_option("--sky", o->sky, "Sky dome frames, e.g. 'dir/sky_%04d.exr' (same numbering as --frames)");
  cmd->add_option("--name", o->name, "Variant name of --frames/--sky")->capture_default_str();
  cmd->add_option("--variant", o->variants, "Another variant (weather): NAME=LIGHTMAP_PATTERN; repeatable");
  cmd->add_option("--variant-sky", o->variantSkies, "Sky frames of a --variant: NAME=SKY_PATTERN; repeatable");
  addEncodeOptions(cmd, o->encode);
  cmd->add_option("--input", o->input, "auto (float files linear, integer files encoded), linear, encoded")
      ->capture_default_str();
  cmd->add_option("--synthetic", o->synthetic, "Generate a synthetic day instead: WEATHER[,WEATHER] (clear, overcast)");
  cmd->add_option("--synthetic-frames", o->syntheticFrames, "Frames of the synthetic day")->capture_default_str();
  cmd->add_option("--synthetic-size", o->syntheticSize, "Synthetic lightmap size WxH")->capture_default_str();
  cmd->add_option("--synthetic-sky-size", o->syntheticSkySize, "Synthetic sky size WxH (0x0: no sky)")
      ->capture_default_str();
  cmd->add_option("--out", o->out, "Output stream file (complete or left as it was)")->required();
  cmd->add_flag("--force", o->force, "Replace an existing output file");
  cmd->add_option("--iso", o->iso, "Also write an ISO 9660 disc image holding the stream (made with xorriso)");
  cmd->add_option("--iso-file", o->isoFile, "Where the stream lies on the --iso image (ISO 9660 level 1 names)")
      ->capture_default_str();
  auto terrain = std::make_shared<TerrainAuthorOptions>();
  addTerrainOptions(cmd, terrain);
  cmd->footer(
      "Examples:\n"
      "  vbim author --procedural --out day.vbim\n"
      "  vbim author --frames 'lm_%04d.exr' --sky 'sky_%04d.exr' --fps 1 --out day.vbim\n");
  cmd->callback([o, terrain] {
    refuseExistingOutputFile(o->out, o->force);  // before minutes of encoding, not after
    if (!o->iso.empty() && std::filesystem::path(o->iso) == std::filesystem::path(o->out)) {
      throw Exit(2, "--iso " + o->iso + " is the --out stream file; give the image another name");
    }
    if (const std::string why = level1PathProblem(o->isoFile); !o->iso.empty() && !why.empty()) {
      throw Exit(2, "--iso-file '" + o->isoFile + "': " + why);
    }
    const std::string technique = firstTerrainOptionGiven(*terrain);
    if (technique.empty()) {
      runAuthor(*o);
      if (!o->iso.empty()) writeDiscImage(*o);
      return;
    }
    // Technique A renders its own frames: the image-sequence and synthetic options do not apply.
    if (!o->frames.empty() || !o->sky.empty() || !o->variants.empty() || !o->variantSkies.empty() ||
        !o->synthetic.empty()) {
      throw Exit(2, technique +
                        " selects Technique A, which renders its own frames; it excludes --frames, --sky, "
                        "--variant, --variant-sky and --synthetic");
    }
    runTerrainAuthor(*terrain, o->encode, o->out);
    if (!o->iso.empty()) writeDiscImage(*o);
  });
}

}  // namespace vbim::cli
