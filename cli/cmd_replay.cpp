// vbim replay: the GS side of a run (blend and present at every vsync, with the GS's timing) fed by
// an arrival schedule, a port's log or the arrivals.csv of `vbim play`; writes hashes.txt,
// timeline.csv and pictures like play, says which arrivals came late or were never shown, and with
// --compare names the first vsync whose hash differs from a run's or a port's (docs/porting.md,
// "Replay"). The replay is runs::replayRun (runs/replay_run.hpp).
#include <iostream>
#include <memory>

#include "cli/command.hpp"
#include "cli/common_options.hpp"
#include "cli/option_checks.hpp"
#include "cli/progress.hpp"
#include "runs/play_json.hpp"
#include "runs/replay_run.hpp"

namespace vbim::cli {

void addReplay(CLI::App& app) {
  auto r = std::make_shared<runs::ReplayRequest>();
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
  cmd->add_option("--policy", r->policy, "Catch-up policy: blend-through (default), hard-skip or play-late")
      ->check(catchupPolicy());
  cmd->add_option("--every", r->every, "Write the lightmap and sky every N vsyncs (0: never)")
      ->check(nonNegativeInteger())
      ->capture_default_str();
  cmd->add_option("--format", r->format, "Image format: png or exr")
      ->check(oneOf("--format", {"png", "exr"}))
      ->capture_default_str();
  cmd->add_option("--alpha", r->alpha,
                  "Alpha of the pictures: opaque (RGB, no alpha) or gs (RGBA, the texels as in VRAM)")
      ->check(CLI::IsMember({"opaque", "gs"}))
      ->capture_default_str();
  cmd->add_flag("--force", r->force, "Replace a non-empty output directory");
  cmd->add_flag("--json", r->json,
                "Print the summary as JSON on stdout: late and unshown arrivals, --compare's first difference "
                "(docs/cli.md, \"JSON summaries\")");
  cmd->add_option("-o,--out", r->out, "Output directory (written complete or not at all)")->required();
  cmd->footer(
      "Examples:\n"
      "  vbim replay streams/samples/day_clear.vbim --arrivals run/arrivals.csv --out replayed/\n"
      "  vbim replay streams/samples/day_clear.vbim --arrivals port-log.csv --duration 10s --out replayed/\n"
      "  vbim replay streams/samples/day_clear.vbim --arrivals run/arrivals.csv --out replayed/ --json\n"
      "  vbim replay disc.iso --file '\\DATA\\DAY.VBI;1' --arrivals run-iso/arrivals.csv --out replayed-iso/\n"
      "  vbim replay streams/samples/day_clear.vbim --arrivals port-log.csv --compare port-hashes.txt --out "
      "replayed/\n"
      "  vbim replay streams/samples/day_clear.vbim --arrivals port-log.csv --frames port-frames/ --compare "
      "run/ --out replayed/\n");
  cmd->callback([r] {
    Progress bar("vbim replay", "vsyncs");
    // Every second of the replay: the progress line, and where Ctrl-C stops it (it ran to the end).
    r->progress = [&bar](std::int64_t done, std::int64_t total) {
      bar.show(static_cast<double>(done), static_cast<double>(total));
    };
    const runs::ReplayResult result = runs::replayRun(
        *r, [](const std::string& warning) { std::cerr << "vbim replay: warning: " << warning << "\n"; });
    r->progress = nullptr;
    bar.finish();
    if (r->json) {
      if (result.jsonReplaced) std::cerr << "vbim replay: " << runs::kNotUtf8Warning << "\n";
      requestedOut() << result.report;  // also under --quiet, and before the exit 1 of a difference
    } else {
      std::cout << result.report;
    }
    if (result.differs) {
      throw Exit(1, "the replay differs from " + *result.differs +
                        (r->json ? " (the first difference is the JSON's compare.first_difference)"
                                 : " (the first difference is above)"));
    }
  });
}

}  // namespace vbim::cli
