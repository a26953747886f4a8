// vbim replay: the GS side of a run (blend and present at every vsync, with the GS's timing) fed by
// an arrival schedule, a port's log or the arrivals.csv of `vbim play`; writes hashes.txt,
// timeline.csv and pictures like play, says which arrivals came late or were never shown, and with
// --compare names the first vsync whose hash differs from a run's or a port's (docs/porting.md,
// "Replay").
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <optional>
#include <set>
#include <vector>

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "cli/output_dir.hpp"
#include "cli/platform_params.hpp"
#include "cli/play_run.hpp"
#include "config/platform_config_toml.hpp"
#include "gs/error.hpp"
#include "gs/simd/blend_simd.hpp"
#include "iop/error.hpp"
#include "iop/fault_plan.hpp"
#include "ipu/simd/simd_kernels.hpp"
#include "player/replay.hpp"
#include "player/replay_report.hpp"
#include "player/report.hpp"
#include "streams/disc/stream_disc.hpp"

namespace vbim::cli {

namespace {

struct ReplayRequest {
  std::string stream;
  std::string file;  // the stream file on an ISO 9660 image (--file), or empty: the default
  std::string arrivals;
  std::string compare;  // a run directory or a hashes.txt to compare with, or empty
  std::string frames;   // the port's decoded frames (player/port_frames.hpp), or empty: vbim decodes
  std::string config;
  std::string duration = "60s";
  bool durationGiven = false;  // --duration given: it wins over the log's end row
  std::string policy;
  std::int64_t every = 0;
  std::string format = "png";
  std::string alpha = "opaque";
  bool force = false;
  std::string out;
};

std::string readAll(const std::string& path, const char* what) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw Exit(2, std::string(what) + " " + path + ": cannot open");
  return std::string(std::istreambuf_iterator<char>(f), {});
}

// Warnings and late arrivals printed before "... and N more".
constexpr std::size_t kListed = 12;

void printWarnings(const std::vector<std::string>& warnings) {
  for (std::size_t i = 0; i < warnings.size() && i < kListed; ++i) std::cerr << "warning: " << warnings[i] << "\n";
  if (warnings.size() > kListed) std::cerr << "warning: ... and " << warnings.size() - kListed << " more\n";
}

void run(const ReplayRequest& r) {
  using namespace vbim::player;
  ReplayOptions o;
  if (!r.config.empty()) o.config = config::loadPlatformFile(r.config);
  if (!r.policy.empty()) o.config.gs.catchup = catchupPolicy(r.policy);
  try {
    o.duration = iop::parseDuration(r.duration);
  } catch (const std::exception& e) {
    throw Exit(2, "--duration '" + r.duration + "': " + e.what() + " (expected a time with a unit, e.g. 60s)");
  }
  if (o.duration <= 0) throw Exit(2, "--duration must be positive");
  if (r.format != "png" && r.format != "exr") throw Exit(2, "--format '" + r.format + "': expected png or exr");
  o.kernels.blend = &gs::simd::kernels();
  o.kernels.ipu = &ipu::simdKernels();
  if (!r.frames.empty()) o.frames.emplace(r.frames);
  // A bare stream file or the stream on an ISO 9660 image, as play takes it.
  std::vector<std::uint8_t> file;
  const streams::StreamDisc disc = streams::openStreamDisc(r.stream, r.file);
  file = streams::readDiscFile(*disc.disc, disc.file);
  const ArrivalLog log = parseArrivals(readAll(r.arrivals, "--arrivals"), r.arrivals);
  printWarnings(log.warnings);
  std::optional<ExpectedHashes> expected;
  if (!r.compare.empty()) expected = readExpectedHashes(r.compare);
  if (!r.durationGiven) o.vsyncs = log.vsyncs;  // the run's own length, when the log says it
  const auto replay = std::make_unique<Replay>(std::span<const std::uint8_t>(file), r.stream, log.arrivals, o);
  ReplayNotes notes(*replay, log, r.arrivals);
  OutputDir dir(r.out, r.force);
  std::ofstream hashes(dir.path("hashes.txt"), std::ios::binary);
  std::ofstream timeline(dir.path("timeline.csv"), std::ios::binary);
  timeline << replayTimelineHeader();
  std::filesystem::create_directories(dir.path("frames"));
  std::int64_t rows = 0;
  std::string difference;  // the first vsync whose hash differs from --compare's, explained
  replay->setSink([&](const VsyncRow& row, const Rgba8Image& lm, const Rgba8Image* sky) {
    hashes << hashesLine(row);
    timeline << replayTimelineLine(row, *replay);
    notes.add(row);
    ++rows;
    if (expected && difference.empty()) difference = hashDifference(*expected, row, notes);
    if (r.every <= 0 || row.vsync % r.every != 0) return;
    char name[64];
    std::snprintf(name, sizeof name, "%06lld", static_cast<long long>(row.vsync));
    const imageio::TexelFileFormat format{r.format == "exr", r.alpha == "gs", imageio::kDefaultTexelPngLevel};
    Rgba8Image copy = lm;  // the writer sets its alpha in place
    writeRunImage(dir.path("frames") / (std::string("lightmap_") + name + "." + r.format), copy, format);
    if (sky != nullptr) {
      copy = *sky;
      writeRunImage(dir.path("frames") / (std::string("sky_") + name + "." + r.format), copy, format);
    }
  });
  replay->run();
  hashes.close();
  timeline.close();
  if (!hashes) throw Exit(1, dir.path("hashes.txt").string() + ": cannot write");
  if (!timeline) throw Exit(1, dir.path("timeline.csv").string() + ": cannot write");
  dir.commit();
  std::cout << "replayed " << rows << " vsyncs of " << r.stream << " from " << r.arrivals
            << (r.frames.empty() ? "" : " with the frames of " + r.frames) << " into " << r.out;
  if (replay->missingPictures() > 0) {
    std::cout << " (" << replay->missingPictures() << " arrivals named pictures the stream lacks: shown black)";
  }
  std::cout << "\n";
  const std::vector<std::string> late = notes.lateOrUnshown();
  std::cout << late.size() << " arrival(s) late or never shown" << (late.empty() ? "" : ":") << "\n";
  for (std::size_t i = 0; i < late.size() && i < kListed; ++i) std::cout << "  " << late[i] << "\n";
  if (late.size() > kListed) std::cout << "  ... and " << late.size() - kListed << " more (timeline.csv)\n";
  if (!expected) return;
  if (difference.empty() && static_cast<std::int64_t>(expected->hashes.size()) > rows) {
    std::cout << "note: " << expected->origin << " has " << expected->hashes.size() - static_cast<std::size_t>(rows)
              << " vsyncs more than the replay; compared the first " << rows << "\n";
  }
  if (difference.empty()) {
    std::cout << "every hash equals " << expected->origin << " (" << rows << " vsyncs)\n";
    return;
  }
  std::cout << difference;
  throw Exit(1, "the replay differs from " + expected->origin + " (the first difference is above)");
}
}  // namespace

