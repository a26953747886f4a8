#include "streams/authoring/encode_options.hpp"

#include <sstream>
#include <stdexcept>

#include "streams/authoring/error.hpp"
#include "streams/authoring/mpeg2_encoder.hpp"

namespace vbim::streams {

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
  if (const std::string why = gopProblem(settings.encoder); !why.empty()) throw AuthoringError(why);
  return settings;
}

ToneMapping toneMapping(const EncodeOptions& o) {
  ToneMapping tone;
  tone.exposure = o.exposure;
  tone.white = o.white;
  tone.curve = parseCurve(o.tone);
  parseTransfer(o.transfer, tone);
  if (!(o.white >= 1 && o.white <= 255)) throw AuthoringError("--white must be in 1..255");
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
    throw AuthoringError(std::string(what) + " '" + s + "': expected N or N/D (e.g. 1, 25, 30000/1001)");
  }
  if (r.num == 0 || r.den == 0) throw AuthoringError(std::string(what) + " '" + s + "' must be positive");
  return r;
}

void parseSize(const std::string& s, int& w, int& h, const char* what) {
  char x = 0;
  std::istringstream in(s);
  if (!(in >> w >> x >> h) || x != 'x' || !in.eof())
    throw AuthoringError(std::string(what) + " '" + s + "': expected WxH");
}

}  // namespace vbim::streams
