// vbim config: prints the platform config with every default and its source, or checks a config
// file (and optionally a fault plan) the way `vbim play` will read them: the same key ranges, the
// same relations between keys, and the same GS checks (runs/console_check.hpp) for the stream given
// with --stream, or for the smallest lightmap when none is given (a config no stream can play).
// The config, the checks and the GS setup are runs::configRun (runs/config_run.hpp).
#include <iostream>
#include <memory>

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "runs/config_run.hpp"

namespace vbim::cli {

namespace {

void runConfig(const runs::ConfigRequest& r) {
  const runs::ConfigResult result = runs::configRun(r);
  // A check that passes is one line (on stdout), unless a config or the GS setup is asked for too:
  // then the line goes to stderr, before it.
  (result.document.empty() ? std::cout : std::cerr) << result.verdict;
  std::cout << result.document;
}

}  // namespace

void addConfig(CLI::App& app) {
  auto opts = std::make_shared<runs::ConfigRequest>();
  auto* cmd = app.add_subcommand(
      "config", "Print the platform config (every timing constant, with sources), or check a config / fault plan");
  cmd->add_flag("--defaults", opts->defaults, "Print the defaults as TOML (the default action)");
  cmd->add_flag("--markdown", opts->markdown, "Print a Markdown table instead of TOML");
  auto* check =
      cmd->add_option("--check", opts->check, "A platform config (TOML) to validate; prints one line when it passes")
          ->check(inputFile());
  cmd->add_flag("--effective", opts->effective,
                "With --check: print the effective config too (the file's values over the defaults)")
      ->needs(check);
  cmd->add_option("--faults", opts->faults, "A fault plan (TOML) to validate")->check(inputFile());
  auto* stream =
      cmd->add_option("--stream", opts->stream,
                      "Check the GS settings against this stream or disc image's frame sizes (VRAM layout), and the "
                      "fault plan's file names and LBAs against the disc, as `vbim play` will; without it, against the "
                      "smallest lightmap")
          ->check(inputFile());
  cmd->add_option("--file", opts->file, "The stream on a disc image given with --stream (default: its only one)");
  cmd->add_flag("--gs-setup", opts->gsSetup,
                "Print the GS setup for the stream instead of the config: the VRAM plan, and the register writes "
                "of the lightmap's and the sky's blend draws with their values (docs/porting.md)")
      ->needs(stream)
      ->excludes("--markdown");
  cmd->add_option("--format", opts->format,
                  "With --gs-setup: markdown (the register tables), gif (the GIF packets to send by PATH3, each "
                  "qword's bytes) or c (the same packets as C arrays)")
      ->check(CLI::IsMember({"markdown", "gif", "c"}))
      ->needs("--gs-setup")
      ->capture_default_str();
  cmd->footer(
      "Examples:\n"
      "  vbim config > platform.toml\n"
      "  vbim config --check platform.toml --faults plan.toml\n"
      "  vbim config --check platform.toml --effective > effective.toml\n"
      "  vbim config --check platform.toml --stream streams/samples/day_clear.vbim\n"
      "  vbim config --gs-setup --stream streams/samples/day_clear.vbim\n"
      "  vbim config --gs-setup --format c --stream streams/samples/day_clear.vbim > vbim_packets.h\n");
  cmd->callback([opts] { runConfig(*opts); });
}

}  // namespace vbim::cli
