#include "runs/decode_json.hpp"

#include <nlohmann/json.hpp>

#include "runs/play_json.hpp"
#include "streams/decode/frame_files.hpp"
#include "streams/format.hpp"

namespace vbim::runs {

using Json = nlohmann::ordered_json;

const char* issueKey(ipu::IssueKind kind) {
  switch (kind) {
    case ipu::IssueKind::kBadVlc:
      return "bad_vlc";
    case ipu::IssueKind::kTruncatedSlice:
      return "truncated_slice";
    case ipu::IssueKind::kCoefficientOverrun:
      return "coefficient_overrun";
    case ipu::IssueKind::kBadMacroblockAddress:
      return "bad_macroblock_address";
    case ipu::IssueKind::kBadSlicePosition:
      return "bad_slice_position";
    case ipu::IssueKind::kMissingMacroblocks:
      return "missing_macroblocks";
    case ipu::IssueKind::kMissingSequenceHeader:
      return "missing_sequence_header";
    case ipu::IssueKind::kMissingPictureHeader:
      return "missing_picture_header";
    case ipu::IssueKind::kMissingCodingExtension:
      return "missing_coding_extension";
    case ipu::IssueKind::kBadHeader:
      return "bad_header";
    case ipu::IssueKind::kAbsurdSize:
      return "absurd_size";
    case ipu::IssueKind::kUnsupportedChromaFormat:
      return "unsupported_chroma_format";
    case ipu::IssueKind::kUnsupportedPictureType:
      return "unsupported_picture_type";
    case ipu::IssueKind::kBadMotionVector:
      return "bad_motion_vector";
    case ipu::IssueKind::kMissingReference:
      return "missing_reference";
    case ipu::IssueKind::kPredictedPictureOnIdec:
      return "predicted_picture_on_idec";
  }
  return "unknown";
}

namespace {

Json orNull(const std::string& s) {
  return s.empty() ? Json(nullptr) : Json(s);
}

// picture_coding_type as its letter (ISO/IEC 13818-2 Table 6-12), null when the header was not read.
Json codingType(int type) {
  static constexpr const char* kLetters[] = {"I", "P", "B", "D"};
  return type >= 1 && type <= 4 ? Json(kLetters[type - 1]) : Json(nullptr);
}

Json issueJson(const streams::LocatedIssue& i) {
  return Json{{"byte", i.fileOffset},
              {"macroblock", i.mbX >= 0 ? Json{{"column", i.mbX}, {"row", i.mbY}} : Json(nullptr)},
              {"kind", issueKey(i.kind)},
              {"reason", ipu::issueName(i.kind)}};
}

Json pictureJson(const streams::DamagedPicture& p, streams::FrameFileFormat format, bool written) {
  Json issues = Json::array();
  for (const streams::LocatedIssue& i : p.issues) issues.push_back(issueJson(i));
  return Json{{"picture", p.picture},
              {"frame", p.frame >= 0 ? Json(p.frame) : Json(nullptr)},
              {"file", p.frame >= 0 && written ? Json(streams::frameFileName(p.frame, format)) : Json(nullptr)},
              {"type", codingType(p.codingType)},
              {"byte", p.fileOffset},
              {"skipped", p.skipped},
              {"macroblocks", p.macroblocks},
              {"concealed_macroblocks", p.macroblocksConcealed},
              {"issue_count", p.issueCount},
              {"issues", std::move(issues)},
              {"issues_not_listed", p.issueCount - p.issues.size()}};
}

}  // namespace

std::string decodeSummaryJson(const DecodeRequest& r, const streams::DecodeInput& input, const std::string& name,
                              const streams::DecodeSummary& s, const DecodeOutput& out,
                              const std::string& strictFailure, bool& replaced) {
  const streams::FrameFileFormat format = streams::frameFileFormatNamed(r.format);
  Json j;
  // The path alone: `name` adds the file on a disc image, which "file" gives apart.
  const std::string path = input.fileOnDisc.empty() ? name : name.substr(0, name.size() - input.fileOnDisc.size() - 1);
  j["input"] = Json{{"path", path},
                    {"file", orNull(input.fileOnDisc)},
                    {"video_stream", s.streamId ? Json(streams::hexId(*s.streamId)) : Json(nullptr)},
                    {"bytes", input.bytes.size()}};
  // What decides the bytes out (--threads does not).
  j["options"] = Json{
      {"format", r.format}, {"png_level", format == streams::FrameFileFormat::Png ? Json(r.pngLevel) : Json(nullptr)},
      {"idct", r.idct},     {"th0", r.th0},
      {"th1", r.th1},       {"strict", r.strict}};
  j["video"] = Json{{"width", s.width}, {"height", s.height}, {"mpeg", s.mpeg2 ? 2 : 1}};
  j["pictures"] = s.pictures;
  j["frames"] = s.frames;
  j["issues"] = s.issues;
  j["concealed_macroblocks"] = s.concealedMacroblocks;
  j["skipped_pictures"] = s.skippedPictures;
  Json damaged = Json::array();
  for (const streams::DamagedPicture& p : s.damaged) damaged.push_back(pictureJson(p, format, out.written));
  j["damaged_pictures"] = std::move(damaged);
  Json defects = Json::array();
  for (const streams::StreamError& d : s.containerDefects)
    defects.push_back(Json{{"byte", d.byteOffset}, {"sector", d.sector}, {"message", d.message}});
  j["container_defects"] = std::move(defects);
  j["output"] = Json{{"directory", out.directory},
                     {"written", out.written},
                     {"files", out.files},
                     {"bytes", out.bytes},
                     {"file_pattern", std::string("frame_%05d.") + streams::extensionOf(format)}};
  j["strict_failed"] = !strictFailure.empty();
  return jsonText(j, replaced);
}

}  // namespace vbim::runs
