// vbim vectors: the known-answer vectors a console port checks itself against (docs/porting.md,
// "Known-answer vectors"). --out DIR writes them; --check DIR compares a port's captured files with
// them, every entry (or the stages and keys --only selects), and scores each file: pass, fail with
// the first differences and where in the value, or absent (exit 1 when a present file fails).
#include <algorithm>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <set>
#include <sstream>

#include "cli/command.hpp"
#include "cli/interrupt.hpp"
#include "cli/option_checks.hpp"
#include "cli/samples.hpp"
#include "player/known_answers.hpp"
#include "runs/output_dir.hpp"
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
  std::vector<std::string> only;  // --only: key patterns checked
  std::string idct = ipu::idctKindName(ipu::kDefaultIdct);
  bool force = false;
};

// "vlc,idct" -> {"vlc", "idct"}.
std::vector<std::string> splitStages(const std::string& s) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t at = s.find(',', start);
    out.push_back(s.substr(start, at == std::string::npos ? std::string::npos : at - start));
    if (at == std::string::npos) return out;
    start = at + 1;
  }
}

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
  if (!r.only.empty() && r.check.empty()) throw Exit(2, "--only selects what --check compares: give --check DIR");
  if (!r.check.empty() && !std::filesystem::is_directory(r.check)) {
    throw Exit(2, "--check " + r.check + ": not a directory");
  }
  if (!r.out.empty()) runs::refuseExistingOutputDir(runs::outputPath(r.out), r.force);
  const std::vector<player::VectorFile> files = generate(r);
  checkInterrupted();  // a Ctrl-C while the vectors were computed stops here: nothing written yet
  if (!r.out.empty()) {
    runs::OutputDir dir(r.out, r.force);
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
  // --only: stage names (the files' names without .txt, alone or comma-separated) select whole
  // files; anything else is a key pattern.
  std::set<std::string> stages;
  std::vector<std::string> patterns;
  for (const std::string& o : r.only) {
    const std::vector<std::string> parts = splitStages(o);
    const bool allStages = std::all_of(parts.begin(), parts.end(), [&](const std::string& p) {
      return std::any_of(files.begin(), files.end(),
                         [&](const player::VectorFile& f) { return player::vectorStage(f) == p; });
    });
    if (allStages) {
      stages.insert(parts.begin(), parts.end());
    } else {
      patterns.push_back(o);
    }
  }
  // Every selected entry of every file, scored: a partial bring-up sees how far it is. A stage
  // whose file is absent is named and not failed: the port has not reached it yet.
  std::size_t checked = 0;
  std::size_t matched = 0;
  std::size_t present = 0;
  bool passed = true;
  std::string report;
  for (const player::VectorFile& f : files) {
    const std::filesystem::path p = std::filesystem::path(r.check) / f.name;
    const std::optional<std::string> found = readText(p);
    const bool wholeFile = stages.contains(player::vectorStage(f));
    std::ostringstream line;
    line << "  " << f.name << ": ";
    if (!r.only.empty() && !wholeFile && patterns.empty()) {
      report += line.str() + "no entry selected\n";
      continue;
    }
    const player::VectorScore s =
        player::scoreVectors(f, found ? &*found : nullptr, wholeFile ? std::vector<std::string>{} : patterns);
    if (s.checked == 0 && s.extra == 0) {
      line << "no entry selected\n";
    } else if (!s.found) {
      line << "no such file, absent (" << s.checked << " entries not checked)\n";
    } else {
      ++present;
      checked += s.checked;
      matched += s.matched;
      passed = passed && s.passed();
      line << s.matched << " of " << s.checked << " match";
      if (s.differ > 0) line << ", " << s.differ << " differ";
      if (s.missing > 0) line << ", " << s.missing << " missing";
      if (s.extra > 0) line << ", " << s.extra << " not in the vectors";
      line << (s.passed() ? " (pass)" : " (fail)") << "\n";
    }
    report += line.str();
    if (!s.found) continue;
    // The first few differences of each file, the first one in the form a script can match; in a
    // value of many elements, where it differs.
    constexpr std::size_t kShown = 3;
    for (std::size_t i = 0; i < s.differences.size() && i < kShown; ++i) {
      const player::VectorDifference& d = s.differences[i];
      report += "    " + (std::filesystem::path(r.check) / d.file).string() + ": entry '" + d.entry + "': ";
      if (d.place.empty()) {
        report += "expected '" + d.expected + "', found '" + d.found + "'\n";
      } else {
        report += d.place + ": expected '" + d.expectedElement + "', found '" + d.foundElement + "'\n";
      }
    }
    if (s.differences.size() > kShown) {
      report += "    ... and " + std::to_string(s.differences.size() - kShown) + " more\n";
    }
  }
  if (present == 0) {
    const bool anySelected = std::any_of(files.begin(), files.end(), [&](const player::VectorFile& f) {
      return r.only.empty() || stages.contains(player::vectorStage(f)) ||
             player::scoreVectors(f, nullptr, patterns).checked > 0;
    });
    if (!anySelected) throw Exit(2, "--only selects no entry of the vectors");
    throw Exit(1, "no vector file selected is in " + r.check + ":\n" + report);
  }
  const std::string total = std::to_string(matched) + " of " + std::to_string(checked) + " entries match";
  if (!passed) throw Exit(1, total + " in " + r.check + ":\n" + report);
  std::cout << "the " << present << " vector files present in " << r.check << " match";
  if (!r.only.empty()) std::cout << " (the " << checked << " entries --only selects)";
  std::cout << "\n" << report;
}

}  // namespace

void addVectors(CLI::App& app) {
  auto r = std::make_shared<VectorsRequest>();
  auto* cmd = app.add_subcommand(
      "vectors", "Write the timing-independent known-answer vectors for a port, or check a port's against them");
  cmd->add_option("-o,--out", r->out, "Write the vector files into this directory (complete or not at all)");
  cmd->add_option("--check", r->check,
                  "Compare the vector files in this directory: every entry, scored per file, differences named");
  cmd->add_option("--only", r->only,
                  "With --check: only these stages (vlc, idct, csc, draw, blend, ... comma-separated) or the entries "
                  "whose key matches PATTERN ('*' any run, e.g. 'ipu/*/rgb32/*'; repeatable): score a partial bring-up")
      ->type_name("STAGES|PATTERN");
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
      "  vbim vectors --check tests/vectors\n"
      "  vbim vectors --check port/ --only 'ipu/*/rgb32/*' --only 'blend/*'\n"
      "  vbim vectors --check port/ --only vlc,idct\n");
  cmd->callback([r] { run(*r); });
}

}  // namespace vbim::cli
