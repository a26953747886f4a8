// The --json summaries of `vbim play` (here, made by playRun) and `vbim profile` (runs/profile_json.hpp) (docs/cli.md,
// "JSON summaries"): the facts their text summaries print, as one JSON document on stdout. Text from the inputs (a
// disc's path, a file name read from a disc image) that is not UTF-8 has its bytes replaced by U+FFFD, as `vbim info
// --json` does, and a warning says so on stderr: the document is always valid JSON.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "player/player.hpp"

namespace vbim::runs {

// The time the pictures of a play took on their own thread, and how they were written.
struct PictureCost {
  double cpuSeconds = 0;
  std::string format;  // "PNG level 1", "EXR"
};

// The document as text. Bytes of the inputs that are not UTF-8 become U+FFFD, and a warning on
// stderr names `command` and says so.
std::string jsonText(const nlohmann::ordered_json& j, const char* command);

// `vbim play --json`: what playSummary (player/report.hpp) and the pictures line print.
std::string playSummaryJson(const player::Player& player, const std::string& disc, double wallSeconds,
                            double cpuSeconds, std::int64_t images, const PictureCost& pictures);

}  // namespace vbim::runs
