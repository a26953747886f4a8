#include "runs/author_run.hpp"

#include <filesystem>

#include "iop/error.hpp"
#include "runs/error.hpp"
#include "runs/output_dir.hpp"
#include "streams/disc/iso_disc.hpp"
#include "streams/disc/iso_writer.hpp"

namespace vbim::runs {

namespace {

void checkRequest(const AuthorRequest& r) {
  refuseExistingOutputFile(r.out, r.force);  // before minutes of encoding, not after
  if (!r.iso.empty() && std::filesystem::path(r.iso) == std::filesystem::path(r.out)) {
    throw Error("--iso " + r.iso + " is the --out stream file; give the image another name");
  }
  if (const std::string why = streams::level1PathProblem(r.isoFile); !r.iso.empty() && !why.empty()) {
    throw Error("--iso-file '" + r.isoFile + "': " + why);
  }
  if (r.technique.empty()) return;
  // Technique A renders its own frames: the image-sequence and synthetic options do not apply.
  const streams::SequenceOptions& seq = r.frames.sequences;
  if (!seq.frames.empty() || !seq.sky.empty() || !seq.variants.empty() || !seq.variantSkies.empty() ||
      !r.frames.synthetic.empty()) {
    throw Error(r.technique +
                " selects Technique A, which renders its own frames; it excludes --frames, --sky, "
                "--variant, --variant-sky and --synthetic");
  }
}

// The stream Technique A renders, one frame at a time in memory; the notes and the summary.
std::string authorTerrain(const AuthorRequest& r, const AuthorObserver& observer) {
  lighting::TerrainAuthorRequest request = r.terrain;
  request.encode = r.frames.encode;
  const lighting::TechniqueAStreamSettings s = lighting::terrainAuthorSettings(request);
  const lighting::AuthoredStream stream =
      lighting::authorTechniqueA(s, r.out, [&](const lighting::TechniqueAProgress& p) {
        if (observer.onProgress) observer.onProgress(p.done, p.total, p.variant + " " + std::to_string(p.frame));
      });
  std::string text;
  for (const std::string& note : stream.terrainNotes)
    text += "vbim author: " + r.terrain.terrain.heightfield + ": " + note + "\n";
  return text + lighting::authoredSummary(r.out, stream, s.stream.encoder.containerFps);
}

// The stream just written, on an ISO 9660 image at isoFile: the line said about it.
std::string writeDiscImage(const AuthorRequest& r) {
  try {
    streams::writeIsoImage(r.iso, {{r.isoFile, r.out}});
    const auto f = streams::IsoDisc(r.iso).find(r.isoFile);
    return r.iso + ": ISO 9660 image, " + r.isoFile + " at LBA " + std::to_string(f->lba) + " (vbim play " + r.iso +
           ")\n";
  } catch (const iop::DiscError& e) {
    throw RunFailure(e.what());  // the stream is written; the image (xorriso) failed
  }
}

}  // namespace

void authorRun(const AuthorRequest& r, const AuthorObserver& observer) {
  checkRequest(r);
  const auto say = [&observer](const std::string& text) {
    if (observer.onText) observer.onText(text);
  };
  if (r.technique.empty()) {
    say(streams::authorFrameStream(r.frames, r.out, [&](const streams::FrameAuthorProgress& p) {
      if (observer.onProgress) observer.onProgress(static_cast<double>(p.done), static_cast<double>(p.total), p.label);
    }));
  } else {
    say(authorTerrain(r, observer));
  }
  if (!r.iso.empty()) say(writeDiscImage(r));
}

}  // namespace vbim::runs
