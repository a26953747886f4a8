// vbim info: what a VBIM stream holds, read sector by sector with the model's reader
// (streams/info/stream_info.hpp).
#include <iostream>

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "streams/disc/standard_input.hpp"
#include "streams/info/stream_info.hpp"

namespace vbim::cli {

void addInfo(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("info", "Inspect a VBIM stream: streams, frames, sectors per frame, bitrate, descriptor");
  auto path = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  auto file = std::make_shared<std::string>();
  cmd->add_option("STREAM", *path, "Stream file, or an ISO 9660 disc image; - reads it from stdin")
      ->required()
      ->transform(stdinAsFile())
      ->check(inputFile());
  cmd->add_option("--file", *file,
                  "The stream on a disc image, e.g. '\\DATA\\DAY.VBI;1' (default: its only VBIM stream)");
  cmd->add_flag("--json", *json, "Machine-readable output");
  cmd->footer(
      "Examples:\n"
      "  vbim info streams/samples/day_clear.vbim\n"
      "  vbim info streams/samples/day_clear.vbim --json\n");
  cmd->callback([path, json, file] {
    const streams::StreamInfo info = streams::inspectStream(*path, *file, *json);
    if (*json) {
      bool replaced = false;
      const std::string text = streams::infoJsonText(info, replaced);
      if (replaced) {
        std::cerr << "vbim info: warning: " << info.shown
                  << ": text in the stream is not UTF-8; its bytes are replaced by U+FFFD in the JSON\n";
      }
      std::cout << streams::nameStandardInput(text) << "\n";
    } else {
      std::cout << streams::nameStandardInput(streams::infoText(info));
    }
    const auto& errors = info.scan.errors;
    if (!errors.empty()) {
      throw Exit(2, info.shown + ": " + std::to_string(errors.size()) +
                        " defects found (first: " + errors.front().describe() + ")");
    }
  });
}

}  // namespace vbim::cli
