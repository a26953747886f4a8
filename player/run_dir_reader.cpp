#include "player/run_dir_reader.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "runtime/error.hpp"

namespace vbim::player {

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(item);
  return out;
}

void readTimeline(const std::filesystem::path& file, RunDir& run) {
  std::ifstream in(file);
  if (!in) return;
  std::string line;
  if (!std::getline(in, line)) throw Error(file.string() + ":1: empty file (expected the timeline header)");
  const std::vector<std::string> header = split(line);
  auto column = [&](const char* name) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) throw Error(file.string() + ":1: no column '" + name + "' in the header");
    return static_cast<std::size_t>(it - header.begin());
  };
  const std::size_t cVsync = column("vsync"), cTime = column("time_s"), cTarget = column("target_seq"),
                    cVariant = column("variant"), cBehind = column("behind"), cCatch = column("catch_up"),
                    cSnapped = column("snapped");
  std::int64_t lineNo = 1;
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.empty()) continue;
    const std::vector<std::string> f = split(line);
    try {
      if (f.size() != header.size()) throw std::invalid_argument("column count");
      TimelineRow r;
      r.timeSeconds = std::stod(f[cTime]);
      r.targetSeq = std::stoll(f[cTarget]);
      r.variant = std::stoi(f[cVariant]);
      r.behind = f[cBehind] == "1";
      r.catchUp = f[cCatch] == "1";
      r.snapped = f[cSnapped] == "1";
      run.timeline[std::stoll(f[cVsync])] = r;
    } catch (const std::exception&) {
      throw Error(file.string() + ":" + std::to_string(lineNo) + ": expected " + std::to_string(header.size()) +
                  " comma-separated fields as in the header (vsync,time_s,...)");
    }
  }
  run.vsyncs = static_cast<std::int64_t>(run.timeline.size());
}

}  // namespace

RunDir readRunDir(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(dir)) throw Error(dir.string() + ": not a directory (expected a `vbim play --out` run)");
  RunDir run;
  run.path = dir;
  const fs::path frames = dir / "frames";
  if (fs::is_directory(frames)) {
    for (const auto& e : fs::directory_iterator(frames)) {
      const std::string name = e.path().filename().string();
      const std::string ext = e.path().extension().string();
      if (name.rfind("lightmap_", 0) != 0 || (ext != ".png" && ext != ".exr")) continue;
      const std::string digits = e.path().stem().string().substr(9);
      if (digits.empty() || !std::all_of(digits.begin(), digits.end(), ::isdigit)) continue;
      RunFrame f;
      f.vsync = std::stoll(digits);
      f.lightmap = e.path();
      const fs::path sky = frames / ("sky_" + digits + ext);
      if (fs::exists(sky)) f.sky = sky;
      run.frames.push_back(f);
    }
  }
  std::sort(run.frames.begin(), run.frames.end(),
            [](const RunFrame& a, const RunFrame& b) { return a.vsync < b.vsync; });
  if (run.frames.empty()) {
    throw Error(dir.string() + ": no frames/lightmap_NNNNNN.png in this run (play it with --every N or --at TIMES)");
  }
  readTimeline(dir / "timeline.csv", run);
  run.faults = readFaultSpansCsv(dir / "faults.csv");
  if (std::ifstream a(dir / "authoring.json", std::ios::binary); a) {
    run.authoring = std::string(std::istreambuf_iterator<char>(a), std::istreambuf_iterator<char>());
  }
  return run;
}

}  // namespace vbim::player
