#include "runs/replay_run.hpp"

#include <cstdio>
#include <exception>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <vector>

#include "config/option_values.hpp"
#include "config/platform_config_toml.hpp"
#include "gs/simd/blend_simd.hpp"
#include "iop/fault_plan.hpp"
#include "ipu/simd/simd_kernels.hpp"
#include "player/replay.hpp"
#include "player/replay_report.hpp"
#include "player/report.hpp"
#include "runs/error.hpp"
#include "runs/output_dir.hpp"
#include "runs/play_run.hpp"
#include "runs/replay_json.hpp"
#include "streams/disc/stream_disc.hpp"

namespace vbim::runs {

namespace {

using namespace vbim::player;

std::string readAll(const std::string& path, const char* what) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw Error(std::string(what) + " " + path + ": cannot open");
  return std::string(std::istreambuf_iterator<char>(f), {});
}

// Warnings and late arrivals listed before "... and N more".
constexpr std::size_t kListed = 12;

ReplayOptions replayOptions(const ReplayRequest& r) {
  ReplayOptions o;
  if (!r.config.empty()) o.config = config::loadPlatformFile(r.config);
  if (!r.policy.empty()) o.config.gs.catchup = config::catchupPolicy(r.policy);
  try {
    o.duration = iop::parseDuration(r.duration);
  } catch (const std::exception& e) {
    throw Error("--duration '" + r.duration + "': " + e.what() + " (expected a time with a unit, e.g. 60s)");
  }
  if (o.duration <= 0) throw Error("--duration must be positive");
  if (r.format != "png" && r.format != "exr") throw Error("--format '" + r.format + "': expected png or exr");
  o.kernels.blend = &gs::simd::kernels();
  o.kernels.ipu = &ipu::simdKernels();
  if (!r.frames.empty()) o.frames.emplace(r.frames);
  return o;
}

}  // namespace

ReplayResult replayRun(const ReplayRequest& r, const std::function<void(const std::string&)>& warn) {
  ReplayOptions o = replayOptions(r);
  // A bare stream file or the stream on an ISO 9660 image, as play takes it.
  const streams::StreamDisc disc = streams::openStreamDisc(r.stream, r.file);
  const std::vector<std::uint8_t> file = streams::readDiscFile(*disc.disc, disc.file);
  const ArrivalLog log = parseArrivals(readAll(r.arrivals, "--arrivals"), r.arrivals);
  for (std::size_t i = 0; i < log.warnings.size() && i < kListed; ++i) warn(log.warnings[i]);
  if (log.warnings.size() > kListed) warn("... and " + std::to_string(log.warnings.size() - kListed) + " more");
  std::optional<ExpectedHashes> expected;
  if (!r.compare.empty()) expected = readExpectedHashes(r.compare);
  if (!r.durationGiven) o.vsyncs = log.vsyncs;  // the run's own length, when the log says it
  const auto replay = std::make_unique<Replay>(std::span<const std::uint8_t>(file), r.stream, log.arrivals, o);
  ReplayNotes notes(*replay, log, r.arrivals);
  ReplayFacts facts;
  facts.fileOnDisc = disc.image ? disc.file.path : std::string();
  facts.policy = o.config.gs.catchup;
  OutputDir dir(r.out, r.force);
  std::ofstream hashes(dir.path("hashes.txt"), std::ios::binary);
  std::ofstream timeline(dir.path("timeline.csv"), std::ios::binary);
  timeline << replayTimelineHeader();
  std::filesystem::create_directories(dir.path("frames"));
  std::int64_t rows = 0;
  std::string difference;  // the first vsync whose hash differs from --compare's, explained
  // What the progress callback threw (Ctrl-C), rethrown as it was: the scheduler would wrap it as a
  // failed process.
  std::exception_ptr stopped;
  replay->setSink([&](const VsyncRow& row, const Rgba8Image& lm, const Rgba8Image* sky) {
    hashes << hashesLine(row);
    timeline << replayTimelineLine(row, *replay);
    notes.add(row);
    if (row.lightmap.targetSeq >= 0) facts.shown.emplace(false, row.lightmap.variant, row.lightmap.targetSeq);
    if (row.sky && row.sky->targetSeq >= 0) facts.shown.emplace(true, row.sky->variant, row.sky->targetSeq);
    ++rows;
    if (r.progress && rows % 60 == 0) {
      try {
        r.progress(rows, o.vsyncs.value_or(0));
      } catch (...) {
        stopped = std::current_exception();
        throw;
      }
    }
    if (expected && difference.empty()) {
      difference = hashDifference(*expected, row, notes);
      if (!difference.empty()) facts.firstDifference = row;
    }
    if (r.every <= 0 || row.vsync % r.every != 0) return;
    facts.imagesWritten += sky != nullptr ? 2 : 1;
    char name[64];
    std::snprintf(name, sizeof name, "%06lld", static_cast<long long>(row.vsync));
    const imageio::TexelFileFormat format{r.format == "exr", r.alpha == "gs", imageio::kDefaultTexelPngLevel};
    writeRunImage(dir.path("frames") / (std::string("lightmap_") + name + "." + r.format), lm, format);
    if (sky != nullptr) writeRunImage(dir.path("frames") / (std::string("sky_") + name + "." + r.format), *sky, format);
  });
  try {
    replay->run();
  } catch (...) {
    if (stopped) std::rethrow_exception(stopped);
    throw;
  }
  hashes.close();
  timeline.close();
  if (!hashes) throw RunFailure(dir.path("hashes.txt").string() + ": cannot write");
  if (!timeline) throw RunFailure(dir.path("timeline.csv").string() + ": cannot write");
  dir.commit();

  ReplayResult result;
  if (expected && !difference.empty()) result.differs = expected->origin;
  if (r.json) {
    facts.vsyncs = rows;
    result.report = replaySummaryJson(r, *replay, log, facts, expected, result.jsonReplaced);
    return result;
  }
  std::ostringstream out;
  out << "replayed " << rows << " vsyncs of " << r.stream << " from " << r.arrivals
      << (r.frames.empty() ? "" : " with the frames of " + r.frames) << " into " << r.out;
  if (replay->missingPictures() > 0) {
    out << " (" << replay->missingPictures() << " arrivals named pictures the stream lacks: shown black)";
  }
  out << "\n";
  const std::vector<std::string> late = notes.lateOrUnshown();
  out << late.size() << " arrival(s) late or never shown" << (late.empty() ? "" : ":") << "\n";
  for (std::size_t i = 0; i < late.size() && i < kListed; ++i) out << "  " << late[i] << "\n";
  if (late.size() > kListed) out << "  ... and " << late.size() - kListed << " more (timeline.csv)\n";
  if (expected) {
    if (difference.empty() && static_cast<std::int64_t>(expected->hashes.size()) > rows) {
      out << "note: " << expected->origin << " has " << expected->hashes.size() - static_cast<std::size_t>(rows)
          << " vsyncs more than the replay; compared the first " << rows << "\n";
    }
    if (difference.empty()) {
      out << "every hash equals " << expected->origin << " (" << rows << " vsyncs)\n";
    } else {
      out << difference;
    }
  }
  result.report = out.str();
  return result;
}

}  // namespace vbim::runs
