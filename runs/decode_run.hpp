// `vbim decode STREAM --out DIR` as a library call: every picture of a stream through the IPU
// decoder (no timing) into frame files (streams/decode/), in an output directory written complete
// or not at all. The input is read as streams::readDecodeInput reads it (a stream file, standard
// input, or the stream on an ISO 9660 image). Not model code; no simulated time.
#pragma once

#include <functional>
#include <string>

#include "imageio/texel_files.hpp"
#include "ipu/kernels.hpp"

namespace vbim::runs {

struct DecodeRequest {
  std::string input;
  std::string file;  // the stream on a disc image, or empty: its only VBIM stream
  std::string out;
  std::string format = "png";  // png, exr, yuv, rgba (streams::frameFileFormatNamed)
  std::string streamId;        // "0xE1", or empty: the first video stream
  std::string idct = ipu::idctKindName(ipu::kDefaultIdct);
  unsigned threads = 0;
  bool force = false;
  bool strict = false;   // a decode issue (a concealed picture) fails the run, and nothing is written
  bool json = false;     // DecodeResult::summary as JSON (runs/decode_json.hpp)
  int th0 = 0, th1 = 0;  // SETTH
  int pngLevel = imageio::kDefaultTexelPngLevel;  // --png-level: 0 stored, 1 to 9 compressed (zlib), as vbim play's
};

struct DecodeResult {
  std::string summary;        // the summary line, or with `json` the JSON document
  bool jsonReplaced = false;  // `json`: bytes of the inputs not UTF-8 written as U+FFFD (kNotUtf8Warning)
  // Under `strict`, a stream with decode issues: the failure (exit 2), and nothing was written;
  // the summary says what was found all the same. Empty otherwise.
  std::string strictFailure;
};

// What the caller is told while the pictures are decoded (each may be empty).
struct DecodeObserver {
  std::function<void()> onPicture;                        // a frame written
  std::function<void(const std::string& line)> onReport;  // a decode issue, said as it is found
};

// Decodes into `out`; returns the summary (pictures, size, MPEG-1 or -2, stream, directory, format,
// and any issues with the macroblocks concealed). Throws vbim::Error for bad input (the file, the
// stream id, an existing --out); issues under `strict` are DecodeResult::strictFailure, which the
// caller makes an error after printing the summary (a --json document lists the damage).
DecodeResult decodeRun(const DecodeRequest& r, const DecodeObserver& observer);

}  // namespace vbim::runs
