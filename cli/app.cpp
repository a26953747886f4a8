// What both programs share: the app's description, `vbim help CMD`, the --help layout, and the one
// error convention of every command (docs/cli.md):
//   vbim CMD: message            on stderr
//   exit 2                       bad usage or bad input (an argument, a file, a config, a stream)
//   exit 1                       a failure while running (a file that cannot be written, ...)
// A usage error prints one line and `see 'vbim CMD --help'`, not the whole help.
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <new>
#include <string>
#include <string_view>
#include <system_error>

#include "cli/command.hpp"
#include "cli/common_options.hpp"
#include "cli/exit_status.hpp"
#include "cli/interrupt.hpp"
#include "cli/option_checks.hpp"
#include "cli/suggest.hpp"
#include "help/option_text.hpp"
#include "runs/error.hpp"
#include "runtime/error.hpp"
#include "streams/disc/standard_input.hpp"
#include "sweep/outputs/study.hpp"

namespace vbim::cli {

namespace {

// "vbim play: " for the command the user typed ("vbim: " before one is known).
std::string prefixFor(CLI::App& app, int argc, char** argv) {
  if (argc > 1 && subcommandNamed(app, argv[1]) != nullptr) return "vbim " + std::string(argv[1]) + ": ";
  return "vbim: ";
}

// --help lines show `--seed UINT=1`: CLI11 would append its validators' names to the type
// (`INT:NONNEGATIVE`, `TEXT:FILE`), which say nothing to a user; the help text says the range.
class HelpFormatter : public CLI::Formatter {
 public:
  std::string make_option_opts(const CLI::Option* opt) const override {
    return help::plainTypeText(CLI::Formatter::make_option_opts(opt), opt->get_type_name());
  }
};

}  // namespace

void configureApp(CLI::App& app) {
  app.description(
      "vbim: a simulator of the PlayStation 2 video-based illumination map pipeline\n"
      "(DVD -> IOP stream ring -> SIF -> EE demux -> IPU decode -> GS blend, on a simulated clock)");
  app.name("vbim");
  app.set_version_flag("-V,--version", "vbim " VBIM_VERSION);
  app.add_subcommand("version", "Print the version (as vbim --version)")->callback([] {
    std::cout << "vbim " VBIM_VERSION "\n";
  });
  app.require_subcommand(1);
  app.fallthrough(false);
  app.formatter(std::make_shared<HelpFormatter>());
  app.footer("'vbim help CMD' or 'vbim CMD --help' shows a command's options, defaults and examples.");
}

void addCoreCommands(CLI::App& app) {
  addPlay(app);
  addInfo(app);
  addDecode(app);
  addConfig(app);
  addVectors(app);
  addReplay(app);
}

std::vector<char*> helpAsOption(int argc, char** argv) {
  std::vector<char*> out(argv, argv + argc);
  static char helpFlag[] = "--help";
  if (argc >= 2 && std::string_view(argv[1]) == "help") {
    out.erase(out.begin() + 1);  // "vbim help play ..." is "vbim play --help"
    out.push_back(helpFlag);
  }
  out.push_back(nullptr);
  return out;
}

void prepareApp(CLI::App& app) {
  addCommonOptions(app);
  checkNumbersStrictly(app);
  refuseOptionsAsValues(app);
}

int runApp(CLI::App& app, int argc, char** argv) {
  installInterruptHandlers();
  prepareApp(app);
  const std::vector<char*> args = helpAsOption(argc, argv);
  argc = static_cast<int>(args.size()) - 1;
  argv = const_cast<char**>(args.data());
  // A first word that is neither an option nor a subcommand gets a plain answer.
  if (argc > 1 && argv[1][0] != '-' && subcommandNamed(app, argv[1]) == nullptr) {
    std::cerr << "vbim: " << unknownCommand(app, argv[1]) << "; see 'vbim --help'\n";
    return kExitBadInput;
  }
  const std::string prefix = prefixFor(app, argc, argv);
  const std::string seeHelp =
      argc > 1 && argv[1][0] != '-' ? "see 'vbim " + std::string(argv[1]) + " --help'" : "see 'vbim --help'";
  // An unknown option is named first: CLI11 would complain of a missing --out when --outt was meant.
  if (const auto unknown = unknownOption(app, argc, argv)) {
    std::cerr << prefix << *unknown << "; " << seeHelp << "\n";
    return kExitBadInput;
  }
  try {
    app.parse(argc, argv);
    for (const CLI::App* sub : app.get_subcommands()) listWritten(*sub);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() != 0) {
      std::cerr << prefix << streams::nameStandardInput(e.what()) << "; " << seeHelp << "\n";
      return kExitBadInput;
    }
    return app.exit(e);  // --help, --version
  } catch (const Exit& e) {
    std::cerr << prefix << streams::nameStandardInput(e.what()) << "\n";
    return e.code();
  } catch (const sweep::MissingShards& e) {
    // docs/sweeps.md: a merge with shards to re-run, told apart from a bad request.
    std::cerr << prefix << streams::nameStandardInput(e.what()) << "\n";
    return kExitShardsMissing;
  } catch (const runs::RunFailure& e) {
    // A library call failed while it ran (an output that cannot be written): not the input's fault.
    std::cerr << prefix << streams::nameStandardInput(e.what()) << "\n";
    return kExitFailure;
  } catch (const Error& e) {
    // The project's own errors name the input and what was expected: bad input.
    std::cerr << prefix << streams::nameStandardInput(e.what()) << "\n";
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    std::cerr << prefix << "out of memory (the input or the options ask for more than this machine has)\n";
    return kExitFailure;
  } catch (const std::filesystem::filesystem_error& e) {
    std::cerr << prefix << streams::nameStandardInput(e.path1().string()) << ": " << e.code().message() << "\n";
    return kExitFailure;
  } catch (const std::system_error& e) {
    std::cerr << prefix << "system error: " << e.code().message() << "\n";
    return kExitFailure;
  } catch (const std::exception& e) {
    std::cerr << prefix << "internal error (" << e.what() << "); please report it with the command line\n";
    return kExitFailure;
  }
  return kExitDone;
}

}  // namespace vbim::cli
