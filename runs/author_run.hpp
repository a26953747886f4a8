// `vbim author --out STREAM [--iso IMAGE]` as a library call: one VBIM stream file from image
// sequences or the synthetic day (streams::authorFrameStream, streams/authoring/frame_author.hpp) or
// from Technique A (lighting::authorTerrainStream, lighting/authoring/terrain_author.hpp), and, with
// an image named, an ISO 9660 disc image holding it (streams/disc/iso_writer.hpp). In library
// vbim_author_run (FFmpeg, OpenImageIO, GDAL), which only vbim-full links. Host time only.
#pragma once

#include <functional>
#include <string>

#include "lighting/authoring/terrain_author.hpp"
#include "streams/authoring/frame_author.hpp"

namespace vbim::runs {

struct AuthorRequest {
  streams::FrameAuthorRequest frames;  // --frames ... or --synthetic ..., and the encoder's options
  // Technique A, when `technique` names the first of its options given ("--procedural"); its encoder
  // options are `frames.encode`.
  lighting::TerrainAuthorRequest terrain;
  std::string technique;
  std::string out;
  bool force = false;
  std::string iso;                            // also a disc image holding the stream, or empty
  std::string isoFile = "\\DATA\\DAY.VBI;1";  // where the stream lies on it
};

// What the caller is told while it runs (each may be empty).
struct AuthorObserver {
  std::function<void(double done, double total, const std::string& note)> onProgress;  // frames
  // What `vbim author` prints, in order, as it is known: the terrain's notes and the stream's summary
  // once the stream is written, then the disc image's line.
  std::function<void(const std::string& text)> onText;
};

// Checks the request before any encoding (an existing --out, --iso naming the stream or a bad
// --iso-file, Technique A with the other sources' options: vbim::Error), authors the stream, then
// writes the image; an image that cannot be written is a RunFailure (runs/error.hpp).
void authorRun(const AuthorRequest& r, const AuthorObserver& observer);

}  // namespace vbim::runs
