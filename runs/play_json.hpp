// The --json summaries of `vbim play` (here, made by playRun) and `vbim profile` (runs/profile_json.hpp) (docs/cli.md,
// "JSON summaries"): the facts their text summaries print, as one JSON document on stdout. Text from the inputs (a
// disc's path, a file name read from a disc image) that is not UTF-8 has its bytes replaced by U+FFFD, as `vbim info
// --json` does, and the command warns on stderr (kNotUtf8Warning): the document is always valid JSON.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "player/player.hpp"

namespace vbim::runs {

// The time the pictures of a play took on their own thread, and how they were written.
struct PictureCost {
  double cpuSeconds = 0;
  std::string format;  // "PNG level 1", "EXR"
};

// What a command says on stderr (after "vbim CMD: ") when its document had bytes replaced.
inline constexpr std::string_view kNotUtf8Warning =
    "warning: text from the input is not UTF-8; its bytes are replaced by U+FFFD in the JSON";

// The document as text (two-space indent, a final newline). Bytes of the inputs that are not UTF-8
// become U+FFFD, and `replaced` says that happened (as streams::infoJsonText does): the library
// returns, the command warns.
std::string jsonText(const nlohmann::ordered_json& j, bool& replaced);

// `vbim play --json`: what playSummary (player/report.hpp) and the pictures line print.
std::string playSummaryJson(const player::Player& player, const std::string& disc, double wallSeconds,
                            double cpuSeconds, std::int64_t images, const PictureCost& pictures, bool& replaced);

}  // namespace vbim::runs
