// "-" for an input stream: `vbim info -`, `vbim play -`, `vbim decode -` read the stream from
// standard input. The readers take a path and seek (ISO 9660 images, the sector reader), so stdin is
// read whole into an anonymous in-memory file (memfd_create: nothing on disk to clean up, even after
// SIGKILL), reached by its /proc/self/fd path. Messages and summaries name it "<stdin>".
#pragma once

#include <cstdint>
#include <string>

namespace vbim::streams {

// The most standard input may hold: a dual-layer DVD (DVD-9, ECMA-267) holds 4,173,824 sectors of
// 2,048 bytes, the largest disc a stream comes from. More is refused, not held in memory: `vbim info -
// < /dev/urandom` must end with a message, not fill the machine.
inline constexpr std::uint64_t kStdinLimitBytes = 4'173'824ULL * 2048;

// Copies everything `fd` gives, at most `limit` bytes, into a new anonymous memory file (memfd) and
// returns its descriptor; or -1 with `problem` saying why (naming "<stdin>").
int copyIntoMemoryFile(int fd, std::uint64_t limit, std::string& problem);

// Reads standard input into a memory file (once per process: a second call is refused) and sets
// `path` to where it can be opened; returns "" on success, else what went wrong.
std::string readStandardInput(std::string& path);

// True when `path` is where readStandardInput() put standard input.
bool isStandardInput(const std::string& path);

// `text` with the path of standard input's bytes written as "<stdin>" (messages, summaries).
std::string nameStandardInput(std::string text);

}  // namespace vbim::streams
