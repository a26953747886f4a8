// vbim config: prints the platform config with every default and its source, or checks a config
// file (and optionally a fault plan) the way `vbim play` will read them: the same key ranges, the
// same relations between keys, and the same GS checks (runs/console_check.hpp) for the stream given
// with --stream, or for the smallest lightmap when none is given (a config no stream can play).
#include <iostream>
#include <memory>
#include <optional>

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "config/fault_plan_toml.hpp"
#include "config/option_values.hpp"
#include "config/params_toml.hpp"
#include "gs/setup_listing.hpp"
#include "iop/fault_plan.hpp"
#include "player/platform_config.hpp"
#include "runs/console_check.hpp"
#include "streams/disc/stream_disc.hpp"

namespace vbim::cli {

namespace {

struct ConfigOptions {
  bool defaults = false;
  bool markdown = false;
  bool gsSetup = false;
  bool effective = false;           // with --check: print the effective config too
  std::string format = "markdown";  // --gs-setup's: markdown, gif or c
  std::string check;
  std::string faults;
  std::string stream;
  std::string file;
};

// The stream given with --stream, opened once: its frame sizes for the GS checks, and the disc a
// fault plan's file names are looked up on. Empty without --stream.
std::optional<streams::StreamDisc> openGivenStream(const ConfigOptions& o) {
  if (o.stream.empty()) return std::nullopt;
  return streams::openStreamDisc(o.stream, o.file);
}

void runConfig(const ConfigOptions& o) {
  player::PlatformConfig params;
  ParamTable table;
  player::describeParams(table, params);
  std::optional<gs::VramLayout> vram;  // checked with --check or --stream (--gs-setup needs --stream)
  if (!o.check.empty()) {
    config::applyTomlFile(table, o.check);
    player::validate(params);
  }
  const std::optional<streams::StreamDisc> given = openGivenStream(o);
  const streams::StreamDisc* disc = given ? &*given : nullptr;
  const runs::PresentedSizes presented = runs::presentedSizes(disc);
  if (!o.check.empty() || disc != nullptr) vram = runs::checkPresenters(presented, params, o.check);
  // A check that passes is one line (on stdout), unless a config or the GS setup is asked for too:
  // then the line goes to stderr, before it.
  const bool checking = !o.check.empty() || !o.stream.empty() || !o.faults.empty();
  const bool printing = !checking || o.gsSetup || o.markdown || o.defaults || o.effective;
  std::ostream& verdict = printing ? std::cerr : std::cout;
  if (!o.faults.empty()) {
    // With --stream, entries that name a file (file = "\\DATA\\DAY.VBI;1") are looked up on that
    // disc and LBAs checked against its size, as play does.
    const iop::FaultPlan plan = config::loadFaultPlan(o.faults, disc != nullptr ? disc->disc.get() : nullptr);
    verdict << o.faults << ": " << plan.faults.size() << " fault(s), valid\n";
  }
  if (!o.check.empty() || !o.stream.empty()) {
    verdict << (o.check.empty() ? std::string("the default platform config") : o.check)
            << (o.stream.empty() ? "" : " with " + o.stream) << ": valid";
    if (printing) verdict << "; the " << (o.gsSetup ? "GS setup" : "effective config") << " follows";
    verdict << "\n";
  }
  if (!printing) return;
  if (o.gsSetup && o.format != "markdown") {
    gs::writeGsPackets(std::cout, params.gs, *vram, presented.lightmap, presented.sky,
                       o.format == "c" ? gs::PacketFormat::C : gs::PacketFormat::Gif, o.stream);
  } else if (o.gsSetup) {
    gs::writeGsSetup(std::cout, params.gs, *vram, presented.lightmap, presented.sky);
  } else if (o.markdown) {
    table.writeMarkdown(std::cout);
  } else {
    std::cout << "# vbim platform config: every timing constant, its default and its source.\n"
              << "# Pass a copy to `vbim play --config FILE`; keys left out keep their defaults.\n\n";
    table.writeToml(std::cout);
  }
}

}  // namespace

void addConfig(CLI::App& app) {
  auto opts = std::make_shared<ConfigOptions>();
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
