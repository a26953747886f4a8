// What `vbim info` shows of a stream: the scan of a bare stream file or of the stream on an ISO 9660
// image (streams/stream_stats.hpp), its per-stream reports and its authoring record, as text and as
// the JSON document docs/cli.md describes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "iop/sector_source.hpp"
#include "streams/stream_stats.hpp"

namespace vbim::streams {

struct StreamInfo {
  std::string path;                      // as given
  std::optional<iop::DiscFile> onImage;  // where the stream lies on a disc image
  std::string shown;                     // the path, and the file and LBA on an image
  StreamScan scan;
  std::vector<StreamReport> reports;
  double fps = 25.0;                             // the descriptor's game rate, or 25 when there is none
  bool fpsGuessed = true;                        // no descriptor: the rates assume `fps`
  std::optional<nlohmann::ordered_json> record;  // how the stream was made, when it says
};

// Scans `path` (a stream file, or `file` on an ISO 9660 image: its only VBIM stream when empty).
// `perPicture`: one bitrate bucket per frame (the JSON's), else about 24 rows. Throws vbim::Error
// when the input cannot be read or is no program stream at all.
StreamInfo inspectStream(const std::string& path, const std::string& file, bool perPicture);

// The text of `vbim info` (every line ends in '\n').
std::string infoText(const StreamInfo& info);

// `vbim info --json`'s document.
nlohmann::json infoJson(const StreamInfo& info);

// The document as text (two-space indent, no final newline). Text read from a damaged stream
// (descriptor names, the authoring record) may not be UTF-8: such bytes are written as U+FFFD, so the
// document is always valid JSON, and `replaced` says that happened.
std::string infoJsonText(const StreamInfo& info, bool& replaced);

}  // namespace vbim::streams
