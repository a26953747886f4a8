// vbim author: image sequences, Technique A (author_terrain.cpp) or the synthetic day generator ->
// one VBIM stream file.
#include <filesystem>
#include <iostream>
#include <utility>

#include "cli/author_terrain.hpp"
#include "cli/command.hpp"
#include "cli/progress.hpp"
#include "iop/error.hpp"
#include "runs/output_dir.hpp"
#include "streams/authoring/frame_author.hpp"
#include "streams/disc/iso_disc.hpp"
#include "streams/disc/iso_writer.hpp"

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

struct AuthorOptions {
  FrameAuthorRequest frames;  // --frames ... or --synthetic ...
  std::string out;
  bool force = false;
  std::string iso, isoFile = "\\DATA\\DAY.VBI;1";  // --iso: also a disc image holding the stream
};

// --iso: the stream just written, on an ISO 9660 image at --iso-file.
void writeDiscImage(const AuthorOptions& o) {
  try {
    writeIsoImage(o.iso, {{o.isoFile, o.out}});
    const auto f = IsoDisc(o.iso).find(o.isoFile);
    std::cout << o.iso << ": ISO 9660 image, " << o.isoFile << " at LBA " << f->lba << " ("
              << "vbim play " << o.iso << ")\n";
  } catch (const iop::DiscError& e) {
    throw Exit(1, e.what());
  }
}

// Image sequences or the synthetic day (streams/authoring/frame_author.hpp).
void runAuthor(const AuthorOptions& o) {
  Progress progress("vbim author", "frames");
  const std::string lines = authorFrameStream(o.frames, o.out, [&](const FrameAuthorProgress& p) {
    progress.show(static_cast<double>(p.done), static_cast<double>(p.total), p.label);
  });
  progress.finish();
  std::cout << lines;
}

}  // namespace

void addAuthor(CLI::App& app) {
  auto* cmd = app.add_subcommand(kAuthorCommand.name, kAuthorCommand.summary);
  auto o = std::make_shared<AuthorOptions>();
  cmd->add_option("--frames", o->frames.sequences.frames,
                  "Lightmap frames, e.g. 'dir/lightmap_%04d.exr' (any OpenImageIO format)");
  cmd->add_option("--sky", o->frames.sequences.sky,
                  "Sky dome frames, e.g. 'dir/sky_%04d.exr' (same numbering as --frames)");
  cmd->add_option("--name", o->frames.sequences.name, "Variant name of --frames/--sky")->capture_default_str();
  cmd->add_option("--variant", o->frames.sequences.variants,
                  "Another variant (weather): NAME=LIGHTMAP_PATTERN; repeatable");
  cmd->add_option("--variant-sky", o->frames.sequences.variantSkies,
                  "Sky frames of a --variant: NAME=SKY_PATTERN; repeatable");
  addEncodeOptions(cmd, o->frames.encode);
  cmd->add_option("--input", o->frames.input, "auto (float files linear, integer files encoded), linear, encoded")
      ->capture_default_str();
  cmd->add_option("--synthetic", o->frames.synthetic,
                  "Generate a synthetic day instead: WEATHER[,WEATHER] (clear, overcast)");
  cmd->add_option("--synthetic-frames", o->frames.syntheticFrames, "Frames of the synthetic day")
      ->capture_default_str();
  cmd->add_option("--synthetic-size", o->frames.syntheticSize, "Synthetic lightmap size WxH")->capture_default_str();
  cmd->add_option("--synthetic-sky-size", o->frames.syntheticSkySize, "Synthetic sky size WxH (0x0: no sky)")
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
    runs::refuseExistingOutputFile(o->out, o->force);  // before minutes of encoding, not after
    if (!o->iso.empty() && std::filesystem::path(o->iso) == std::filesystem::path(o->out)) {
      throw Exit(2, "--iso " + o->iso + " is the --out stream file; give the image another name");
    }
    if (const std::string why = level1PathProblem(o->isoFile); !o->iso.empty() && !why.empty()) {
      throw Exit(2, "--iso-file '" + o->isoFile + "': " + why);
    }
    const std::string technique = firstTerrainOptionGiven(*terrain);
    if (technique.empty()) {
      runAuthor(*o);
      if (!o->iso.empty()) writeDiscImage(*o);
      return;
    }
    // Technique A renders its own frames: the image-sequence and synthetic options do not apply.
    const SequenceOptions& seq = o->frames.sequences;
    if (!seq.frames.empty() || !seq.sky.empty() || !seq.variants.empty() || !seq.variantSkies.empty() ||
        !o->frames.synthetic.empty()) {
      throw Exit(2, technique +
                        " selects Technique A, which renders its own frames; it excludes --frames, --sky, "
                        "--variant, --variant-sky and --synthetic");
    }
    runTerrainAuthor(*terrain, o->frames.encode, o->out);
    if (!o->iso.empty()) writeDiscImage(*o);
  });
}

}  // namespace vbim::cli
