#include "runs/vectors_run.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <optional>
#include <set>
#include <sstream>

#include "runs/error.hpp"
#include "runs/output_dir.hpp"
#include "runs/samples.hpp"
#include "runtime/error.hpp"

namespace vbim::runs {

namespace {

namespace fs = std::filesystem;

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

std::optional<std::string> readText(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  if (!f) return std::nullopt;
  return std::string(std::istreambuf_iterator<char>(f), {});
}

// One file's line of the report, and whether it was scored (not absent, something selected).
std::string scoreLine(const player::VectorFile& f, const player::VectorScore& s) {
  std::ostringstream line;
  line << "  " << f.name << ": ";
  if (s.checked == 0 && s.extra == 0) {
    line << "no entry selected\n";
  } else if (!s.found) {
    line << "no such file, absent (" << s.checked << " entries not checked)\n";
  } else {
    line << s.matched << " of " << s.checked << " match";
    if (s.differ > 0) line << ", " << s.differ << " differ";
    if (s.missing > 0) line << ", " << s.missing << " missing";
    if (s.extra > 0) line << ", " << s.extra << " not in the vectors";
    line << (s.passed() ? " (pass)" : " (fail)") << "\n";
  }
  return line.str();
}

// The first few differences of a file, the first one in the form a script can match; in a value of
// many elements, where it differs.
std::string differenceLines(const fs::path& dir, const player::VectorScore& s) {
  constexpr std::size_t kShown = 3;
  std::string out;
  for (std::size_t i = 0; i < s.differences.size() && i < kShown; ++i) {
    const player::VectorDifference& d = s.differences[i];
    out += "    " + (dir / d.file).string() + ": entry '" + d.entry + "': ";
    if (d.place.empty()) {
      out += "expected '" + d.expected + "', found '" + d.found + "'\n";
    } else {
      out += d.place + ": expected '" + d.expectedElement + "', found '" + d.foundElement + "'\n";
    }
  }
  if (s.differences.size() > kShown) out += "    ... and " + std::to_string(s.differences.size() - kShown) + " more\n";
  return out;
}

}  // namespace

std::vector<player::VectorFile> streamVectors(const std::vector<std::string>& paths, const std::string& label,
                                              ipu::IdctKind idct) {
  std::vector<std::vector<std::uint8_t>> bytes;
  std::vector<player::VectorStream> streams;
  bytes.reserve(paths.size());  // the streams borrow these bytes: no reallocation
  for (const std::string& path : paths) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw Error(label + path + ": cannot open the stream file");
    bytes.emplace_back(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    streams.push_back(player::VectorStream{fs::path(path).stem().string(), bytes.back()});
  }
  return player::knownAnswerVectors(streams, idct);
}

std::size_t writeVectors(const std::vector<player::VectorFile>& files, const std::string& out, bool force,
                         const std::function<void()>& beforeCommit) {
  OutputDir dir(out, force);
  std::size_t lines = 0;
  for (const player::VectorFile& f : files) {
    std::ofstream o(dir.path(f.name), std::ios::binary);
    o << f.text;
    if (!o) throw RunFailure(dir.path(f.name).string() + ": cannot write");
    lines += static_cast<std::size_t>(std::count(f.text.begin(), f.text.end(), '\n'));
  }
  if (beforeCommit) beforeCommit();
  dir.commit();
  return lines;
}

VectorsCheck checkVectors(const std::vector<player::VectorFile>& files, const fs::path& dir,
                          const std::vector<std::string>& only) {
  std::set<std::string> stages;
  std::vector<std::string> patterns;
  for (const std::string& o : only) {
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
  // Every selected entry of every file, scored: a partial bring-up sees how far it is.
  VectorsCheck c;
  for (const player::VectorFile& f : files) {
    const bool wholeFile = stages.contains(player::vectorStage(f));
    if (!only.empty() && !wholeFile && patterns.empty()) {
      c.report += "  " + f.name + ": no entry selected\n";
      continue;
    }
    const std::optional<std::string> found = readText(dir / f.name);
    const player::VectorScore s =
        player::scoreVectors(f, found ? &*found : nullptr, wholeFile ? std::vector<std::string>{} : patterns);
    c.report += scoreLine(f, s);
    if (!s.found) continue;
    if (s.checked != 0 || s.extra != 0) {
      ++c.present;
      c.checked += s.checked;
      c.matched += s.matched;
      c.passed = c.passed && s.passed();
    }
    c.report += differenceLines(dir, s);
  }
  if (c.present == 0) {
    c.anySelected = std::any_of(files.begin(), files.end(), [&](const player::VectorFile& f) {
      return only.empty() || stages.contains(player::vectorStage(f)) ||
             player::scoreVectors(f, nullptr, patterns).checked > 0;
    });
  }
  return c;
}

std::vector<std::string> sampleVectorStreams() {
  const std::vector<std::string> names{"day_clear.vbim", "day_weather.vbim"};
  const std::optional<fs::path> dir = findSamples(names);
  if (!dir) {
    std::string searched;
    for (const fs::path& d : sampleDirectories()) searched += (searched.empty() ? "" : ", ") + d.string();
    throw Error("cannot find the sample streams " + names[0] + " and " + names[1] + " (looked in " + searched +
                "); name the streams with --stream FILE");
  }
  std::vector<std::string> paths;
  paths.reserve(names.size());
  for (const std::string& name : names) paths.push_back((*dir / name).string());
  return paths;
}

void checkVectorsRequest(const std::string& out, const std::string& check, const std::vector<std::string>& only,
                         bool force) {
  if (out.empty() == check.empty()) throw Error("give exactly one of --out DIR and --check DIR");
  if (!only.empty() && check.empty()) throw Error("--only selects what --check compares: give --check DIR");
  if (!check.empty() && !fs::is_directory(check)) throw Error("--check " + check + ": not a directory");
  if (!out.empty()) refuseExistingOutputDir(outputPath(out), force);
}

VectorsVerdict vectorsVerdict(const VectorsCheck& c, const std::string& dir, bool onlyGiven) {
  if (c.present == 0) {
    if (!c.anySelected) throw Error("--only selects no entry of the vectors");
    return {false, "no vector file selected is in " + dir + ":\n" + c.report};
  }
  const std::string total = std::to_string(c.matched) + " of " + std::to_string(c.checked) + " entries match";
  if (!c.passed) return {false, total + " in " + dir + ":\n" + c.report};
  std::string text = "the " + std::to_string(c.present) + " vector files present in " + dir + " match";
  if (onlyGiven) text += " (the " + std::to_string(c.checked) + " entries --only selects)";
  return {true, text + "\n" + c.report};
}

VectorsVerdict vectorsRun(const VectorsRequest& r, const std::function<void()>& checkpoint) {
  checkVectorsRequest(r.out, r.check, r.only, r.force);
  const ipu::IdctKind idct = ipu::idctKindByName(r.idct).value_or(ipu::kDefaultIdct);
  const std::vector<player::VectorFile> files =
      r.streams.empty() ? streamVectors(sampleVectorStreams(), "", idct) : streamVectors(r.streams, "--stream ", idct);
  if (checkpoint) checkpoint();  // nothing written yet
  if (r.out.empty()) return vectorsVerdict(checkVectors(files, r.check, r.only), r.check, !r.only.empty());
  const std::size_t lines = writeVectors(files, r.out, r.force, checkpoint);
  return {true, "wrote " + std::to_string(files.size()) + " vector files (" + std::to_string(lines) + " lines) to " +
                    r.out + "\n"};
}

}  // namespace vbim::runs