void addReplay(CLI::App& app) {
  auto r = std::make_shared<ReplayRequest>();
  auto* cmd = app.add_subcommand(
      "replay", "Blend and present a stream on the simulated GS from an arrival log (vsync,stream,frame)");
  cmd->add_option("stream", r->stream, "A VBIM stream file or an ISO 9660 disc image holding one")
      ->required()
      ->check(inputFile());
  cmd->add_option("--file", r->file,
                  "The stream on a disc image, e.g. '\\DATA\\DAY.VBI;1' (default: its only VBIM stream)");
  cmd->add_option("--arrivals", r->arrivals,
                  "Arrival log: CSV vsync,stream,frame, and an end row N,end, (play writes arrivals.csv)")
      ->required()
      ->check(inputFile());
  cmd->add_option("--compare", r->compare,
                  "A run directory or a port's hashes.txt: print the first vsync whose hash differs, with the "
                  "frame due, the target and its lateness there, and exit 1 on a difference");
  cmd->add_option("--frames", r->frames,
                  "The port's decoded frames instead of vbim's decode: DIR/lightmap/frame_NNNNN.rgba and "
                  "DIR/sky/frame_NNNNN.rgba, raw RGB32, as `vbim decode --format rgba` writes them")
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--config", r->config, "Platform config (TOML), as given to play")->check(inputFile());
  cmd->add_option("--duration", r->duration,
                  "Simulated time to present (e.g. 60s); without it, the vsyncs the log's end row gives (play "
                  "writes one), else 60s")
      ->each([r](const std::string&) { r->durationGiven = true; });
  cmd->add_option("--policy", r->policy, "Catch-up policy: blend-through (default), hard-skip or play-late");
  cmd->add_option("--every", r->every, "Write the lightmap and sky every N vsyncs (0: never)")
      ->check(nonNegativeInteger())
      ->capture_default_str();
  cmd->add_option("--format", r->format, "Image format: png or exr")->capture_default_str();
  cmd->add_option("--alpha", r->alpha, "Alpha of the pictures: opaque (255) or gs (the texels as in VRAM)")
      ->check(CLI::IsMember({"opaque", "gs"}))
      ->capture_default_str();
  cmd->add_flag("--force", r->force, "Replace a non-empty output directory");
  cmd->add_option("--out", r->out, "Output directory (written complete or not at all)")->required();
  cmd->footer(
      "Examples:\n"
      "  vbim replay streams/samples/day_clear.vbim --arrivals run/arrivals.csv --out replayed/\n"
      "  vbim replay streams/samples/day_clear.vbim --arrivals port-log.csv --duration 10s --out replayed/\n"
      "  vbim replay disc.iso --file '\\DATA\\DAY.VBI;1' --arrivals run-iso/arrivals.csv --out replayed-iso/\n"
      "  vbim replay streams/samples/day_clear.vbim --arrivals port-log.csv --compare port-hashes.txt --out "
      "replayed/\n"
      "  vbim replay streams/samples/day_clear.vbim --arrivals port-log.csv --frames port-frames/ --compare "
      "run/ --out replayed/\n");
  cmd->callback([r] { run(*r); });
}

}  // namespace vbim::cli
