#include "cli/option_checks.hpp"

#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <string>
#include <system_error>

#include "help/option_text.hpp"
#include "streams/disc/standard_input.hpp"

namespace vbim::cli {

namespace fs = std::filesystem;

namespace {

std::string fileProblem(const std::string& path, bool directory) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (!fs::exists(st)) return path + ": no such " + (directory ? "directory" : "file");
  if (directory && !fs::is_directory(st)) return path + ": is a file; expected a directory";
  if (!directory && fs::is_directory(st)) return path + ": is a directory; expected a file";
  if (::access(path.c_str(), R_OK) != 0)
    return path + ": cannot be read (" + std::generic_category().message(errno) + ")";
  return {};
}

// What an option's value is, in words, from its checks and type: "a file", "a number", ...
std::string expectedValue(CLI::Option& opt) {
  if (hasValidator(opt, "input file")) return "a file";
  if (hasValidator(opt, "input directory")) return "a directory";
  const std::string type = opt.get_type_name();
  if (type == "INT" || type == "UINT" || type == "FLOAT") return "a number";
  return "a value";
}

}  // namespace

bool hasValidator(CLI::Option& opt, const std::string& name) {
  try {
    return opt.get_validator(name) != nullptr;
  } catch (const CLI::OptionNotFound&) {
    return false;
  }
}

const CLI::Validator& inputFile() {
  static const CLI::Validator v([](std::string& s) { return fileProblem(s, false); }, "", "input file");
  return v;
}

const CLI::Validator& inputDirectory() {
  static const CLI::Validator v([](std::string& s) { return fileProblem(s, true); }, "", "input directory");
  return v;
}

const CLI::Validator& stdinAsFile() {
  static const CLI::Validator v(
      [](std::string& s) {
        if (s != "-") return std::string();
        std::string path;
        std::string problem = streams::readStandardInput(path);
        if (problem.empty()) s = path;
        return problem;
      },
      "", "stdin");
  return v;
}

const CLI::Validator& nonNegativeInteger() {
  static const CLI::Validator v([](std::string& s) { return help::wholeNumberProblem(s, false); }, "",
                                "non-negative integer");
  return v;
}

void checkNumbersStrictly(CLI::App& app) {
  static const CLI::Validator signedInteger([](std::string& s) { return help::wholeNumberProblem(s, true); }, "",
                                            "integer");
  static const CLI::Validator real([](std::string& s) { return help::numberProblem(s); }, "", "number");
  for (CLI::Option* opt : app.get_options({})) {
    std::string type = opt->get_type_name();
    if (const auto colon = type.find(':'); colon != std::string::npos) type = type.substr(0, colon);
    if (type == "UINT") {
      opt->check(nonNegativeInteger());
    } else if (type == "INT") {
      opt->check(signedInteger);
    } else if (type == "FLOAT") {
      opt->check(real);
    }
    if (!type.empty()) opt->type_name(type);
  }
  for (CLI::App* sub : app.get_subcommands({})) checkNumbersStrictly(*sub);
}

void refuseOptionsAsValues(CLI::App& app) {
  for (CLI::Option* opt : app.get_options({})) {
    if (!opt->nonpositional() || opt->get_type_size_min() <= 0) continue;  // flags and positionals
    const std::string expected = expectedValue(*opt);
    const std::string expectedIfEmpty = opt->check_lname("out") ? "the name of what to write" : expected;
    // transform() puts the check first, so it speaks before inputFile() says "no such file".
    opt->transform(CLI::Validator(
        [expected, expectedIfEmpty](std::string& s) {
          // An empty value (`--out ''`, an unset shell variable) would otherwise run the whole job
          // and fail only when the output is moved into place.
          if (s.empty()) return "is empty; expected " + expectedIfEmpty;
          return s.rfind("--", 0) == 0 ? "expects " + expected + ", got the option '" + s + "'" : std::string();
        },
        "", "not an option"));
  }
  for (CLI::App* sub : app.get_subcommands({})) refuseOptionsAsValues(*sub);
}

}  // namespace vbim::cli
