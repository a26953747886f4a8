#include "cli/generate_docs.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli/app_doc.hpp"
#include "cli/command.hpp"
#include "help/man_page.hpp"
#include "help/shell_completion.hpp"

namespace vbim::cli {

int runGenerate(CLI::App& app, const std::string& kind, const std::string& file) {
  prepareApp(app);
  std::string text;
  try {
    text = generateDocs(app, kind);
  } catch (const Exit& e) {
    std::cerr << "vbim: " << e.what() << "\n";
    return e.code();
  }
  if (file.empty()) {
    std::cout << text;
    return 0;
  }
  // Written under a temporary name and renamed, so a build never installs half a page.
  const std::string partial = file + ".partial";
  std::ofstream out(partial, std::ios::binary);
  out << text;
  out.close();
  std::error_code ec;
  if (out) std::filesystem::rename(partial, file, ec);
  if (!out || ec) {
    std::filesystem::remove(partial, ec);
    std::cerr << "vbim: --generate " << kind << ": cannot write " << file << "\n";
    return 1;
  }
  return 0;
}

std::string generateDocs(CLI::App& app, const std::string& kind) {
  if (kind == "man") return help::manPage(programDoc(app));
  if (kind == "bash") return help::bashCompletion(programDoc(app));
  if (kind == "zsh") return help::zshCompletion(programDoc(app));
  throw Exit(2, "--generate '" + kind + "': expected man, bash or zsh");
}

}  // namespace vbim::cli
