// vbim play: a disc through the whole pipeline on the simulated clock; writes images, hashes.txt,
// stats.json, trace.json, signals.vcd, timeline.csv and arrivals.csv into --out (docs/player.md).
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <set>

#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/host_threads.hpp"
#include "cli/interrupt.hpp"
#include "cli/option_checks.hpp"
#include "cli/output_dir.hpp"
#include "cli/platform_params.hpp"
#include "cli/play_run.hpp"
#include "cli/progress.hpp"
#include "cli/provenance.hpp"
#include "config/fault_plan_toml.hpp"
#include "config/platform_config_toml.hpp"
#include "gs/error.hpp"
#include "gs/simd/blend_simd.hpp"
#include "imageio/error.hpp"
#include "imageio/png_encoder.hpp"
#include "imageio/texel_files.hpp"
#include "ipu/pool_runner.hpp"
#include "ipu/simd/simd_kernels.hpp"
#include "player/report.hpp"
#include "player/run_dir.hpp"
#include "runtime/error.hpp"
#include "runtime/worker_pool.hpp"
#include "streams/disc/stream_disc.hpp"

namespace vbim::cli {

void writeRunImage(const std::filesystem::path& path, Rgba8Image& texels, const imageio::TexelFileFormat& format) {
  try {
    imageio::writeTexelImage(path, texels, format);
  } catch (const imageio::ImageIoError& e) {
    throw Exit(1, e.what());
  }
}

namespace {

// The variant after '=' in --branch: a plain index (0 is the first variant).
int variantIndex(const std::string& branch, const std::string& text) {
  int v = -1;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || v < 0) {
    throw Exit(2, "--branch '" + branch + "': the variant '" + text +
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

}  // namespace

std::string runPlay(const PlayRequest& r, bool progress) {
  using namespace vbim::player;
  // The disc: an ISO 9660 image and the stream on it, or a bare stream file at kBareFileLba.
  const streams::StreamDisc opened = streams::openStreamDisc(r.disc, r.file);
  const std::shared_ptr<iop::SectorSource>& disc = opened.disc;
  const iop::DiscFile& file = opened.file;
  std::string shown = r.disc;  // the disc as the summary names it
  if (opened.image) shown += " " + file.path + " (LBA " + std::to_string(file.lba) + ")";
  PlayerOptions o;
  if (!r.config.empty()) o.config = config::loadPlatformFile(r.config);
  if (!r.faults.empty()) {
    o.faults = config::loadFaultPlan(r.faults, disc.get());
  } else if (!r.faultsText.empty()) {
    o.faults = config::parseFaultPlan(r.faultsText, "<built-in fault plan>", disc.get());
  }
  if (!r.policy.empty()) o.config.gs.catchup = catchupPolicy(r.policy);
  o.seed = r.seed;
  o.duration = parseTime("--duration", r.duration);
  if (o.duration <= 0) throw Exit(2, "--duration must be positive");
  o.trace = r.trace;
  o.kernels.blend = &gs::simd::kernels();
  o.kernels.ipu = &ipu::simdKernels();
  // --threads N: the IPU's picture decode split by slice rows over N host threads. The simulation
  // stays on this thread; the bytes out do not depend on N (docs/player.md, "Speed and memory").
  std::optional<WorkerPool> pool;
  std::optional<ipu::PoolSliceRunner> sliceRunner;
  if (r.threads > 1) {
    try {
      pool.emplace(r.threads - 1);
    } catch (const Error& e) {
      throw Exit(1, "--threads " + std::to_string(r.threads) + ": " + e.what());
    }
    sliceRunner.emplace(*pool);
    o.kernels.sliceRunner = &*sliceRunner;
  }
  for (const std::string& b : r.branches) {
    const auto eq = b.find('=');
    if (eq == std::string::npos) throw Exit(2, "--branch '" + b + "': expected TIME=VARIANT, e.g. 12.5s=1");
    o.branches.push_back(Branch{parseTime("--branch", b.substr(0, eq)), variantIndex(b, b.substr(eq + 1))});
  }
  std::set<Tick> atTimes;
  for (const std::string& a : r.at) {
    const Tick t = parseTime("--at", a);
    if (t >= o.duration) {
      throw Exit(2, "--at " + a + " is outside the run (0 s to " + std::to_string(toSeconds(o.duration)) +
                        " s; see --duration)");
    }
    atTimes.insert(t);
  }
  if (r.format != "png" && r.format != "exr") throw Exit(2, "--format '" + r.format + "': expected png or exr");
  if (r.pngLevel < 0 || r.pngLevel > imageio::kMaxPngLevel) {
    throw Exit(2, "--png-level " + std::to_string(r.pngLevel) + ": expected 0 (stored) to " +
                      std::to_string(imageio::kMaxPngLevel));
  }

  std::unique_ptr<Player> player;
  try {
    player = std::make_unique<Player>(*disc, file, o);
  } catch (const gs::GsError& e) {
    throw Exit(2, gsConfigMessage(e, r.config));
  }

  // How the stream was made, for `vbim render RUN_DIR` (lighting/authoring/technique_a_record.hpp).
  const std::optional<std::string> record = streams::readAuthoringRecord(*disc, file);

  OutputDir dir(r.out, r.force);
  if (record) {
    std::ofstream a(dir.path("authoring.json"), std::ios::binary);
    try {
      a << nlohmann::ordered_json::parse(*record).dump(2) << "\n";
    } catch (const nlohmann::json::exception&) {
      a << *record << "\n";  // kept as the stream holds it; render reports what is wrong with it
    }
  }
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
  files.onRow = r.onRow;
  RunDirWriter writer(*player, dir.directory(), files);

  const auto wall0 = std::chrono::steady_clock::now();  // host time: the summary only
  const std::clock_t cpu0 = std::clock();               // CPU time of every thread: the summary only
  const Tick step = fromMs(1'000);
  Progress bar("vbim play", "s");
  for (Tick t = step;; t += step) {
    player->runTo(std::min(t, o.duration));
    if (progress) bar.show(toSeconds(player->now()), toSeconds(o.duration));
    checkInterrupted();
    if (t >= o.duration) break;
  }
  bar.finish();
  writer.flushPictures();  // the summary's times include every picture
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  const double cpu = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  try {
    const json::Value run = playProvenance(r, o);
    writer.finish(&run);
  } catch (const Error& e) {
    throw Exit(1, e.what());
  }
  if (r.beforeCommit) r.beforeCommit(dir);
  dir.commit();

  std::string s = playSummary(*player, r.discLabel.empty() ? shown : r.discLabel, wall, cpu, writer.images());
  if (writer.images() > 0) s += picturesLine(writer.pictureCpuSeconds(), cpu, r);
  // A run that completed but stopped showing frames says so loudly (stderr) as well as in the summary.
  if (const std::string warning = healthWarning(runHealth(player->pipeline().lightmap().counters(), player->totals()));
      !warning.empty()) {
    s += "  " + warning + "\n";
    std::cerr << "vbim play: " << warning << "\n";
  }
  return s;
}

void addPlay(CLI::App& app) {
  auto r = std::make_shared<PlayRequest>();
  auto* cmd = app.add_subcommand("play", "Play a VBIM disc through the whole pipeline on the simulated clock");
  cmd->add_option("disc", r->disc, "A VBIM stream file (a disc with one file) or an ISO 9660 disc image")
      ->required()
      ->check(inputFile());
  cmd->add_option("--file", r->file,
                  "The stream on a disc image, e.g. '\\DATA\\DAY.VBI;1' (default: its only VBIM stream)");
  cmd->add_option("--config", r->config, "Platform config (TOML; `vbim config --defaults` lists every key)")
      ->check(inputFile());
  cmd->add_option("--faults", r->faults, "Fault plan (TOML; docs/fault-plans.md)")->check(inputFile());
  cmd->add_option("--seed", r->seed, "Seed of every random draw of the model")->capture_default_str();
  cmd->add_option("--duration", r->duration, "Simulated time to play (e.g. 60s)")->capture_default_str();
  cmd->add_option("--policy", r->policy, "Catch-up policy: blend-through (default), hard-skip or play-late");
  cmd->add_option("--every", r->every, "Write the lightmap and sky every N vsyncs (0: never)")
      ->check(nonNegativeInteger())
      ->capture_default_str();
  cmd->add_option("--at", r->at, "Write the images at these times (12.5s,30s,...)")->delimiter(',');
  cmd->add_option("--format", r->format, "Image format: png or exr")->capture_default_str();
  cmd->add_option(
         "--png-level", r->pngLevel,
         "PNG compression (zlib's level): 0 stores the pixels (fastest, ~2.5x the bytes), 1 to 9 compress (1: about "
         "libpng's default size, ~3x the CPU of 0; docs/player.md, \"Saving frames\")")
      ->capture_default_str();
  cmd->add_option("--alpha", r->alpha,
                  "Alpha of the pictures: opaque (255, for viewers) or gs (the texels as in VRAM: 0x80 is 1.0, "
                  "the bytes hashes.txt hashes)")
      ->check(CLI::IsMember({"opaque", "gs"}))
      ->capture_default_str();
  cmd->add_option("--branch", r->branches, "Switch to a variant at a time: 12.5s=1 (repeatable)");
  cmd->add_flag("--force", r->force, "Replace a non-empty output directory");
  cmd->add_flag_callback(
      "--no-trace", [r] { r->trace = false; }, "Skip trace.json and signals.vcd (written as the run goes)");
  cmd->add_option("--trace-detail", r->traceDetail,
                  "coalesced: signals.vcd keeps the value each signal ends an instant with; full: every change")
      ->check(CLI::IsMember({"coalesced", "full"}))
      ->capture_default_str();
  cmd->add_option("--threads", r->threads,
                  "Host threads for the IPU's slice-parallel picture decode (same bytes out; default 1)")
      ->capture_default_str()
      ->check(hostThreads());
  cmd->add_option("--out", r->out, "Output directory (written complete or not at all)")->required();
  cmd->footer(
      "Examples:\n"
      "  vbim play streams/samples/day_clear.vbim --out run/\n"
      "  vbim play streams/samples/day_clear.vbim --faults plan.toml --seed 7 --duration 60s --every 60 --out run/\n");
  cmd->callback([r] { std::cout << runPlay(*r, true); });
}

}  // namespace vbim::cli
