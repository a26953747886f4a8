// `vbim info --json`'s document: the scan of a stream (streams/stream_stats.hpp), its descriptor,
// pictures, defects and authoring record, in the form docs/cli.md describes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "iop/sector_source.hpp"
#include "streams/stream_stats.hpp"

namespace vbim::cli {

nlohmann::json infoJson(const std::string& path, const std::optional<iop::DiscFile>& onImage,
                        const streams::StreamScan& scan, const std::vector<streams::StreamReport>& reports,
                        const std::optional<nlohmann::ordered_json>& record);

}  // namespace vbim::cli
