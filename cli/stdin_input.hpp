// "-" for an input stream: `vbim info -`, `vbim play -`, `vbim decode -` read the stream from
// standard input. The readers take a path and seek (ISO 9660 images, the sector reader), so stdin is
// read whole into an anonymous in-memory file (memfd_create: nothing on disk to clean up, even after
// SIGKILL), reached by its /proc/self/fd path. Messages and summaries name it "<stdin>".
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace vbim::cli {

// A transform for an input option: "-" becomes the path of standard input's bytes (read on first
// use; once per process: a second "-" is refused), any other value is left as it is. Register it
// before the option's check(inputFile()).
const CLI::Validator& stdinAsFile();

// True when `path` is where stdinAsFile() put standard input.
bool isStdin(const std::string& path);

// `text` with the path of standard input's bytes written as "<stdin>" (messages, summaries).
std::string nameStdin(std::string text);

}  // namespace vbim::cli
