#include "cli/app_doc.hpp"

#include <string>
#include <vector>

#include "cli/exit_status.hpp"
#include "cli/option_checks.hpp"
#include "help/option_text.hpp"

namespace vbim::cli {

namespace {

std::vector<std::string> optionNames(const CLI::Option& opt) {
  std::vector<std::string> names;
  for (const std::string& s : opt.get_snames()) names.push_back("-" + s);
  for (const std::string& l : opt.get_lnames()) names.push_back("--" + l);
  return names;
}

// What the option's value is, from its own checks and type (the same definitions --help shows).
void describeValue(CLI::Option& opt, help::OptionDoc& doc) {
  // A flag takes none: CLI11 gives it a type size of 1 like any option, and expects no item.
  if (opt.get_expected_max() <= 0) {
    doc.value = help::ValueKind::None;
    return;
  }
  doc.list = opt.get_delimiter() != '\0';
  // get_type_name() is the type and every validator's description: "TEXT:{png,exr}".
  const std::string typeName = opt.get_type_name();
  doc.choices = help::choicesIn(typeName);  // CLI::IsMember's, CLI::CheckedTransformer's, cli::oneOf's
  const std::string type = typeName.substr(0, typeName.find(':'));
  if (!doc.choices.empty()) {
    doc.value = help::ValueKind::Choice;
  } else if (type == "INT" || type == "UINT" || type == "FLOAT") {
    doc.value = help::ValueKind::Number;
  } else if (hasValidator(opt, "input directory") || hasValidator(opt, "DIR")) {
    doc.value = help::ValueKind::Directory;
  } else {
    doc.value = help::ValueKind::File;
  }
}

help::OptionDoc optionDoc(CLI::Option& opt, const CLI::Formatter* formatter) {
  help::OptionDoc doc;
  doc.description = opt.get_description();
  if (!opt.nonpositional()) {
    doc.positional = true;
    doc.names = {opt.get_name()};
    doc.many = opt.get_items_expected_max() > 1;
    return doc;
  }
  doc.names = optionNames(opt);
  // --help's text after the names (" TEXT=png"), without the leading spaces.
  const std::string opts = formatter != nullptr ? formatter->make_option_opts(&opt) : std::string();
  if (!opts.empty()) doc.valueText = opts.substr(opts.find_first_not_of(' '));
  describeValue(opt, doc);
  return doc;
}

}  // namespace

help::ProgramDoc programDoc(CLI::App& app) {
  const auto formatter = std::dynamic_pointer_cast<CLI::Formatter>(app.get_formatter());
  help::ProgramDoc doc;
  doc.version = VBIM_VERSION;
  doc.description = app.get_description();
  doc.footer = app.get_footer();
  for (CLI::Option* opt : app.get_options({})) {
    if (opt->nonpositional()) doc.options.push_back(optionDoc(*opt, formatter.get()));
  }
  // The commands as --help lists them (named, not the program's own help).
  for (CLI::App* sub : app.get_subcommands({})) {
    if (sub->get_name().empty()) continue;
    help::CommandDoc cmd{sub->get_name(), sub->get_description(), sub->get_footer(), {}};
    for (CLI::Option* opt : sub->get_options({})) cmd.options.push_back(optionDoc(*opt, formatter.get()));
    doc.commands.push_back(std::move(cmd));
  }
  doc.exits.done = kExitDone;
  doc.exits.failure = kExitFailure;
  doc.exits.badInput = kExitBadInput;
  doc.exits.shardsMissing = kExitShardsMissing;
  for (const StopSignal& s : kStopSignals) doc.exits.signals.push_back({s.name, exitForSignal(s.number)});
  return doc;
}

}  // namespace vbim::cli
