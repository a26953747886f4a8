// Test support: run a command line (the vbim binary, ffprobe, ...) as a user would, and read files.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

namespace vbim::testing {

struct CommandResult {
  int status = -1;     // exit status, or -1 if it did not exit normally
  std::string output;  // stdout and stderr together
};

// Runs `cmd` through the shell with stderr folded into stdout.
inline CommandResult runCommand(const std::string& cmd) {
  CommandResult r;
  FILE* p = ::popen((cmd + " 2>&1").c_str(), "r");
  if (p == nullptr) return r;
  std::array<char, 4096> buf{};
  for (std::size_t n; (n = std::fread(buf.data(), 1, buf.size(), p)) > 0;) r.output.append(buf.data(), n);
  const int st = ::pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

// Runs `program args`: the program a test was built against (VBIM_BINARY, ...), as runCommand does.
inline CommandResult runProgram(const std::string& program, const std::string& args) {
  return runCommand(program + " " + args);
}

// The same, run from the directory `cwd` (a program's defaults must not depend on where it is run).
inline CommandResult runProgram(const std::string& program, const std::string& args, const std::filesystem::path& cwd) {
  std::string quotedCwd = "'";
  for (char c : cwd.string()) quotedCwd += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return runCommand("cd " + quotedCwd + "' && " + program + " " + args);
}

// The whole file, or "<missing PATH>" so a comparison against it fails with a clear value.
inline std::string readFileBytes(const std::filesystem::path& path) {
  std::string data;
  FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) return "<missing " + path.string() + ">";
  std::array<char, 4096> buf{};
  for (std::size_t n; (n = std::fread(buf.data(), 1, buf.size(), f)) > 0;) data.append(buf.data(), n);
  std::fclose(f);
  return data;
}

// Writes `text` to `path` (a config or fault plan for a test); false if it cannot.
inline bool writeTextFile(const std::filesystem::path& path, const std::string& text) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) return false;
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  return std::fclose(f) == 0 && ok;
}

}  // namespace vbim::testing
