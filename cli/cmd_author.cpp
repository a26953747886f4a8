// vbim author: image sequences (or the synthetic day generator) -> one VBIM stream file.
#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>

#include "cli/command.hpp"
#include "streams/authoring/authoring_error.hpp"
#include "streams/authoring/frame_pattern.hpp"
#include "streams/authoring/image_loader.hpp"
#include "streams/authoring/stream_writer.hpp"
#include "streams/authoring/synthetic_day.hpp"

extern "C" {
#include <libavutil/log.h>
}

namespace vbim::cli {

namespace {

using namespace vbim::streams;

struct AuthorOptions {
  std::string frames, sky, name = "default";
  std::vector<std::string> variants, variantSkies;
  std::string fps, containerFps = "25";
  std::uint32_t loop = 0;
  int q = 3;
  std::int64_t bitrate = 0;
  double exposure = 0;
  std::string tone = "clamp", transfer = "srgb", input = "auto";
  double white = 255;
  std::string synthetic;
  std::uint32_t syntheticFrames = 48;
  std::string syntheticSize = "256x256", syntheticSkySize = "128x64";
  std::string out;
};

Rational parseRational(const std::string& s, const char* what) {
  Rational r;
  const std::size_t slash = s.find('/');
  try {
    std::size_t used = 0;
    r.num = static_cast<std::uint32_t>(std::stoul(s.substr(0, slash), &used));
    if (used != s.substr(0, slash).size()) throw std::invalid_argument(s);
    if (slash != std::string::npos) {
      r.den = static_cast<std::uint32_t>(std::stoul(s.substr(slash + 1), &used));
      if (used != s.size() - slash - 1) throw std::invalid_argument(s);
    }
  } catch (const std::exception&) {
    throw Exit(2, std::string("vbim author: ") + what + " '" + s + "': expected N or N/D (e.g. 1, 25, 30000/1001)");
  }
  if (r.num == 0 || r.den == 0) throw Exit(2, std::string("vbim author: ") + what + " '" + s + "' must be positive");
  return r;
}

void parseSize(const std::string& s, int& w, int& h, const char* what) {
  char x = 0;
  std::istringstream in(s);
  if (!(in >> w >> x >> h) || x != 'x' || !in.eof())
    throw Exit(2, std::string("vbim author: ") + what + " '" + s + "': expected WxH");
}

// NAME=VALUE options, in order of first appearance.
std::vector<std::pair<std::string, std::string>> parsePairs(const std::vector<std::string>& in, const char* what) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const std::string& s : in) {
    const std::size_t eq = s.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == s.size())
      throw Exit(2, std::string("vbim author: ") + what + " '" + s + "': expected NAME=PATTERN");
    out.emplace_back(s.substr(0, eq), s.substr(eq + 1));
  }
  return out;
}

// A progress bar on stderr, only when it is a terminal.
class Progress {
 public:
  explicit Progress(std::size_t total) : total_(total), tty_(::isatty(STDERR_FILENO) == 1) {}
  void step(const std::string& label) {
    ++done_;
    if (!tty_) return;
    const int width = 30;
    const int filled = static_cast<int>(width * done_ / std::max<std::size_t>(1, total_));
    std::fprintf(stderr, "\r[%.*s%*s] %zu/%zu %-24.24s", filled, "##############################", width - filled, "",
                 done_, total_, label.c_str());
    std::fflush(stderr);
  }
  void end() {
    if (tty_) std::fprintf(stderr, "\n");
  }

 private:
  std::size_t total_, done_ = 0;
  bool tty_;
};

struct VariantInput {
  std::string name;
  std::vector<FrameFile> lightmaps, skies;
};

