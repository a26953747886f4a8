#include "streams/decode/stream_decode.hpp"

#include <map>
#include <memory>
#include <vector>

#include "ipu/elementary_stream.hpp"
#include "ipu/simd/simd_kernels.hpp"
#include "runtime/worker_pool.hpp"
#include "streams/format.hpp"
#include "streams/video_elementary_stream.hpp"

namespace vbim::streams {
namespace {

constexpr int kListedSkips = 20;  // skipped pictures named one by one; the rest are counted

VideoElementaryStream videoOf(std::span<const std::uint8_t> file, const std::string& name,
                              std::optional<std::uint8_t> streamId) {
  switch (detectStreamForm(file)) {
    case StreamForm::ProgramStream: {
      VideoElementaryStream video = readVideoStream(file, streamId);
      if (!video.streamId) {
        throw Error(
            name + ": MPEG program stream without " +
            (streamId ? "video stream " + hexId(*streamId) : std::string("a video stream (PES id 0xE0..0xEF)")));
      }
      return video;
    }
    case StreamForm::ElementaryStream:
      // If it lacks a sequence header the decoder says so.
      return rawVideoStream(file);
    case StreamForm::NotMpeg:
      break;
  }
  throw Error(name +
              ": byte 0: not an MPEG program stream or video elementary stream "
              "(expected 00 00 01 BA or 00 00 01 B3)");
}

// Which frame number each damaged picture is written as. The decoder shows frames in display order
// from its three frame stores (ipu/reference_frames.hpp), so the pictures decoded into a store since
// it was last shown are the ones its next display carries (two fields make one frame).
class FrameNumbers {
 public:
  // Before decoding a picture: whether it may be the second field of the frame begun last.
  void beforePicture(const ipu::Decoder& d) { fieldStore_ = d.fieldPending() ? &d.frame() : nullptr; }
  // After it was decoded into d.frame(): `damaged` is its index in the summary's list, or -1.
  void decoded(const ipu::Decoder& d, int damaged) {
    std::vector<int>& in = pending_[&d.frame()];
    if (&d.frame() != fieldStore_) in.clear();  // a new frame: what the store held was never shown
    if (damaged >= 0) in.push_back(damaged);
  }
  // The display frame is written as frame number `frame`.
  void shown(const ipu::Decoder& d, int frame, std::vector<DamagedPicture>& damaged) {
    std::vector<int>& in = pending_[d.displayFrame()];
    for (const int i : in) damaged[static_cast<std::size_t>(i)].frame = frame;
    in.clear();
  }

 private:
  const ipu::FrameStore* fieldStore_ = nullptr;
  std::map<const ipu::FrameStore*, std::vector<int>> pending_;
};

}  // namespace

DecodeSummary decodeStream(std::span<const std::uint8_t> file, const std::string& name, const DecodeOptions& options,
                           const FrameSink& frames, const DiagnosticSink& diagnostics) {
  const VideoElementaryStream video = videoOf(file, name, options.streamId);
  for (const StreamError& d : video.defects)
    diagnostics("warning: " + name + ": byte " + std::to_string(d.byteOffset) + ": " + d.message);

  ipu::DecoderOptions decoderOptions;
  decoderOptions.kernels = &ipu::simdKernels();  // same bytes as the scalar reference, faster
  decoderOptions.idct = options.idct;
  ipu::Decoder decoder(decoderOptions);
  std::unique_ptr<WorkerPool> pool;
  if (options.threads > 1) pool = std::make_unique<WorkerPool>(options.threads - 1);

  DecodeSummary summary;
  summary.containerDefects = video.defects;
  summary.streamId = video.streamId;
  if (video.streamId) summary.streamLabel = " (video stream " + hexId(*video.streamId) + ")";
  const std::string source = name + summary.streamLabel;
  std::string firstSkipped;  // why the first picture that could not be decoded was skipped
  FrameNumbers numbers;
  const auto show = [&] {
    numbers.shown(decoder, summary.frames, summary.damaged);
    frames(summary.frames++, decoder);
  };
  for (const ipu::AccessUnit& au : ipu::splitAccessUnits(video.bytes)) {
    const auto bytes = std::span(video.bytes).subspan(au.offset, au.size);
    numbers.beforePicture(decoder);
    const ipu::PictureReport r = pool ? decoder.decode(bytes, *pool) : decoder.decode(bytes);
    summary.issues += r.issueCount;
    if (!r.produced && !r.undecodable && r.clean()) continue;  // no picture in these bytes
    const int picture = summary.pictures++;
    int damagedIndex = -1;
    if (r.undecodable || r.issueCount > 0 || r.macroblocksConcealed > 0) {
      damagedIndex = static_cast<int>(summary.damaged.size());
      DamagedPicture& p = summary.damaged.emplace_back();
      p.picture = picture;
      p.codingType = r.pictureCodingType;
      p.fileOffset = video.fileOffsetOf(au.offset);
      p.skipped = r.undecodable;
      p.issueCount = r.issueCount;
      p.macroblocks = r.macroblocks;
      p.macroblocksConcealed = r.macroblocksConcealed;
      for (const ipu::DecodeIssue& is : r.issues)
        p.issues.push_back({is.kind, video.fileOffsetOf(au.offset + is.byteOffset), is.mbX, is.mbY});
    }
    if (r.undecodable) {
      // A picture header the decoder cannot use (damaged, or a sequence it does not support): the
      // picture is skipped and the decode goes on, as libmpeg2 and libavcodec do; the pictures that
      // predict from it use the reference before it (ipu/README.md, "Bad input").
      const ipu::IssueKind k = r.issues.empty() ? ipu::IssueKind::kBadHeader : r.issues.back().kind;
      const std::string why =
          source + ": byte " + std::to_string(video.fileOffsetOf(au.offset)) + ": cannot decode: " + ipu::issueName(k);
      if (firstSkipped.empty()) firstSkipped = why;
      if (summary.skippedPictures < kListedSkips) diagnostics(why + "; picture skipped");
      if (summary.skippedPictures == kListedSkips)
        diagnostics("... more pictures that cannot be decoded are skipped and counted, not listed");
      ++summary.skippedPictures;
      continue;
    }
    if (r.produced) numbers.decoded(decoder, damagedIndex);
    for (const ipu::DecodeIssue& is : r.issues) {
      std::string line = source + ": byte " + std::to_string(video.fileOffsetOf(au.offset + is.byteOffset));
      if (is.mbX >= 0) {
        line += ", picture " + std::to_string(picture) + " macroblock (" + std::to_string(is.mbX) + "," +
                std::to_string(is.mbY) + ")";
      }
      diagnostics(line + ": " + ipu::issueName(is.kind));
    }
    if (r.issueCount > r.issues.size())
      diagnostics("... and " + std::to_string(r.issueCount - r.issues.size()) + " more issues in this picture");
    summary.concealedMacroblocks += r.macroblocksConcealed;
    // Frames leave in display order (§6.1.1.11): B frames at once, I and P frames when the next
    // one is complete, the last at the end.
    if (decoder.displayFrame()) show();
  }
  while (decoder.flushDisplay()) show();
  if (summary.frames == 0) {
    if (!firstSkipped.empty()) throw Error(firstSkipped);
    if (!decoder.hasSequence()) throw Error(source + ": no sequence header: nothing can be decoded");
    throw Error(source + ": no picture could be decoded");
  }
  summary.width = decoder.width();
  summary.height = decoder.height();
  summary.mpeg2 = decoder.sequence().mpeg2;
  return summary;
}

}  // namespace vbim::streams
