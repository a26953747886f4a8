#include "runs/decode_run.hpp"

#include <filesystem>
#include <sstream>
#include <system_error>

#include "imageio/png_encoder.hpp"
#include "runs/decode_json.hpp"
#include "runs/output_dir.hpp"
#include "streams/decode/decode_input.hpp"
#include "streams/decode/frame_files.hpp"
#include "streams/decode/stream_decode.hpp"
#include "streams/disc/standard_input.hpp"

namespace vbim::runs {

namespace {

// The frame files a committed output directory holds, and their bytes.
void countFiles(DecodeOutput& out) {
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(out.directory, ec)) {
    if (!e.is_regular_file(ec)) continue;
    ++out.files;
    out.bytes += e.file_size(ec);
  }
}

std::string summaryLine(const DecodeRequest& r, const streams::DecodeSummary& s, const std::string& directory) {
  std::ostringstream line;
  line << "decoded " << s.frames << " pictures " << s.width << "x" << s.height << " ("
       << (s.mpeg2 ? "MPEG-2" : "MPEG-1") << ")" << s.streamLabel << " to " << directory << "/ as " << r.format;
  if (r.format == "png") line << " (level " << r.pngLevel << ")";
  if (s.issues) line << "; " << s.issues << " issues, " << s.concealedMacroblocks << " macroblocks concealed";
  if (s.skippedPictures) {
    line << ", " << s.skippedPictures << (s.skippedPictures == 1 ? " picture" : " pictures")
         << " skipped (cannot be decoded)";
  }
  line << "\n";
  return line.str();
}

}  // namespace

DecodeResult decodeRun(const DecodeRequest& r, const DecodeObserver& observer) {
  imageio::checkPngLevelOption(r.pngLevel);
  streams::DecodeOptions options;
  options.threads = r.threads;
  options.idct = ipu::idctKindByName(r.idct).value_or(ipu::kDefaultIdct);
  if (!r.streamId.empty()) options.streamId = streams::parseStreamId(r.streamId);
  const streams::DecodeInput in = streams::readDecodeInput(r.input, r.file);
  const std::string name = streams::nameStandardInput(in.name);
  OutputDir dir(r.out, r.force);
  streams::FrameFileWriter writer(dir.directory(), streams::frameFileFormatNamed(r.format),
                                  ipu::CscThresholds{r.th0, r.th1}, r.pngLevel);
  const streams::DecodeSummary s = streams::decodeStream(
      in.bytes, name, options,
      [&](int frame, const ipu::Decoder& d) {
        writer.write(frame, d);
        if (observer.onPicture) observer.onPicture();
      },
      [&observer](const std::string& line) {
        if (observer.onReport) observer.onReport(line);
      });
  DecodeResult result;
  DecodeOutput out;
  out.directory = dir.finalPath().string();
  if (r.strict && s.issues > 0) {
    // Nothing is committed: the temporary directory goes with `dir`.
    result.strictFailure = name + s.streamLabel + ": " + std::to_string(s.issues) + " issues (--strict)";
  } else {
    dir.commit();
    out.written = true;
    countFiles(out);
  }
  result.summary = r.json ? decodeSummaryJson(r, in, name, s, out, result.strictFailure, result.jsonReplaced)
                          : summaryLine(r, s, out.directory);
  return result;
}

}  // namespace vbim::runs
