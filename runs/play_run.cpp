#include "runs/play_run.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <memory>
#include <optional>
#include <set>

#include <nlohmann/json.hpp>

#include "config/fault_plan_toml.hpp"
#include "config/option_values.hpp"
#include "config/platform_config_toml.hpp"
#include "gs/error.hpp"
#include "gs/simd/blend_simd.hpp"
#include "imageio/error.hpp"
#include "imageio/png_encoder.hpp"
#include "ipu/pool_runner.hpp"
#include "ipu/simd/simd_kernels.hpp"
#include "player/report.hpp"
#include "player/run_dir.hpp"
#include "runs/error.hpp"
#include "runs/play_json.hpp"
#include "runs/provenance.hpp"
#include "runtime/worker_pool.hpp"
#include "streams/disc/stream_disc.hpp"

namespace vbim::runs {

void writeRunImage(const std::filesystem::path& path, const Rgba8Image& texels,
                   const imageio::TexelFileFormat& format) {
  try {
    imageio::writeTexelImage(path, texels, format, imageio::FilePlacement::InStagedDirectory);
  } catch (const imageio::ImageIoError& e) {
    throw RunFailure(e.what());
  }
}

namespace {

using namespace vbim::player;

// The variant after '=' in --branch: a plain index (0 is the first variant).
int variantIndex(const std::string& branch, const std::string& text) {
  int v = -1;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || v < 0) {
    throw Error("--branch '" + branch + "': the variant '" + text +
                "' is not a variant number (0, 1, ...; `vbim info` lists the variants)");
  }
  return v;
}

// The CPU the pictures took on their thread (bench/player/image_share.sh reads it; issue #31's goal
// is at most 10 % of the play's).
std::string picturesLine(double pictureCpu, double cpu, const PlayRequest& r) {
  char line[160];
  std::snprintf(line, sizeof line, "  pictures: %.1f ms of CPU time on their own thread (%.1f %% of the play's), %s\n",
                pictureCpu * 1e3, 100.0 * pictureCpu / std::max(cpu, 1e-9),
                r.format == "exr" ? "EXR" : ("PNG level " + std::to_string(r.pngLevel)).c_str());
  return line;
}

// The request's options as the player takes them, every one checked (vbim::Error naming it).
PlayerOptions playerOptions(const PlayRequest& r, const iop::SectorSource* disc, std::set<Tick>& atTimes) {
  PlayerOptions o;
  if (!r.config.empty()) o.config = config::loadPlatformFile(r.config);
  if (!r.faults.empty()) {
    o.faults = config::loadFaultPlan(r.faults, disc);
  } else if (!r.faultsText.empty()) {
    o.faults = config::parseFaultPlan(r.faultsText, "<built-in fault plan>", disc);
  }
  if (!r.policy.empty()) o.config.gs.catchup = config::catchupPolicy(r.policy);
  o.seed = r.seed;
  o.duration = config::parseTime("--duration", r.duration);
  if (o.duration <= 0) throw Error("--duration must be positive");
  o.trace = r.trace && !r.out.empty();  // nothing to write it to without a run directory
  o.kernels.blend = &gs::simd::kernels();
  o.kernels.ipu = &ipu::simdKernels();
  for (const std::string& b : r.branches) {
    const auto eq = b.find('=');
    if (eq == std::string::npos) throw Error("--branch '" + b + "': expected TIME=VARIANT, e.g. 12.5s=1");
    o.branches.push_back(Branch{config::parseTime("--branch", b.substr(0, eq)), variantIndex(b, b.substr(eq + 1))});
  }
  for (const std::string& a : r.at) {
    const Tick t = config::parseTime("--at", a);
    if (t >= o.duration) {
      throw Error("--at " + a + " is outside the run (0 s to " + std::to_string(toSeconds(o.duration)) +
                  " s; see --duration)");
    }
    atTimes.insert(t);
  }
  if (r.format != "png" && r.format != "exr") throw Error("--format '" + r.format + "': expected png or exr");
  imageio::checkPngLevelOption(r.pngLevel);
  if (r.out.empty() && (r.every > 0 || !r.at.empty())) {
    throw Error(std::string(r.every > 0 ? "--every" : "--at") +
                " writes pictures into the run directory: give --out DIR (without --out, play writes nothing)");
  }
  return o;
}

// authoring.json: how the stream was made, for `vbim render RUN_DIR`
// (lighting/authoring/technique_a_record.hpp), pretty-printed when it is JSON.
void writeAuthoringRecord(const OutputDir& dir, const std::string& record) {
  std::ofstream a(dir.path("authoring.json"), std::ios::binary);
  try {
    a << nlohmann::ordered_json::parse(record).dump(2) << "\n";
  } catch (const nlohmann::json::exception&) {
    a << record << "\n";  // kept as the stream holds it; render reports what is wrong with it
  }
}

RunDirOptions runDirOptions(const PlayRequest& r, const std::set<Tick>& atTimes) {
  RunDirOptions files;
  files.every = r.every;
  files.at = atTimes;
  files.imageExtension = r.format;
  // Written on a thread of their own (player/picture_queue.hpp), flushed before the times are taken.
  files.writeImage = [format = imageio::TexelFileFormat{r.format == "exr", r.alpha == "gs", r.pngLevel}](
                         const std::filesystem::path& path, Rgba8Image& texels) {
    writeRunImage(path, texels, format);
  };
  files.trace = r.trace;
  files.traceDetail = r.traceDetail == "full" ? TraceDetail::Full : TraceDetail::Coalesced;
  files.ipuCommands = r.traceDetail == "ipu";
  files.onRow = r.onRow;
  return files;
}

}  // namespace

