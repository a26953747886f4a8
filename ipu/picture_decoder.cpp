#include "ipu/picture_decoder.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "ipu/quant_tables.hpp"

namespace vbim::ipu {
namespace {

// Position of the next start code prefix 00 00 01 at or after `from`, or n.
std::size_t findStartCode(const std::uint8_t* d, std::size_t n, std::size_t from) {
  std::size_t i = from;
  while (i + 2 < n) {
    const void* hit = std::memchr(d + i + 2, 0x01, n - i - 2);
    if (!hit) return n;
    const std::size_t one = static_cast<std::size_t>(static_cast<const std::uint8_t*>(hit) - d);
    if (d[one - 1] == 0 && d[one - 2] == 0) return one - 2;
    i = one - 1;
  }
  return n;
}

}  // namespace

Decoder::Decoder(DecoderOptions options) : options_(options) {}

void Decoder::handleExtension(BitReader& br, PictureReport& report, std::size_t offset) {
  const int id = static_cast<int>(br.read(4));
  bool ok = true;
  switch (id) {
    case 1:  // sequence extension
      if (haveSequence_) ok = parseSequenceExtension(br, seq_);
      break;
    case 3:  // quant matrix extension: the SETIQ path
      if (haveSequence_) ok = parseQuantMatrixExtension(br, seq_);
      break;
    case 8:  // picture coding extension
      if (pictureOpen_) ok = parsePictureCodingExtension(br, pic_);
      break;
    default:  // display, scalability, copyright ...: not needed for decoding
      break;
  }
  if (!ok) report.add(IssueKind::kBadHeader, offset);
}

void Decoder::beginPicture(PictureReport& report, std::size_t offset) {
  pictureValid_ = false;
  report.pictureCodingType = pic_.codingType;
  report.temporalReference = pic_.temporalReference;
  auto fail = [&](IssueKind k) {
    report.add(k, offset);
    report.undecodable = true;
  };
  if (!haveSequence_) return fail(IssueKind::kMissingSequenceHeader);
  report.mpeg1 = !seq_.mpeg2;
  report.width = seq_.width;
  report.height = seq_.height;
  if (seq_.width <= 0 || seq_.height <= 0 || seq_.width > options_.maxWidth || seq_.height > options_.maxHeight)
    return fail(IssueKind::kAbsurdSize);
  if (seq_.chromaFormat != 1) return fail(IssueKind::kUnsupportedChromaFormat);
  if (pic_.codingType != 1) return fail(IssueKind::kUnsupportedPictureType);
  if (seq_.mpeg2 && !pic_.hasCodingExtension) return fail(IssueKind::kMissingCodingExtension);

  const int mbw = (seq_.width + 15) / 16;
  const int mbh = (!seq_.mpeg2 || seq_.progressiveSequence) ? (seq_.height + 15) / 16 : 2 * ((seq_.height + 31) / 32);
  if (store_.mbWidth != mbw || store_.mbHeight != mbh) store_.reset(mbw, mbh);

  PictureParams& p = params_;
  p = PictureParams{};
  p.mpeg1 = !seq_.mpeg2;
  p.idct = (options_.kernels ? *options_.kernels : scalarKernels()).idct;
  p.mbWidth = mbw;
  p.intraMatrix = seq_.intraMatrix;
  p.tallPicture = seq_.height > 2800;
  if (seq_.mpeg2) {
    p.scan = pic_.alternateScan ? kAlternateScan.data() : kZigzagScan.data();
    p.intraDcPrecision = pic_.intraDcPrecision;
    if (p.intraDcPrecision == 3 && options_.dcPrecision11AsNine) p.intraDcPrecision = 1;
    p.qScaleType = pic_.qScaleType;
    p.intraVlcFormat = pic_.intraVlcFormat;
    p.fieldPicture = pic_.pictureStructure != 3;
    p.fieldDctAllowed = !p.fieldPicture && !pic_.framePredFrameDct;
    p.concealmentMotionVectors = pic_.concealmentMotionVectors;
    p.fCode[0] = pic_.fCode[0][0];
    p.fCode[1] = pic_.fCode[0][1];
  } else {
    p.scan = kZigzagScan.data();
  }
  if (p.fieldPicture) {
    const int bottom = pic_.pictureStructure == 2 ? 1 : 0;
    p.mbRows = mbh / 2;
    p.y = store_.y.data() + bottom * store_.lumaStride;
    p.cb = store_.cb.data() + bottom * store_.chromaStride;
    p.cr = store_.cr.data() + bottom * store_.chromaStride;
    p.yStride = 2 * store_.lumaStride;
    p.cStride = 2 * store_.chromaStride;
  } else {
    p.mbRows = mbh;
    p.y = store_.y.data();
    p.cb = store_.cb.data();
    p.cr = store_.cr.data();
    p.yStride = store_.lumaStride;
    p.cStride = store_.chromaStride;
  }
  report.macroblocks += p.mbWidth * p.mbRows;
  decoded_.assign(static_cast<std::size_t>(p.mbWidth) * p.mbRows, 0);
  pictureValid_ = true;
}

void Decoder::finishPicture(std::span<const std::uint8_t> bytes, PictureReport& report, SliceRunner* pool) {
  pictureOpen_ = false;
  if (!pictureValid_) {
    slices_.clear();
    return;
  }
  pictureValid_ = false;
  const std::uint8_t* d = bytes.data();
  // Several row ranges per thread, so a worker that wakes late still finds work (the caller runs
  // ranges too); ranges are contiguous and disjoint, so the bytes never depend on who ran what.
  const std::size_t jobs =
      pool && pool->threads() > 0 ? std::min<std::size_t>(slices_.size(), 4 * (pool->threads() + std::size_t{1})) : 1;
  if (jobs > 1 && !params_.mpeg1 && !params_.tallPicture && slices_.size() > 1) {
    // MPEG-2 slices never leave their row, so contiguous row ranges are disjoint in the frame.
    std::vector<PictureReport> reports(jobs);
    std::vector<std::vector<MacroblockBits>> traces(jobs);
    // Contiguous row ranges with about the same number of bytes each (busy rows cost more).
    const int rows = params_.mbRows;
    std::vector<std::size_t> rowBytes(static_cast<std::size_t>(rows) + 1, 0);
    std::size_t total = 0;
    for (const Slice& s : slices_) {
      rowBytes[static_cast<std::size_t>(std::min(s.row, rows))] += s.end - s.begin;
      total += s.end - s.begin;
    }
    std::vector<int> firstRow(jobs + 1, rows + 1);
    firstRow[0] = 0;
    std::size_t acc = 0;
    std::size_t j = 1;
    for (int r = 0; r < rows && j < jobs; ++r) {
      acc += rowBytes[static_cast<std::size_t>(r)];
      if (acc * jobs >= total * j) firstRow[j++] = r + 1;
    }
    pool->run(jobs, [&](std::size_t k) {
      const int lo = firstRow[k];
      const int hi = k + 1 == jobs ? INT32_MAX : firstRow[k + 1];
      SliceOutput out{&reports[k], &decoded_, options_.recordMacroblocks ? &traces[k] : nullptr};
      for (const Slice& s : slices_) {
        if (s.row >= lo && s.row < hi) decodeSlice(params_, s.code, d + s.begin, d + s.end, s.begin, out);
      }
    });
    for (std::size_t j = 0; j < jobs; ++j) {
      report.issueCount += reports[j].issueCount;
      report.fieldDctMacroblocks += reports[j].fieldDctMacroblocks;
      for (const DecodeIssue& i : reports[j].issues)
        if (report.issues.size() < PictureReport::kMaxIssues) report.issues.push_back(i);
      trace_.insert(trace_.end(), traces[j].begin(), traces[j].end());
    }
  } else {
    SliceOutput out{&report, &decoded_, options_.recordMacroblocks ? &trace_ : nullptr};
    for (const Slice& s : slices_) decodeSlice(params_, s.code, d + s.begin, d + s.end, s.begin, out);
  }
  const std::size_t lastEnd = slices_.empty() ? 0 : slices_.back().end;
  slices_.clear();
  int done = 0;
  int firstMissing = -1;
  for (std::size_t i = 0; i < decoded_.size(); ++i) {
    if (decoded_[i]) {
      ++done;
    } else if (firstMissing < 0) {
      firstMissing = static_cast<int>(i);
    }
  }
  report.macroblocksDecoded += done;
  const int missing = static_cast<int>(decoded_.size()) - done;
  report.macroblocksConcealed += missing;
  if (missing > 0) {
    report.add(IssueKind::kMissingMacroblocks, lastEnd, firstMissing % params_.mbWidth, firstMissing / params_.mbWidth);
  }
  report.produced = true;
}

PictureReport Decoder::decode(std::span<const std::uint8_t> bytes, SliceRunner* pool) {
  PictureReport report;
  trace_.clear();
  const std::uint8_t* d = bytes.data();
  const std::size_t n = bytes.size();
  std::size_t pos = findStartCode(d, n, 0);
  bool reportedOrphanSlice = false;
  while (pos + 3 < n) {
    const int code = d[pos + 3];
    const std::size_t payload = pos + 4;
    const std::size_t next = findStartCode(d, n, payload);
    BitReader br(d + payload, d + next);
    if (code >= kSliceFirst && code <= kSliceLast) {
      if (!pictureOpen_) {
        if (!reportedOrphanSlice) report.add(IssueKind::kMissingPictureHeader, pos);
        reportedOrphanSlice = true;
      } else {
        if (!sawSlice_) {
          sawSlice_ = true;
          beginPicture(report, pos);
        }
        if (pictureValid_) {
          int row = code - 1;
          if (params_.tallPicture && !params_.mpeg1) row += static_cast<int>(br.peek(3)) << 7;
          slices_.push_back(Slice{code, row, payload, next});
        }
      }
    } else {
      switch (code) {
        case kPictureStartCode: {
          if (pictureOpen_) finishPicture(bytes, report, pool);
          PictureHeader p;
          if (parsePictureHeader(br, p)) {
            pic_ = p;
            pictureOpen_ = true;
            sawSlice_ = false;
          } else {
            report.add(IssueKind::kBadHeader, pos);
          }
          break;
        }
        case kSequenceHeaderCode: {
          if (pictureOpen_) finishPicture(bytes, report, pool);
          SequenceHeader s;
          if (parseSequenceHeader(br, s)) {
            seq_ = s;
            haveSequence_ = true;
          } else {
            report.add(IssueKind::kBadHeader, pos);
          }
          break;
        }
        case kExtensionStartCode:
          handleExtension(br, report, pos);
          break;
        case kGroupStartCode:
        case kSequenceEndCode:
          if (pictureOpen_) finishPicture(bytes, report, pool);
          break;
        default:  // user data, sequence error, system start codes: skipped
          break;
      }
    }
    pos = next;
  }
  if (pictureOpen_) finishPicture(bytes, report, pool);
  return report;
}

PictureReport decodeToRgba(Decoder& decoder, std::span<const std::uint8_t> bytes, Rgba8Image& out, CscThresholds th) {
  PictureReport r = decoder.decode(bytes);
  if (r.produced)
    convertToRgba32(decoder.frame(), decoder.width(), decoder.height(), th, out, decoder.kernels().cscRow);
  return r;
}

}  // namespace vbim::ipu
