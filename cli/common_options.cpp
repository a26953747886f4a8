#include "cli/common_options.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <streambuf>
#include <system_error>
#include <vector>

#include "gs/params.hpp"
#include "help/status_text.hpp"
#include "runtime/error.hpp"

namespace vbim::cli {

namespace {

Verbosity& level() {
  static Verbosity v = Verbosity::Normal;
  return v;
}

// A stream buffer that drops everything (std::cout under --quiet).
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return traits_type::not_eof(c); }
  std::streamsize xsputn(const char* /*s*/, std::streamsize n) override { return n; }
};

std::streambuf*& originalStdout() {
  static std::streambuf* buffer = nullptr;
  return buffer;
}

void beQuiet() {
  // Never destroyed: std::cout is flushed by std::ios_base::Init's destructor after every
  // function-local static is gone, and a destroyed sink there is a use after free (ASan saw it).
  static NullBuffer* const sink = new NullBuffer;
  level() = Verbosity::Quiet;
  if (originalStdout() == nullptr) originalStdout() = std::cout.rdbuf(sink);
}

}  // namespace

CLI::Validator oneOf(const std::string& option, std::vector<std::string> values) {
  std::string set, words;
  for (std::size_t i = 0; i < values.size(); ++i) {
    set += (i ? "," : "") + values[i];
    words += (i == 0 ? "" : i + 1 == values.size() ? " or " : ", ") + values[i];
  }
  return {[option, values = std::move(values), words](std::string& value) {
            if (std::find(values.begin(), values.end(), value) != values.end()) return std::string();
            // vbim::Error, not CLI11's "NAME: text": the message the library's own check gives.
            throw Error(option + " '" + value + "': expected " + words);
          },
          "{" + set + "}", "one of"};
}

CLI::Validator catchupPolicy() {
  return oneOf("--policy", std::vector<std::string>(gs::kCatchupPolicies.begin(), gs::kCatchupPolicies.end()));
}

void addCommonOptions(CLI::App& app) {
  for (CLI::App* sub : app.get_subcommands({})) {
    const CLI::Option* out = nullptr;
    bool json = false;
    for (const CLI::Option* opt : sub->get_options({})) {
      if (opt->check_lname("out")) out = opt;
      json = json || opt->check_lname("json");
    }
    if (out == nullptr) continue;
    if (!out->check_sname("o")) {
      throw std::logic_error("vbim " + sub->get_name() + ": --out is registered without -o");
    }
    CLI::Option* quiet = sub->add_flag_callback(
        "-q,--quiet", [] { beQuiet(); },
        json ? "No progress and no summary: only warnings and errors (and --json)"
             : "No progress and no summary: only warnings and errors");
    CLI::Option* verbose = sub->add_flag_callback(
        "-v,--verbose", [] { level() = Verbosity::Verbose; },
        "Progress lines even into a log or pipe, and every file written with its size");
    quiet->excludes(verbose);
  }
}

Verbosity verbosity() {
  return level();
}

std::ostream& requestedOut() {
  static std::ostream out(nullptr);
  out.rdbuf(originalStdout() != nullptr ? originalStdout() : std::cout.rdbuf());
  return out;
}

void listWritten(const CLI::App& command) {
  if (level() != Verbosity::Verbose) return;
  std::vector<std::filesystem::path> outputs;
  for (const CLI::Option* opt : command.get_options({})) {
    if ((opt->check_lname("out") || opt->check_lname("iso")) && opt->count() > 0) {
      outputs.emplace_back(opt->as<std::string>());
    }
  }
  for (const std::filesystem::path& out : outputs) {
    std::error_code ec;
    std::vector<std::filesystem::path> files;
    if (std::filesystem::is_directory(out, ec)) {
      for (const auto& e : std::filesystem::recursive_directory_iterator(out, ec)) {
        if (e.is_regular_file(ec)) files.push_back(e.path());
      }
    } else if (std::filesystem::is_regular_file(out, ec)) {
      files.push_back(out);
    }
    std::sort(files.begin(), files.end());
    for (const std::filesystem::path& f : files) {
      std::cerr << "vbim " << command.get_name() << ": wrote " << f.string() << " ("
                << help::sizeText(std::filesystem::file_size(f, ec)) << ")\n";
    }
  }
}

CLI::Option* addPngLevelOption(CLI::App& cmd, int& level) {
  return cmd
      .add_option("--png-level", level,
                  "PNG compression (zlib's level): 0 stores the pixels (fastest, ~2.5x the bytes), 1 to 9 compress (1: "
                  "about libpng's default size, ~3x the CPU of 0; docs/player.md, \"Saving frames\")")
      ->capture_default_str();
}

}  // namespace vbim::cli
