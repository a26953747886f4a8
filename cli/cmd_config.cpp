// vbim config: prints the platform config with every default and its source, or checks a config
// file (and optionally a fault plan) the way `vbim play` will read them.
#include <iostream>

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "cli/platform_params.hpp"
#include "config/fault_plan_toml.hpp"
#include "config/params_toml.hpp"
#include "iop/fault_plan.hpp"

namespace vbim::cli {

namespace {

struct ConfigOptions {
  bool defaults = false;
  bool markdown = false;
  std::string check;
  std::string faults;
};

void runConfig(const ConfigOptions& o) {
  PlatformParams params;
  ParamTable table;
  describePlatform(table, params);
  try {
    if (!o.check.empty()) {
      config::applyTomlFile(table, o.check);
      validatePlatform(params);
    }
    if (!o.faults.empty()) {
      const iop::FaultPlan plan = config::loadFaultPlan(o.faults);
      std::cerr << o.faults << ": " << plan.faults.size() << " fault(s), valid\n";
    }
  } catch (const ConfigError& e) {
    throw Exit(2, e.what());
  } catch (const std::exception& e) {
    throw Exit(2, e.what());
  }
  if (!o.check.empty()) std::cerr << o.check << ": valid; the effective config follows\n";
  if (o.markdown) {
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
  cmd->add_option("--check", opts->check, "A platform config (TOML) to validate; prints the effective config")
      ->check(inputFile());
  cmd->add_option("--faults", opts->faults, "A fault plan (TOML) to validate")->check(inputFile());
  cmd->footer(
      "Examples:\n"
      "  vbim config > platform.toml\n"
      "  vbim config --check platform.toml --faults plan.toml\n");
  cmd->callback([opts] { runConfig(*opts); });
}

}  // namespace vbim::cli
