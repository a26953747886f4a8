// Where a run came from, recorded in its stats.json ("run"): the vbim version, the command's
// settings, and each input file with its SHA-256 (the digest `sha256sum FILE` prints), so a
// result can be traced back to the exact stream, platform config and fault plan that made it.
#pragma once

#include <filesystem>
#include <string>

#include "player/player.hpp"
#include "runs/play_run.hpp"
#include "runtime/json.hpp"

namespace vbim::runs {

// Lowercase hex SHA-256 of a file's bytes; throws vbim::Error (bad input) if it cannot be read.
std::string sha256File(const std::filesystem::path& path);
// Of bytes in memory (a fault plan given inline).
std::string sha256Text(const std::string& bytes);

// {"path": ..., "sha256": ...} for an input file.
json::Value inputJson(const std::filesystem::path& path);

// stats.json's "run" of `vbim play` (and `vbim demo`): the version, the settings and every input
// with its SHA-256.
json::Value playProvenance(const PlayRequest& r, const player::PlayerOptions& o);

}  // namespace vbim::runs
