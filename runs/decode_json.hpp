// The --json summary of `vbim decode` (docs/cli.md, "JSON summaries"): what its summary line says, and
// every damaged picture with each issue the decoder found (file byte, macroblock, reason), so a
// script over a damaged disc reads the concealment as data. Text from the inputs that is not UTF-8
// becomes U+FFFD (runs::jsonText, as play's).
#pragma once

#include <cstdint>
#include <string>

#include "runs/decode_run.hpp"
#include "streams/decode/decode_input.hpp"
#include "streams/decode/stream_decode.hpp"

namespace vbim::runs {

// What the decode left in its output directory.
struct DecodeOutput {
  std::string directory;    // the --out directory as the summary line names it
  bool written = false;     // false: --strict failed, nothing was written
  std::int64_t files = 0;   // frame files in it
  std::uint64_t bytes = 0;  // their sizes together
};

// A decode issue's kind as a stable key for scripts ("bad_vlc", "missing_reference", ...); the
// reason in words is ipu::issueName.
const char* issueKey(ipu::IssueKind kind);

// `vbim decode --json`: `input` as readDecodeInput gave it, named `name` (`<stdin>` for standard input).
std::string decodeSummaryJson(const DecodeRequest& r, const streams::DecodeInput& input, const std::string& name,
                              const streams::DecodeSummary& s, const DecodeOutput& out,
                              const std::string& strictFailure, bool& replaced);

}  // namespace vbim::runs
