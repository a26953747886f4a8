// vbim vectors: the known-answer vectors a console port checks itself against (docs/porting.md,
// "Known-answer vectors"). --out DIR writes them; --check DIR compares a port's captured files with
// them and names the first difference (exit 1).
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "cli/output_dir.hpp"
#include "player/known_answers.hpp"
#include "runtime/error.hpp"

namespace vbim::cli {

namespace {

struct VectorsRequest {
  std::vector<std::string> streams{"streams/samples/day_clear.vbim", "streams/samples/day_weather.vbim"};
  std::string out;
  std::string check;
  bool force = false;
};

std::optional<std::string> readText(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  if (!f) return std::nullopt;
  return std::string(std::istreambuf_iterator<char>(f), {});
}

std::vector<player::VectorFile> generate(const VectorsRequest& r) {
  std::vector<std::vector<std::uint8_t>> bytes;
  std::vector<player::VectorStream> streams;
  bytes.reserve(r.streams.size());
  for (const std::string& path : r.streams) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw Exit(2, "--stream " + path + ": cannot open the stream file");
    bytes.emplace_back(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    streams.push_back(player::VectorStream{std::filesystem::path(path).stem().string(), bytes.back()});
  }
  try {
    return player::knownAnswerVectors(streams);
  } catch (const ConfigError& e) {
    throw Exit(2, e.what());
  }
}

void run(const VectorsRequest& r) {
  if (r.out.empty() == r.check.empty()) throw Exit(2, "give exactly one of --out DIR and --check DIR");
  if (!r.check.empty() && !std::filesystem::is_directory(r.check)) {
    throw Exit(2, "--check " + r.check + ": not a directory");
  }
  if (!r.out.empty()) refuseExistingOutputDir(outputPath(r.out), r.force);
  const std::vector<player::VectorFile> files = generate(r);
  if (!r.out.empty()) {
    OutputDir dir(r.out, r.force);
    std::size_t entries = 0;
    for (const player::VectorFile& f : files) {
      std::ofstream o(dir.path(f.name), std::ios::binary);
      o << f.text;
      if (!o) throw Exit(1, dir.path(f.name).string() + ": cannot write");
      for (char c : f.text) entries += c == '\n' ? 1 : 0;
    }
    dir.commit();
    std::cout << "wrote " << files.size() << " vector files (" << entries << " lines) to " << r.out << "\n";
    return;
  }
  for (const player::VectorFile& f : files) {
    const std::filesystem::path p = std::filesystem::path(r.check) / f.name;
    const std::optional<std::string> found = readText(p);
    if (const auto d = player::compareVectors(f, found ? &*found : nullptr)) {
      throw Exit(1, (std::filesystem::path(r.check) / d->file).string() + ": entry '" + d->entry + "': expected '" +
                        d->expected + "', found '" + d->found + "'");
    }
  }
  std::cout << "all " << files.size() << " vector files in " << r.check << " match\n";
}

}  // namespace

void addVectors(CLI::App& app) {
  auto r = std::make_shared<VectorsRequest>();
  auto* cmd = app.add_subcommand(
      "vectors", "Write the timing-independent known-answer vectors for a port, or check a port's against them");
  cmd->add_option("--out", r->out, "Write the vector files into this directory (complete or not at all)");
  cmd->add_option("--check", r->check, "Compare the vector files in this directory; name the first difference");
  cmd->add_option("--stream", r->streams, "Stream files whose pictures become IPU vectors (repeatable)")
      ->check(inputFile())
      ->capture_default_str();
  cmd->add_flag("--force", r->force, "Replace a non-empty output directory");
  cmd->footer(
      "Examples:\n"
      "  vbim vectors --out tests/vectors --force\n"
      "  vbim vectors --check tests/vectors\n");
  cmd->callback([r] { run(*r); });
}

}  // namespace vbim::cli
