#include "cli/author_common.hpp"

#include <sstream>

#include "cli/command.hpp"
#include "streams/authoring/error.hpp"

namespace vbim::cli {

using namespace vbim::streams;

void addEncodeOptions(CLI::App* cmd, EncodeOptions& o) {
  cmd->add_option("--fps", o.fps, "Game-time frame rate: stream frames per second of game time (N or N/D)")
      ->capture_default_str();
  cmd->add_option("--container-fps", o.containerFps, "Frame rate written in the MPEG headers (what ffplay shows)")
      ->capture_default_str();
  cmd->add_option("--loop", o.loop, "Frame playback returns to after the last one")->capture_default_str();
  auto* q = cmd->add_option("--q", o.q, "Fixed quantiser_scale 1..31 (lower is better)")->capture_default_str();
  cmd->add_option("--bitrate", o.bitrate, "Target bit/s instead of a fixed quantiser (VBV sized for DVD)")->excludes(q);
  cmd->add_option("--gop", o.gop,
                  "Pictures per GOP, from one I picture to the next (1: every picture I; more: P pictures)")
      ->capture_default_str();
  cmd->add_option("--b-frames", o.bFrames, "B pictures between references (below --gop)")->capture_default_str();
  cmd->add_flag("--open-gop", o.openGop,
                "Let B pictures refer across GOP headers (default: closed GOPs); each variant's first frame and "
                "the loop frame still start a GOP no B picture reaches back from");
  cmd->add_option("--exposure", o.exposure, "Linear inputs: multiply by 2^EV before the curve")->capture_default_str();
  cmd->add_option("--tone", o.tone, "Tone curve for linear inputs: clamp, reinhard, filmic")->capture_default_str();
  cmd->add_option("--transfer", o.transfer, "Encoding after the curve: srgb, linear, gamma:G")->capture_default_str();
  cmd->add_option("--white", o.white, "8-bit code of 1.0 after the curve (128 = GS MODULATE 1.0)")
      ->capture_default_str();
}

AuthorSettings streamSettings(const EncodeOptions& o) {
  AuthorSettings settings;
  settings.gameFps = parseRational(o.fps, "--fps");
  settings.encoder.containerFps = parseRational(o.containerFps, "--container-fps");
  settings.encoder.qscale = o.q;
  settings.encoder.bitrate = o.bitrate;
  settings.loopFrame = o.loop;
  settings.encoder.gop = o.gop;
  settings.encoder.bFrames = o.bFrames;
  settings.encoder.openGop = o.openGop;
  if (const std::string why = gopProblem(settings.encoder); !why.empty()) throw Exit(2, why);
  return settings;
}

ToneMapping toneMapping(const EncodeOptions& o) {
  ToneMapping tone;
  tone.exposure = o.exposure;
  tone.white = o.white;
  tone.curve = parseCurve(o.tone);
  parseTransfer(o.transfer, tone);
  if (!(o.white >= 1 && o.white <= 255)) throw Exit(2, "--white must be in 1..255");
  return tone;
}

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
    throw Exit(2, std::string(what) + " '" + s + "': expected N or N/D (e.g. 1, 25, 30000/1001)");
  }
  if (r.num == 0 || r.den == 0) throw Exit(2, std::string(what) + " '" + s + "' must be positive");
  return r;
}

void parseSize(const std::string& s, int& w, int& h, const char* what) {
  char x = 0;
  std::istringstream in(s);
  if (!(in >> w >> x >> h) || x != 'x' || !in.eof()) throw Exit(2, std::string(what) + " '" + s + "': expected WxH");
}

}  // namespace vbim::cli