PlayResult playRun(const PlayRequest& r, const PlayProgressFn& onSecond) {
  // The disc: an ISO 9660 image and the stream on it, or a bare stream file at kBareFileLba.
  const streams::StreamDisc opened = streams::openStreamDisc(r.disc, r.file);
  const std::shared_ptr<iop::SectorSource>& disc = opened.disc;
  const iop::DiscFile& file = opened.file;
  std::string shown = r.disc;  // the disc as the summary names it
  if (opened.image) shown += " " + file.path + " (LBA " + std::to_string(file.lba) + ")";
  std::set<Tick> atTimes;
  PlayerOptions o = playerOptions(r, disc.get(), atTimes);
  // --threads N: the IPU's picture decode split by slice rows over N host threads. The simulation
  // stays on this thread; the bytes out do not depend on N (docs/player.md, "Speed and memory").
  std::optional<WorkerPool> pool;
  std::optional<ipu::PoolSliceRunner> sliceRunner;
  if (r.threads > 1) {
    try {
      pool.emplace(r.threads - 1);
    } catch (const Error& e) {
      throw RunFailure("--threads " + std::to_string(r.threads) + ": " + e.what());
    }
    sliceRunner.emplace(*pool);
    o.kernels.sliceRunner = &*sliceRunner;
  }

  std::unique_ptr<Player> player;
  try {
    player = std::make_unique<Player>(*disc, file, o);
  } catch (const gs::GsError& e) {
    throw Error(config::gsConfigMessage(e, r.config));
  }

  std::optional<OutputDir> dir;
  std::optional<RunDirWriter> writer;
  if (!r.out.empty()) {
    const std::optional<std::string> record = streams::readAuthoringRecord(*disc, file);
    dir.emplace(r.out, r.force);
    if (record) writeAuthoringRecord(*dir, *record);
    writer.emplace(*player, dir->directory(), runDirOptions(r, atTimes));
  }

  const auto wall0 = std::chrono::steady_clock::now();  // host time: the summary only
  const std::clock_t cpu0 = std::clock();               // CPU time of every thread: the summary only
  const Tick step = fromMs(1'000);
  for (Tick t = step;; t += step) {
    player->runTo(std::min(t, o.duration));
    onSecond(toSeconds(player->now()), toSeconds(o.duration));
    if (t >= o.duration) break;
  }
  if (writer) writer->flushPictures();  // the summary's times include every picture
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  const double cpu = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  if (writer) {
    const json::Value run = playProvenance(r, o);
    try {
      writer->finish(&run);
    } catch (const Error& e) {
      throw RunFailure(e.what());
    }
    if (r.beforeCommit) r.beforeCommit(*dir);
    dir->commit();
  }

  const std::int64_t images = writer ? writer->images() : 0;
  PlayResult result;
  const std::string label = r.discLabel.empty() ? shown : r.discLabel;
  // A run that completed but stopped showing frames says so loudly (stderr) as well as in the summary.
  result.warning = healthWarning(runHealth(player->pipeline().lightmap().counters(), player->totals()));
  if (r.json) {
    const PictureCost pictures{writer ? writer->pictureCpuSeconds() : 0.0,
                               r.format == "exr" ? "EXR" : "PNG level " + std::to_string(r.pngLevel)};
    result.summary = playSummaryJson(*player, label, wall, cpu, images, pictures, result.jsonReplaced);
    return result;
  }
  result.summary = playSummary(*player, label, wall, cpu, images);
  if (images > 0) result.summary += picturesLine(writer->pictureCpuSeconds(), cpu, r);
  if (!result.warning.empty()) result.summary += "  " + result.warning + "\n";
  return result;
}

}  // namespace vbim::runs
