// Shared by the vbim subcommands: each cmd_*.cpp registers one subcommand on the app.
//
// Two programs: `vbim` holds the commands that play, inspect and profile (play, info, decode, config,
// vectors, replay, profile) and links only the model and small libraries (PLplot for the figures), so
// playback stays small (issue #7: under 64 MB) and starts without loading media libraries (issue
// #31); the commands that author and render (demo, author, lightmap, render) need OpenImageIO, FFmpeg
// and Mesa and live in `vbim-full` (which has every command), installed beside it, as does a profile
// that re-encodes. `vbim` hands those over by exec, so users always type `vbim ...`.
#pragma once

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace vbim::runs {
struct PlayResult;
}

namespace vbim::cli {

// Thrown by a subcommand to end the program with a message on stderr and an exit code.
class Exit : public std::runtime_error {
 public:
  Exit(int code, const std::string& message) : std::runtime_error(message), code_(code) {}
  int code() const { return code_; }

 private:
  int code_;
};

// Thrown by a command `vbim` cannot run itself (a sweep that re-encodes needs FFmpeg): cli/main.cpp
// catches it and hands the whole command line to vbim-full. Not a std::exception, so that runApp's
// error handling lets it through.
struct HandOverToFull {};

// A play's summary on stdout, after its health warning on stderr (`vbim play: ...`); play and demo.
void printPlayResult(const runs::PlayResult& result);

// A subcommand's name and one-line summary, shared by its registration and by `vbim --help`.
struct CommandInfo {
  const char* name;
  const char* summary;
};

inline constexpr CommandInfo kDemoCommand{"demo",
                                          "Run the main job on built-in defaults and write everything to out/demo/"};
inline constexpr CommandInfo kAuthorCommand{
    "author", "Author a VBIM stream (MPEG-2 PS, 2048-byte packs) from image sequences or Technique A"};
inline constexpr CommandInfo kLightmapCommand{"lightmap",
                                              "Generate day/night terrain lightmaps and sky domes with Technique A"};
inline constexpr CommandInfo kRenderCommand{
    "render", "Render the frames of a play run with OSMesa (pictures, contact sheet, video)"};
inline constexpr CommandInfo kProfileCommand{
    "profile", "Sweep ring size, bitrate, faults and policy; find the longest survivable stall"};
// The commands only `vbim-full` has (`vbim profile` runs in both; vbim-full re-encodes).
inline constexpr std::array kFullOnlyCommands{kDemoCommand, kAuthorCommand, kLightmapCommand, kRenderCommand};

// The tool's name, description and version (both programs).
void configureApp(CLI::App& app);
// Adds what every command shares (cli/common_options.hpp) and the checks of every value
// (cli/option_checks.hpp): the tree as it is parsed, and as --generate describes it.
void prepareApp(CLI::App& app);
// Parses and runs (after prepareApp); every error becomes `vbim CMD: message` on stderr and exit 2 (bad usage or
// input) or 1 (a failure while running: runs::RunFailure, an output that cannot be written).
int runApp(CLI::App& app, int argc, char** argv);
// argv with `vbim help CMD ...` turned into `vbim CMD ... --help` (null-terminated, for exec too).
std::vector<char*> helpAsOption(int argc, char** argv);
// The commands both programs have: play, info, decode, config, vectors, replay (and profile, which
// each program adds with its encoders: cli/profile_plan.hpp).
void addCoreCommands(CLI::App& app);

void addDemo(CLI::App& app);
void addPlay(CLI::App& app);
void addAuthor(CLI::App& app);
void addInfo(CLI::App& app);
void addDecode(CLI::App& app);
void addLightmap(CLI::App& app);
void addRender(CLI::App& app);
void addConfig(CLI::App& app);
void addVectors(CLI::App& app);
void addReplay(CLI::App& app);

}  // namespace vbim::cli
