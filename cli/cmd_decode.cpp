// vbim decode STREAM --out DIR --format png|exr|yuv|rgba: every picture of a stream through the IPU
// decoder (no timing). STREAM is an MPEG program stream (a VBIM stream, or any MPEG-2 program stream
// or MPEG-1 system stream) or a raw MPEG-1/2 video elementary stream (.m2v / .m1v). The work is
// runs::decodeRun (runs/decode_run.hpp, over streams/decode/); this file parses the arguments and prints.
#include <iostream>
#include <memory>
#include <string>

#include "cli/command.hpp"
#include "cli/common_options.hpp"
#include "cli/exit_status.hpp"
#include "cli/host_threads.hpp"
#include "cli/option_checks.hpp"
#include "cli/progress.hpp"
#include "runs/decode_run.hpp"
#include "runs/play_json.hpp"

namespace vbim::cli {
namespace {

void run(const runs::DecodeRequest& r) {
  Progress progress("vbim decode", "pictures");
  int pictures = 0;
  runs::DecodeObserver observer;
  observer.onPicture = [&] { progress.show(++pictures, 0); };
  observer.onReport = [&progress](const std::string& line) {
    progress.finish();  // a report starts on a line of its own
    std::cerr << "vbim decode: " << line << "\n";
  };
  const runs::DecodeResult result = runs::decodeRun(r, observer);
  progress.finish();
  if (r.json) {
    if (result.jsonReplaced) std::cerr << "vbim decode: " << runs::kNotUtf8Warning << "\n";
    requestedOut() << result.summary;  // also under --quiet, and also when --strict fails below
  } else if (result.strictFailure.empty()) {
    std::cout << result.summary;
  }
  if (!result.strictFailure.empty()) throw Exit(kExitBadInput, result.strictFailure);
}

}  // namespace

void addDecode(CLI::App& app) {
  auto* cmd = app.add_subcommand("decode", "Decode every picture of a stream with the IPU model (no timing)");
  auto o = std::make_shared<runs::DecodeRequest>();
  cmd->add_option("stream", o->input,
                  "MPEG program stream (VBIM stream), MPEG-1/2 video elementary stream, or an ISO 9660 disc image; - "
                  "reads it from stdin")
      ->required()
      ->transform(stdinAsFile())
      ->check(inputFile());
  cmd->add_option("--file", o->file,
                  "The stream on a disc image, e.g. '\\DATA\\DAY.VBI;1' (default: its only VBIM stream)");
  cmd->add_option("-o,--out", o->out, "Output directory (written completely or not at all)")->required();
  cmd->add_option("--format", o->format,
                  "png (RGBA, GS alpha doubled), exr (half float), yuv (planar 4:2:0) or rgba (raw RGB32 bytes, GS "
                  "alpha: what `vbim replay --frames` reads)")
      ->capture_default_str()
      ->check(CLI::IsMember({"png", "exr", "yuv", "rgba"}));
  addPngLevelOption(*cmd, o->pngLevel);
  cmd->add_option("--stream-id", o->streamId, "PES stream id to decode, e.g. 0xE1 (default: the first video stream)");
  addThreadsOption(*cmd, o->threads, "Host threads for the slice-parallel decode");
  cmd->add_option("--idct", o->idct, "Inverse DCT as ipu.idct: pcsx2, libmpeg2 (mpeg2dec -c) or exact")
      ->capture_default_str()
      ->check(CLI::IsMember({"pcsx2", "libmpeg2", "exact"}));
  cmd->add_option("--th0", o->th0, "SETTH TH0: pixels with R, G, B all below it become transparent black")
      ->check(CLI::Range(0, 511));
  cmd->add_option("--th1", o->th1, "SETTH TH1: pixels with R, G, B all below it get alpha 0x40")
      ->check(CLI::Range(0, 511));
  cmd->add_flag("--force", o->force, "Replace a non-empty output directory");
  cmd->add_flag("--strict", o->strict, "Fail (exit 2) if any picture needed concealment");
  cmd->add_flag("--json", o->json,
                "Print the summary as JSON on stdout, with every damaged picture (docs/cli.md, \"JSON summaries\")");
  cmd->footer(
      "Examples:\n"
      "  vbim decode streams/samples/day_clear.vbim --out frames/\n"
      "  vbim decode streams/samples/day_clear.vbim --out frames/ --format exr --threads 2\n"
      "  vbim decode streams/samples/day_clear.vbim --out frames/ --json\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vbim::cli