void runAuthor(const AuthorOptions& o) {
  AuthorSettings settings;
  settings.gameFps = parseRational(o.fps, "--fps");
  settings.encoder.containerFps = parseRational(o.containerFps, "--container-fps");
  settings.encoder.qscale = o.q;
  settings.encoder.bitrate = o.bitrate;
  settings.loopFrame = o.loop;
  ToneMapping tone;
  tone.exposure = o.exposure;
  tone.white = o.white;
  InputEncoding enc = InputEncoding::Auto;
  try {
    tone.curve = parseCurve(o.tone);
    parseTransfer(o.transfer, tone);
  } catch (const AuthoringError& e) {
    throw Exit(2, std::string("vbim author: ") + e.what());
  }
  if (o.input == "linear")
    enc = InputEncoding::Linear;
  else if (o.input == "encoded")
    enc = InputEncoding::Encoded;
  else if (o.input != "auto")
    throw Exit(2, "vbim author: --input '" + o.input + "': expected auto, linear or encoded");
  if (!(o.white >= 1 && o.white <= 255)) throw Exit(2, "vbim author: --white must be in 1..255");

  av_log_set_level(AV_LOG_ERROR);
  std::vector<std::uint8_t> bytes;
  if (!o.synthetic.empty()) {
    if (!o.frames.empty() || !o.variants.empty())
      throw Exit(2, "vbim author: --synthetic replaces --frames and --variant; give one or the other");
    SyntheticDay day;
    day.frames = o.syntheticFrames;
    parseSize(o.syntheticSize, day.width, day.height, "--synthetic-size");
    parseSize(o.syntheticSkySize, day.skyWidth, day.skyHeight, "--synthetic-sky-size");
    settings.withSky = day.skyWidth > 0;
    std::vector<std::string> weathers;
    std::stringstream list(o.synthetic);
    for (std::string w; std::getline(list, w, ',');) weathers.push_back(w);
    StreamWriter writer(settings);
    Progress progress(weathers.size() * day.frames);
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
        progress.step(w + " " + std::to_string(f));
      }
    }
    progress.end();
    bytes = writer.finish();
  } else {
    if (o.frames.empty()) throw Exit(2, "vbim author: --frames PATTERN (or --synthetic) is required");
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
      if (!known) throw Exit(2, "vbim author: --variant-sky " + skyName + "=...: no --variant named '" + skyName + "'");
    }
    settings.withSky = !inputs[0].skies.empty();
    std::size_t total = 0;
    for (const VariantInput& v : inputs) {
      if (settings.withSky && v.skies.empty())
        throw Exit(2, "vbim author: variant '" + v.name + "' has no sky sequence (give --variant-sky " + v.name +
                          "=PATTERN, or no sky for any variant)");
      if (!settings.withSky && !v.skies.empty())
        throw Exit(2, "vbim author: variant '" + v.name + "' has a sky sequence but the first variant has none");
      if (settings.withSky && v.skies.size() != v.lightmaps.size())
        throw Exit(2, "vbim author: variant '" + v.name + "': " + std::to_string(v.lightmaps.size()) +
                          " lightmap frames but " + std::to_string(v.skies.size()) + " sky frames (first sky file " +
                          v.skies.front().path.string() + ")");
      total += v.lightmaps.size();
    }
    StreamWriter writer(settings);
    Progress progress(total);
    for (const VariantInput& v : inputs) {
      writer.beginVariant(v.name);
      for (std::size_t i = 0; i < v.lightmaps.size(); ++i) {
        const auto& lmPath = v.lightmaps[i].path;
        const Rgba8Image lm = loadFrame(lmPath, enc, tone);
        std::optional<Rgba8Image> sky;
        if (settings.withSky) sky = loadFrame(v.skies[i].path, enc, tone);
        try {
          writer.addFrame(lm, sky ? &*sky : nullptr);
        } catch (const AuthoringError& e) {
          const bool skyFault = std::string(e.what()).rfind("sky", 0) == 0;
          throw AuthoringError((skyFault ? v.skies[i].path : lmPath).string() + ": " + e.what());
        }
        progress.step(lmPath.filename().string());
      }
    }
    progress.end();
    bytes = writer.finish();
  }
  writeStreamFile(o.out, bytes);
  std::cout << o.out << ": " << bytes.size() / 2048 << " sectors (" << bytes.size() << " bytes)\n";
}

}  // namespace

void addAuthor(CLI::App& app) {
  auto* cmd = app.add_subcommand("author", "Author a VBIM stream (MPEG-2 PS, 2048-byte packs) from image sequences");
  auto o = std::make_shared<AuthorOptions>();
  cmd->add_option("--frames", o->frames, "Lightmap frames, e.g. 'dir/lightmap_%04d.exr' (any OpenImageIO format)");
  cmd->add_option("--sky", o->sky, "Sky dome frames, e.g. 'dir/sky_%04d.exr' (same numbering as --frames)");
  cmd->add_option("--name", o->name, "Variant name of --frames/--sky")->capture_default_str();
  cmd->add_option("--variant", o->variants, "Another variant (weather): NAME=LIGHTMAP_PATTERN; repeatable");
  cmd->add_option("--variant-sky", o->variantSkies, "Sky frames of a --variant: NAME=SKY_PATTERN; repeatable");
  cmd->add_option("--fps", o->fps, "Game-time frame rate: stream frames per second of game time (N or N/D)")
      ->required();
  cmd->add_option("--container-fps", o->containerFps, "Frame rate written in the MPEG headers (what ffplay shows)")
      ->capture_default_str();
  cmd->add_option("--loop", o->loop, "Frame playback returns to after the last one")->capture_default_str();
  auto* q = cmd->add_option("--q", o->q, "Fixed quantiser_scale 1..31 (lower is better)")->capture_default_str();
  cmd->add_option("--bitrate", o->bitrate, "Target bit/s instead of a fixed quantiser (VBV sized for DVD)")
      ->excludes(q);
  cmd->add_option("--exposure", o->exposure, "Linear inputs: multiply by 2^EV before the curve")->capture_default_str();
  cmd->add_option("--tone", o->tone, "Tone curve for linear inputs: clamp, reinhard, filmic")->capture_default_str();
  cmd->add_option("--transfer", o->transfer, "Encoding after the curve: srgb, linear, gamma:G")->capture_default_str();
  cmd->add_option("--white", o->white, "8-bit code of 1.0 after the curve (128 = GS MODULATE 1.0)")
      ->capture_default_str();
  cmd->add_option("--input", o->input, "auto (float files linear, integer files encoded), linear, encoded")
      ->capture_default_str();
  cmd->add_option("--synthetic", o->synthetic, "Generate a synthetic day instead: WEATHER[,WEATHER] (clear, overcast)");
  cmd->add_option("--synthetic-frames", o->syntheticFrames, "Frames of the synthetic day")->capture_default_str();
  cmd->add_option("--synthetic-size", o->syntheticSize, "Synthetic lightmap size WxH")->capture_default_str();
  cmd->add_option("--synthetic-sky-size", o->syntheticSkySize, "Synthetic sky size WxH (0x0: no sky)")
      ->capture_default_str();
  cmd->add_option("--out", o->out, "Output stream file")->required();
  cmd->callback([o] {
    try {
      runAuthor(*o);
    } catch (const AuthoringError& e) {
      throw Exit(1, std::string("vbim author: ") + e.what());
    }
  });
}

}  // namespace vbim::cli
