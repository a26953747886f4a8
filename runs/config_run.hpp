// `vbim config` as a library call: the platform config printed with every default and its source
// (TOML or Markdown), or a config file and a fault plan checked the way `vbim play` reads them (the
// same key ranges and relations, the same GS checks, runs/console_check.hpp, against the stream
// given or the smallest lightmap), and the GS setup of a stream (gs/setup_listing.hpp). Not model
// code (TOML through config/, disc images); no cost on the simulated clock.
#pragma once

#include <string>

namespace vbim::runs {

struct ConfigRequest {
  bool markdown = false;            // the config as a Markdown table, not TOML
  bool gsSetup = false;             // the GS setup of `stream` instead of the config
  bool effective = false;           // with `check`: the effective config too
  bool defaults = false;            // the defaults asked for (printed as well as any verdict)
  std::string format = "markdown";  // the GS setup's: markdown, gif or c
  std::string check;                // a platform config to check, or empty
  std::string faults;               // a fault plan to check, or empty
  std::string stream;               // a stream file or disc image, or empty
  std::string file;                 // the stream on the disc image, or empty: its only one
};

struct ConfigResult {
  // What passed, one line each ("plan.toml: 3 fault(s), valid"); empty when nothing was checked.
  // With a document, the last line says which follows.
  std::string verdict;
  // The config (TOML with its header, or Markdown) or the GS setup; empty when only a check was
  // asked for (then the verdict is the output).
  std::string document;
};

// Throws vbim::Error naming the file, line and key of whatever fails, before anything is returned.
ConfigResult configRun(const ConfigRequest& r);

}  // namespace vbim::runs
