// vbim vectors: the known-answer vectors a console port checks itself against (docs/porting.md,
// "Known-answer vectors"). --out DIR writes them; --check DIR compares a port's captured files with
// them, every entry (or the stages and keys --only selects), and scores each file: pass, fail with
// the first differences and where in the value, or absent (exit 1 when a present file fails). The
// vectors, their writing and the scoring are runs::vectorsRun's (runs/vectors_run.hpp).
#include <iostream>
#include <memory>

#include "cli/command.hpp"
#include "cli/interrupt.hpp"
#include "cli/option_checks.hpp"
#include "runs/vectors_run.hpp"

namespace vbim::cli {

namespace {

void run(const runs::VectorsRequest& r) {
  // A Ctrl-C while the vectors are computed or written stops the run before the directory takes its name.
  const runs::VectorsVerdict v = runs::vectorsRun(r, checkInterrupted);
  if (!v.passed) throw Exit(1, v.text);
  std::cout << v.text;
}

}  // namespace

void addVectors(CLI::App& app) {
  auto r = std::make_shared<runs::VectorsRequest>();
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
