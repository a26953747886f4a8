// vbim play: a disc through the whole pipeline on the simulated clock; writes images, hashes.txt,
// stats.json, trace.json, signals.vcd, timeline.csv and arrivals.csv into --out (docs/player.md), or,
// without --out, only prints the summary. The run is runs::playRun (runs/play_run.hpp).
#include <iostream>
#include <memory>

#include "cli/command.hpp"
#include "cli/common_options.hpp"
#include "cli/host_threads.hpp"
#include "cli/interrupt.hpp"
#include "cli/option_checks.hpp"
#include "cli/progress.hpp"
#include "runs/play_json.hpp"
#include "runs/play_run.hpp"
#include "streams/disc/standard_input.hpp"

namespace vbim::cli {

void printPlayResult(const runs::PlayResult& result) {
  if (!result.warning.empty()) std::cerr << "vbim play: " << result.warning << "\n";
  std::cout << result.summary;
}

void addPlay(CLI::App& app) {
  auto r = std::make_shared<runs::PlayRequest>();
  auto* cmd = app.add_subcommand("play", "Play a VBIM disc through the whole pipeline on the simulated clock");
  cmd->add_option("disc", r->disc,
                  "A VBIM stream file (a disc with one file) or an ISO 9660 disc image; - reads it from stdin")
      ->required()
      ->transform(stdinAsFile())
      ->check(inputFile());
  cmd->add_option("--file", r->file,
                  "The stream on a disc image, e.g. '\\DATA\\DAY.VBI;1' (default: its only VBIM stream)");
  cmd->add_option("--config", r->config, "Platform config (TOML; `vbim config --defaults` lists every key)")
      ->check(inputFile());
  cmd->add_option("--faults", r->faults, "Fault plan (TOML; docs/fault-plans.md)")->check(inputFile());
  cmd->add_option("--seed", r->seed, "Seed of every random draw of the model")->capture_default_str();
  cmd->add_option("--duration", r->duration, "Simulated time to play (e.g. 60s)")->capture_default_str();
  cmd->add_option("--policy", r->policy, "Catch-up policy: blend-through (default), hard-skip or play-late")
      ->check(catchupPolicy());
  cmd->add_option("--every", r->every, "Write the lightmap and sky every N vsyncs (0: never)")
      ->check(nonNegativeInteger())
      ->capture_default_str();
  cmd->add_option("--at", r->at, "Write the images at these times (12.5s,30s,...)")->delimiter(',');
  cmd->add_option("--format", r->format, "Image format: png or exr")
      ->check(oneOf("--format", {"png", "exr"}))
      ->capture_default_str();
  addPngLevelOption(*cmd, r->pngLevel);
  cmd->add_option("--alpha", r->alpha,
                  "Alpha of the pictures: opaque (RGB files, no alpha, as viewers show the game) or gs (RGBA, the "
                  "texels as in VRAM: 0x80 is 1.0, the bytes hashes.txt hashes)")
      ->check(CLI::IsMember({"opaque", "gs"}))
      ->capture_default_str();
  cmd->add_option("--branch", r->branches, "Switch to a variant at a time: 12.5s=1 (repeatable)");
  cmd->add_flag("--force", r->force, "Replace a non-empty output directory");
  cmd->add_flag("--json", r->json, "Print the summary as JSON on stdout (docs/cli.md, \"JSON summaries\")");
  cmd->add_flag_callback(
      "--no-trace", [r] { r->trace = false; }, "Skip trace.json and signals.vcd (written as the run goes)");
  cmd->add_option("--trace-detail", r->traceDetail,
                  "coalesced: signals.vcd keeps the value each signal ends an instant with; full: every change; "
                  "ipu: coalesced, and ipu_commands.csv with every IPU command word and its time (docs/run-files.md)")
      ->check(CLI::IsMember({"coalesced", "full", "ipu"}))
      ->capture_default_str();
  addThreadsOption(*cmd, r->threads, "Host threads for the IPU's slice-parallel picture decode");
  cmd->add_option("-o,--out", r->out,
                  "Output directory (written complete or not at all); without it, the run is played and "
                  "summarised and nothing is written");
  cmd->footer(
      "Examples:\n"
      "  vbim play streams/samples/day_clear.vbim --out run/\n"
      "  vbim play streams/samples/day_clear.vbim --duration 20s\n"
      "  vbim play streams/samples/day_clear.vbim --faults plan.toml --seed 7 --duration 60s --every 60 --out run/\n");
  cmd->callback([r] {
    if (streams::isStandardInput(r->disc)) r->discLabel = "<stdin>";  // the summary and stats.json
    Progress bar("vbim play", "s");
    const runs::PlayResult result = runs::playRun(*r, [&bar](double played, double total) {
      bar.show(played, total);
      checkInterrupted();
    });
    bar.finish();
    if (r->json) {
      if (result.jsonReplaced) std::cerr << "vbim play: " << runs::kNotUtf8Warning << "\n";
      if (!result.warning.empty()) std::cerr << "vbim play: " << result.warning << "\n";
      requestedOut() << result.summary;
      return;
    }
    printPlayResult(result);
  });
}

}  // namespace vbim::cli
