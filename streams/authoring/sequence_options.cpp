#include "streams/authoring/sequence_options.hpp"

#include <sstream>
#include <utility>

#include "streams/authoring/error.hpp"

namespace vbim::streams {

namespace {

// NAME=VALUE options, in order of first appearance.
std::vector<std::pair<std::string, std::string>> parsePairs(const std::vector<std::string>& in, const char* what) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const std::string& s : in) {
    const std::size_t eq = s.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == s.size())
      throw AuthoringError(std::string(what) + " '" + s + "': expected NAME=PATTERN");
    out.emplace_back(s.substr(0, eq), s.substr(eq + 1));
  }
  return out;
}

}  // namespace

InputEncoding inputEncoding(const std::string& text) {
  if (text == "auto") return InputEncoding::Auto;
  if (text == "linear") return InputEncoding::Linear;
  if (text == "encoded") return InputEncoding::Encoded;
  throw AuthoringError("--input '" + text + "': expected auto, linear or encoded");
}

ImageSequences imageSequences(const SequenceOptions& o, InputEncoding input) {
  ImageSequences in;
  in.input = input;
  in.variants.push_back(SequenceVariant{o.name, o.frames, o.sky});
  const auto skies = parsePairs(o.variantSkies, "--variant-sky");
  for (const auto& [name, pattern] : parsePairs(o.variants, "--variant")) {
    SequenceVariant v{name, pattern, {}};
    for (const auto& [skyName, skyPattern] : skies)
      if (skyName == name) v.skies = skyPattern;
    in.variants.push_back(std::move(v));
  }
  for (const auto& [skyName, skyPattern] : skies) {
    bool known = false;
    for (const SequenceVariant& v : in.variants) known |= v.name == skyName;
    if (!known) throw AuthoringError("--variant-sky " + skyName + "=...: no --variant named '" + skyName + "'");
  }
  return in;
}

std::vector<std::string> weatherList(const std::string& text) {
  std::vector<std::string> weathers;
  std::stringstream list(text);
  for (std::string w; std::getline(list, w, ',');) weathers.push_back(w);
  return weathers;
}

}  // namespace vbim::streams
