// vbim author: image sequences, Technique A (author_terrain.cpp) or the synthetic day generator ->
// one VBIM stream file, and with --iso a disc image holding it: runs::authorRun (runs/author_run.hpp).
#include <iostream>

#include "cli/author_terrain.hpp"
#include "cli/command.hpp"
#include "cli/progress.hpp"
#include "runs/author_run.hpp"

namespace vbim::cli {

namespace {

using namespace vbim::streams;

// --fps, --container-fps, --loop, --q, --bitrate, --gop, --b-frames, --open-gop, --exposure, --tone,
// --transfer, --white: what every source encodes with.
void addEncodeOptions(CLI::App* cmd, EncodeOptions& o) {
  cmd->add_option("--fps", o.fps, "Game-time frame rate: stream frames per second of game time (N or N/D)")
      ->capture_default_str();
  cmd->add_option("--container-fps", o.containerFps, "Frame rate written in the MPEG headers (what ffplay shows)")
      ->capture_default_str();
  cmd->add_option("--loop", o.loop, "Frame playback returns to after the last one")->capture_default_str();
  auto* q = cmd->add_option("--q", o.q, "Fixed quantiser_scale 1..31 (lower is better)")->capture_default_str();
  cmd->add_option("--bitrate", o.bitrate, "Target bit/s instead of a fixed quantiser (VBV sized for DVD)")->excludes(q);
  cmd->add_option("--gop", o.gop,
                  "Pictures per GOP, from one I picture to the next (1: every picture I; more: P pictures)")
      ->capture_default_str();
  cmd->add_option("--b-frames", o.bFrames, "B pictures between references (below --gop)")->capture_default_str();
  cmd->add_flag("--open-gop", o.openGop,
                "Let B pictures refer across GOP headers (default: closed GOPs); each variant's first frame and "
                "the loop frame still start a GOP no B picture reaches back from");
  cmd->add_option("--exposure", o.exposure, "Linear inputs: multiply by 2^EV before the curve")->capture_default_str();
  cmd->add_option("--tone", o.tone, "Tone curve for linear inputs: clamp, reinhard, filmic")->capture_default_str();
  cmd->add_option("--transfer", o.transfer, "Encoding after the curve: srgb, linear, gamma:G")->capture_default_str();
  cmd->add_option("--white", o.white, "8-bit code of 1.0 after the curve (128 = GS MODULATE 1.0)")
      ->capture_default_str();
}

}  // namespace

void addAuthor(CLI::App& app) {
  auto* cmd = app.add_subcommand(kAuthorCommand.name, kAuthorCommand.summary);
  auto o = std::make_shared<runs::AuthorRequest>();
  streams::FrameAuthorRequest& frames = o->frames;  // lives in `o`, as long as the app
  cmd->add_option("--frames", frames.sequences.frames,
                  "Lightmap frames, e.g. 'dir/lightmap_%04d.exr' (any OpenImageIO format)");
  cmd->add_option("--sky", frames.sequences.sky,
                  "Sky dome frames, e.g. 'dir/sky_%04d.exr' (same numbering as --frames)");
  cmd->add_option("--name", frames.sequences.name, "Variant name of --frames/--sky")->capture_default_str();
  cmd->add_option("--variant", frames.sequences.variants,
                  "Another variant (weather): NAME=LIGHTMAP_PATTERN; repeatable");
  cmd->add_option("--variant-sky", frames.sequences.variantSkies,
                  "Sky frames of a --variant: NAME=SKY_PATTERN; repeatable");
  addEncodeOptions(cmd, frames.encode);
  cmd->add_option("--input", frames.input, "auto (float files linear, integer files encoded), linear, encoded")
      ->capture_default_str();
  cmd->add_option("--synthetic", frames.synthetic,
                  "Generate a synthetic day instead: WEATHER[,WEATHER] (clear, overcast)");
  cmd->add_option("--synthetic-frames", frames.syntheticFrames, "Frames of the synthetic day")->capture_default_str();
  cmd->add_option("--synthetic-size", frames.syntheticSize, "Synthetic lightmap size WxH")->capture_default_str();
  cmd->add_option("--synthetic-sky-size", frames.syntheticSkySize, "Synthetic sky size WxH (0x0: no sky)")
      ->capture_default_str();
  cmd->add_option("-o,--out", o->out, "Output stream file (complete or left as it was)")->required();
  cmd->add_flag("--force", o->force, "Replace an existing output file");
  cmd->add_option("--iso", o->iso, "Also write an ISO 9660 disc image holding the stream (made with xorriso)");
  cmd->add_option("--iso-file", o->isoFile, "Where the stream lies on the --iso image (ISO 9660 level 1 names)")
      ->capture_default_str();
  auto terrain = std::make_shared<TerrainAuthorOptions>();
  addTerrainOptions(cmd, terrain);
  cmd->footer(
      "Examples:\n"
      "  vbim author --procedural --out day.vbim\n"
      "  vbim author --frames 'lm_%04d.exr' --sky 'sky_%04d.exr' --fps 1 --out day.vbim\n");
  cmd->callback([o, terrain] {
    o->technique = firstTerrainOptionGiven(*terrain);
    if (!o->technique.empty()) o->terrain = terrainRequest(*terrain);
    Progress progress("vbim author", "frames");
    runs::AuthorObserver observer;
    observer.onProgress = [&progress](double done, double total, const std::string& note) {
      progress.show(done, total, note);
    };
    observer.onText = [&progress](const std::string& text) {
      progress.finish();
      std::cout << text;
    };
    runs::authorRun(*o, observer);
  });
}

}  // namespace vbim::cli
