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
#include "cli/samples.hpp"
#include "player/known_answers.hpp"
#include "runtime/error.hpp"

namespace vbim::cli {

namespace {

// Without --stream: the two sample streams, wherever vbim finds them (cli/samples.hpp), so the
// vectors do not depend on the directory vbim is run from.
const std::vector<std::string> kDefaultStreams{"day_clear.vbim", "day_weather.vbim"};

struct VectorsRequest {
  std::vector<std::string> streams;  // --stream; empty: kDefaultStreams
  std::string out;
  std::string check;
  std::string idct = ipu::idctKindName(ipu::kDefaultIdct);
  bool force = false;
};

std::optional<std::string> readText(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  if (!f) return std::nullopt;
  return std::string(std::istreambuf_iterator<char>(f), {});
}

// The sample streams' paths; Exit(2) naming where they were looked for when they are not there.
std::vector<std::string> defaultStreams() {
  const std::optional<std::filesystem::path> dir = findSamples(kDefaultStreams);
  if (!dir) {
    std::string searched;
    for (const std::filesystem::path& d : sampleDirectories()) searched += (searched.empty() ? "" : ", ") + d.string();
    throw Exit(2, "cannot find the sample streams " + kDefaultStreams[0] + " and " + kDefaultStreams[1] +
                      " (looked in " + searched + "); name the streams with --stream FILE");
  }
  std::vector<std::string> paths;
  paths.reserve(kDefaultStreams.size());
  for (const std::string& name : kDefaultStreams) paths.push_back((*dir / name).string());
  return paths;
}

std::vector<player::VectorFile> generate(const VectorsRequest& r) {
  const std::vector<std::string> paths = r.streams.empty() ? defaultStreams() : r.streams;
  std::vector<std::vector<std::uint8_t>> bytes;
  std::vector<player::VectorStream> streams;
  bytes.reserve(paths.size());
  for (const std::string& path : paths) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw Exit(2, (r.streams.empty() ? "" : "--stream ") + path + ": cannot open the stream file");
    bytes.emplace_back(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    streams.push_back(player::VectorStream{std::filesystem::path(path).stem().string(), bytes.back()});
  }
  return player::knownAnswerVectors(streams, ipu::idctKindByName(r.idct).value_or(ipu::kDefaultIdct));
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
  cmd->add_option("--stream", r->streams,
                  "Stream files whose pictures become IPU vectors (repeatable; default: the samples day_clear.vbim "
                  "and day_weather.vbim, from share/vbim/samples beside an installed vbim or the source tree)")
      ->check(inputFile());
  cmd->add_option("--idct", r->idct, "The platform's inverse DCT (ipu.idct): pcsx2, libmpeg2 or exact")
      ->capture_default_str()
      ->check(CLI::IsMember({"pcsx2", "libmpeg2", "exact"}));
  cmd->add_flag("--force", r->force, "Replace a non-empty output directory");
  cmd->footer(
      "Examples:\n"
      "  vbim vectors --out tests/vectors --force\n"
      "  vbim vectors --check tests/vectors\n");
  cmd->callback([r] { run(*r); });
}

}  // namespace vbim::cli
