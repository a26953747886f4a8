// Shared by the vbim subcommands: each cmd_*.cpp registers one subcommand on the app.
#pragma once

#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>

namespace vbim::cli {

// Thrown by a subcommand to end the program with a message on stderr and an exit code.
class Exit : public std::runtime_error {
 public:
  Exit(int code, const std::string& message) : std::runtime_error(message), code_(code) {}
  int code() const { return code_; }

 private:
  int code_;
};

// For subcommands whose issue is still open: says so and exits non-zero; never pretends to work.
[[noreturn]] inline void notYetAvailable(const std::string& name, int issue) {
  throw Exit(3, "vbim " + name + ": not yet available (tracked in issue #" + std::to_string(issue) + ")");
}

void addDemo(CLI::App& app);
void addPlay(CLI::App& app);
void addProfile(CLI::App& app);
void addAuthor(CLI::App& app);
void addInfo(CLI::App& app);
void addDecode(CLI::App& app);
void addLightmap(CLI::App& app);
void addRender(CLI::App& app);
void addConfig(CLI::App& app);

}  // namespace vbim::cli
