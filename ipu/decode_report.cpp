#include "ipu/decode_report.hpp"

namespace vbim::ipu {

const char* issueName(IssueKind k) {
  switch (k) {
    case IssueKind::kBadVlc:
      return "invalid variable-length code";
    case IssueKind::kTruncatedSlice:
      return "slice data ends inside a macroblock";
    case IssueKind::kCoefficientOverrun:
      return "DCT coefficients run past the end of the block";
    case IssueKind::kBadMacroblockAddress:
      return "macroblock address increment out of range or skip in intra picture";
    case IssueKind::kBadSlicePosition:
      return "slice vertical position outside the picture";
    case IssueKind::kMissingMacroblocks:
      return "macroblocks not covered by any slice";
    case IssueKind::kMissingSequenceHeader:
      return "no sequence header before the picture";
    case IssueKind::kMissingPictureHeader:
      return "slice data without a picture header";
    case IssueKind::kMissingCodingExtension:
      return "MPEG-2 picture without a picture coding extension";
    case IssueKind::kBadHeader:
      return "header or extension too short or invalid";
    case IssueKind::kAbsurdSize:
      return "picture size zero or beyond the limit";
    case IssueKind::kUnsupportedChromaFormat:
      return "chroma format other than 4:2:0 (the IPU decodes 4:2:0 only)";
    case IssueKind::kUnsupportedPictureType:
      return "D picture (DC-only pictures are not supported)";
    case IssueKind::kBadMotionVector:
      return "motion vector points outside the reference frame";
    case IssueKind::kMissingReference:
      return "reference frame missing (predicted from mid-grey)";
    case IssueKind::kPredictedPictureOnIdec:
      return "P or B picture on the IDEC path (IDEC decodes intra pictures only; decode the stream on the BDEC path)";
  }
  return "unknown";
}

std::string PictureReport::describe() const {
  std::string out;
  for (const DecodeIssue& i : issues) {
    out += "byte " + std::to_string(i.byteOffset);
    if (i.mbX >= 0) out += " (macroblock " + std::to_string(i.mbX) + "," + std::to_string(i.mbY) + ")";
    out += ": ";
    out += issueName(i.kind);
    out += "\n";
  }
  if (issueCount > issues.size()) out += "... and " + std::to_string(issueCount - issues.size()) + " more\n";
  return out;
}

}  // namespace vbim::ipu
