#include "ipu/picture_decoder.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "ipu/idct_libmpeg2.hpp"
#include "ipu/quant_tables.hpp"
#include "ipu/start_code.hpp"

namespace vbim::ipu {

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
  if (pic_.codingType < 1 || pic_.codingType > 3) return fail(IssueKind::kUnsupportedPictureType);
  if (seq_.mpeg2 && !pic_.hasCodingExtension) return fail(IssueKind::kMissingCodingExtension);

  const int mbw = (seq_.width + 15) / 16;
  const int mbh = (!seq_.mpeg2 || seq_.progressiveSequence) ? (seq_.height + 15) / 16 : 2 * ((seq_.height + 31) / 32);
  // Field pictures (§6.1.1.4): the second field of a frame is the one of the other parity after a
  // first field, both B or both not B (I then P is allowed); it fills the same frame.
  const int structure = seq_.mpeg2 ? pic_.pictureStructure : 3;
  const FrameStore& cur = frames_.current();
  const bool second = structure != 3 && pendingField_ != 0 && pendingField_ != structure &&
                      (frameType_ == 3) == (pic_.codingType == 3) && cur.mbWidth == mbw && cur.mbHeight == mbh;
  if (!second) {
    if (pendingField_ != 0) completeFrame();  // a lone field: its frame ends here
    beginFrame(pic_.codingType, mbw, mbh);
  }
  pendingField_ = (structure != 3 && !second) ? structure : 0;
  concealedBefore_ = report.macroblocksConcealed;
  FrameStore& store = frames_.current();
  // Fixed for this picture: a sequence extension among its slices may change seq_ (the size
  // extension bits), but not the store the slices write into.
  frameWidth_ = seq_.width;
  frameHeight_ = seq_.height;

  PictureParams& p = params_;
  p = PictureParams{};
  p.mpeg1 = !seq_.mpeg2;
  p.idct = kernels().idctOf(options_.idct).copy;
  p.idctAdd = kernels().idctOf(options_.idct).add;
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
    p.y = store.y.data() + static_cast<std::ptrdiff_t>(bottom) * store.lumaStride;
    p.cb = store.cb.data() + static_cast<std::ptrdiff_t>(bottom) * store.chromaStride;
    p.cr = store.cr.data() + static_cast<std::ptrdiff_t>(bottom) * store.chromaStride;
    p.yStride = 2 * store.lumaStride;
    p.cStride = 2 * store.chromaStride;
  } else {
    p.mbRows = mbh;
    p.y = store.y.data();
    p.cb = store.cb.data();
    p.cr = store.cr.data();
    p.yStride = store.lumaStride;
    p.cStride = store.chromaStride;
  }
  interPicture_ = pic_.codingType != 1;
  if (interPicture_) {
    InterParams& ip = inter_;
    ip = InterParams{};
    ip.codingType = pic_.codingType;
    ip.pictureStructure = structure;
    ip.framePredFrameDct = !seq_.mpeg2 || pic_.framePredFrameDct;
    ip.topFieldFirst = pic_.topFieldFirst;
    ip.secondField = second;
    for (int s = 0; s < 2; ++s) {
      for (int t = 0; t < 2; ++t) ip.fCode[s][t] = seq_.mpeg2 ? pic_.fCode[s][t] : pic_.headerFCode[s];
      ip.fullPel[s] = !seq_.mpeg2 && pic_.fullPel[s];
    }
    ip.nonIntraMatrix = seq_.nonIntraMatrix;
    // A P picture predicts from the I or P frame decoded last; a B picture from the two last.
    ip.refs.forward = pic_.codingType == 2 ? frames_.backward() : frames_.forward();
    ip.refs.backward = pic_.codingType == 3 ? frames_.backward() : nullptr;
    ip.refs.current = &store;
    ip.mc = kernels().mc;
    prepareScanSlots(ip, p);
  }
  report.macroblocks += p.mbWidth * p.mbRows;
  // One row of flags per cache line multiple, so jobs on neighbouring rows never share a line.
  decodedStride_ = (p.mbWidth + 63) / 64 * 64;
  decoded_.assign(static_cast<std::size_t>(decodedStride_) * p.mbRows, 0);
  pictureValid_ = true;
}

void Decoder::convertLines(int y0, int y1, const RgbaOutput& rgba) const {
  if (y0 < y1) convertLinesToRgba32(frame(), y0, y1, rgba.thresholds, *rgba.image, kernels().cscRow);
}

void Decoder::decodeSlices(std::span<const std::uint8_t> bytes, std::size_t first, std::size_t last,
                           const SliceOutput& out, const RgbaOutput* rgba) {
  for (std::size_t j = first; j < last; ++j) {
    const Slice& sl = slices_[j];
    if (interPicture_) {
      decodeInterSlice(params_, inter_, sl.code, bytes.data() + sl.begin, bytes.data() + sl.end, sl.begin, out);
    } else {
      decodeSlice(params_, sl.code, bytes.data() + sl.begin, bytes.data() + sl.end, sl.begin, out);
    }
  }
  if (rgba && first < last) convertLines(16 * slices_[first].row, 16 * slices_[last - 1].row + 16, *rgba);
}

void Decoder::finishPicture(std::span<const std::uint8_t> bytes, PictureReport& report, SliceRunner* pool,
                            const RgbaOutput* rgba) {
  pictureOpen_ = false;
  if (!pictureValid_) {
    slices_.clear();
    return;
  }
  pictureValid_ = false;
  // MPEG-2 slices never leave their row, so rows can be decoded (and converted) in any order and on
  // any thread; an MPEG-1 slice may run on into the next rows.
  const bool independentRows = !params_.mpeg1 && !params_.tallPicture;
  const bool parallel = pool && pool->threads() > 0 && independentRows && slices_.size() > 1;
  auto byRow = [](const Slice& a, const Slice& b) { return a.row < b.row; };
  if (rgba) {
    Rgba8Image& img = *rgba->image;
    const int w = rgba->wholeMacroblocks ? frame().mbWidth * 16 : frameWidth_;
    const int h = rgba->wholeMacroblocks ? frame().mbHeight * 16 : frameHeight_;
    if (img.width != w || img.height != h) img = Rgba8Image(w, h);
  }
  // On the parallel path each job converts its rows once it has decoded them, so the conversion is
  // split with the decode. Per job, not per row: a row's RGBA (32 KiB at 512 wide) would push the
  // VLC tables out of L1 before every row (measured 12 % slower single-threaded), so the serial
  // path converts the whole picture after it. A field picture fills every other line of the frame,
  // which is converted after it.
  const bool convertInJobs = rgba && parallel && !params_.fieldPicture;
  if (parallel) {
    // Jobs of whole rows write disjoint parts of the frame, of the image and of decoded_ (rows
    // padded to a cache line); reports and traces are merged in job order, so the result never
    // depends on which thread ran which job. Slices in row order (stable: a later slice of the
    // same row still overwrites an earlier one, as in the serial decode).
    if (!std::is_sorted(slices_.begin(), slices_.end(), byRow)) std::stable_sort(slices_.begin(), slices_.end(), byRow);
    // Guided job sizes by bytes (busy rows cost more): each job takes 1 / (2 * participants) of
    // what is left, at least one row, so the first jobs are large (few hand-overs) and the last
    // ones single rows (a thread that finishes early, or a worker that wakes late, still finds
    // small work and both end together).
    const std::size_t participants = pool->threads() + std::size_t{1};
    std::size_t remaining = 0;
    for (const Slice& sl : slices_) remaining += sl.end - sl.begin;
    jobStarts_.clear();
    std::size_t i = 0;
    while (i < slices_.size()) {
      jobStarts_.push_back(i);
      const std::size_t target = std::max<std::size_t>(1, remaining / (2 * participants));
      std::size_t taken = 0;
      while (i < slices_.size() && taken < target) {
        const int row = slices_[i].row;
        while (i < slices_.size() && slices_[i].row == row) {  // whole rows only
          taken += slices_[i].end - slices_[i].begin;
          ++i;
        }
      }
      remaining -= taken;
    }
    jobStarts_.push_back(slices_.size());
    const std::size_t jobs = jobStarts_.size() - 1;
    if (jobResults_.size() < jobs) jobResults_.resize(jobs);
    for (std::size_t k = 0; k < jobs; ++k) {
      jobResults_[k].report = PictureReport{};
      jobResults_[k].trace.clear();
    }
    pool->run(jobs, [&](std::size_t k) {
      JobResult& r = jobResults_[k];
      SliceOutput out{&r.report, &decoded_, decodedStride_, options_.recordMacroblocks ? &r.trace : nullptr};
      decodeSlices(bytes, jobStarts_[k], jobStarts_[k + 1], out, convertInJobs ? rgba : nullptr);
    });
    for (std::size_t k = 0; k < jobs; ++k) {
      const JobResult& r = jobResults_[k];
      report.issueCount += r.report.issueCount;
      report.fieldDctMacroblocks += r.report.fieldDctMacroblocks;
      report.macroblocksConcealed += r.report.macroblocksConcealed;
      for (const DecodeIssue& issue : r.report.issues)
        if (report.issues.size() < PictureReport::kMaxIssues) report.issues.push_back(issue);
      trace_.insert(trace_.end(), r.trace.begin(), r.trace.end());
    }
  } else {
    SliceOutput out{&report, &decoded_, decodedStride_, options_.recordMacroblocks ? &trace_ : nullptr};
    decodeSlices(bytes, 0, slices_.size(), out, nullptr);
  }
  // Macroblocks no slice decoded: counted, and copied from the picture decoded before (or the
  // reference of a P or B picture) when this frame's store held another picture.
  int done = 0;
  int firstMissing = -1;
  const int mbCount = params_.mbWidth * params_.mbRows;
  std::vector<int> missingRows;
  for (int y = 0; y < params_.mbRows; ++y) {
    const std::uint8_t* flags = decoded_.data() + static_cast<std::size_t>(y) * decodedStride_;
    const int rowDone = static_cast<int>(std::count(flags, flags + params_.mbWidth, std::uint8_t{1}));
    done += rowDone;
    if (rowDone < params_.mbWidth) {
      missingRows.push_back(y);
      if (firstMissing < 0)
        firstMissing = y * params_.mbWidth + static_cast<int>(std::find(flags, flags + params_.mbWidth, 0) - flags);
    }
  }
  if (!missingRows.empty()) concealMissing(missingRows, convertInJobs ? rgba : nullptr);
  if (rgba) {
    // The lines no job converted: the rows between the jobs' rows (no slice reached them), or all.
    int line = 0;
    if (convertInJobs) {
      for (std::size_t k = 0; k + 1 < jobStarts_.size(); ++k) {
        convertLines(line, 16 * slices_[jobStarts_[k]].row, *rgba);
        line = std::max(line, 16 * slices_[jobStarts_[k + 1] - 1].row + 16);
      }
    }
    convertLines(line, rgba->image->height, *rgba);
  }
  const std::size_t lastEnd = slices_.empty() ? 0 : slices_.back().end;
  slices_.clear();
  // Macroblocks predicted from a missing reference count as concealed, not decoded.
  const int fromMissingReference = report.macroblocksConcealed - concealedBefore_;
  report.macroblocksDecoded += done - fromMissingReference;
  const int missing = mbCount - done;
  if (fromMissingReference > 0) report.add(IssueKind::kMissingReference, lastEnd);
  report.macroblocksConcealed += missing;
  if (missing > 0) {
    report.add(IssueKind::kMissingMacroblocks, lastEnd, firstMissing % params_.mbWidth, firstMissing / params_.mbWidth);
  }
  if (pendingField_ == 0) completeFrame();
  report.produced = true;
}

void Decoder::beginFrame(int codingType, int mbw, int mbh) {
  const FrameStore& before = frames_.current();
  const bool hadPicture = !before.empty();
  FrameStore& s = frames_.begin(codingType, mbw, mbh, clearFrame_);
  // A store that held another picture: what no slice reaches shows the picture before (an I
  // picture) or the reference (P, B), as one persistent store would; a new store stays mid-grey.
  concealFrom_ = nullptr;
  if (!clearFrame_ && hadPicture) {
    const FrameStore* ref = codingType == 1 ? nullptr : frames_.backward();
    concealFrom_ = ref ? ref : frames_.previous();
    if (concealFrom_ == &s) concealFrom_ = nullptr;
  }
  clearFrame_ = false;
  frameType_ = codingType;
}

void Decoder::completeFrame() {
  frames_.complete(frameType_, frameWidth_, frameHeight_);
  pendingField_ = 0;
}

void Decoder::copyStateFrom(const Decoder& other) {
  if (&other == this) return;
  if (other.fieldPending()) throw std::logic_error("Decoder::copyStateFrom: a field is pending");
  *this = other;
  concealFrom_ = nullptr;  // set again when the next frame begins (beginFrame); never read before
}

bool Decoder::flushDisplay() {
  frames_.clearDisplay();
  if (pendingField_ != 0) {
    completeFrame();
    if (frames_.display()) return true;  // a lone last field of a B frame
  }
  return frames_.flush();
}

void Decoder::concealMissing(const std::vector<int>& rows, const RgbaOutput* rgba) {
  if (!concealFrom_) return;
  FrameStore& cur = frames_.current();
  // Offsets of this picture's first line in the stores (a bottom field starts one line down).
  const std::ptrdiff_t yOff = params_.y - cur.y.data();
  const std::ptrdiff_t cOff = params_.cb - cur.cb.data();
  for (const int y : rows) {
    const std::uint8_t* flags = decoded_.data() + static_cast<std::size_t>(y) * decodedStride_;
    for (int x = 0; x < params_.mbWidth; ++x) {
      if (flags[x]) continue;
      const std::ptrdiff_t ly = yOff + std::ptrdiff_t{16} * y * params_.yStride + std::ptrdiff_t{16} * x;
      const std::ptrdiff_t lc = cOff + std::ptrdiff_t{8} * y * params_.cStride + std::ptrdiff_t{8} * x;
      for (int r = 0; r < 16; ++r) {
        const std::ptrdiff_t i = ly + std::ptrdiff_t{r} * params_.yStride;
        std::memcpy(cur.y.data() + i, concealFrom_->y.data() + i, 16);
      }
      for (int r = 0; r < 8; ++r) {
        const std::ptrdiff_t i = lc + std::ptrdiff_t{r} * params_.cStride;
        std::memcpy(cur.cb.data() + i, concealFrom_->cb.data() + i, 8);
        std::memcpy(cur.cr.data() + i, concealFrom_->cr.data() + i, 8);
      }
    }
    if (rgba) convertLines(16 * y, 16 * y + 16, *rgba);
  }
}

PictureReport Decoder::decode(std::span<const std::uint8_t> bytes, SliceRunner* pool) {
  return decode(bytes, pool, RgbaOutput{});
}

PictureReport Decoder::decode(std::span<const std::uint8_t> bytes, SliceRunner* pool, const RgbaOutput& rgbaOutput) {
  const RgbaOutput* rgba = rgbaOutput.image ? &rgbaOutput : nullptr;
  PictureReport report;
  trace_.clear();
  frames_.clearDisplay();
  if (options_.freshStorePerDecode) clearFrame_ = true;
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
          if (pictureOpen_) finishPicture(bytes, report, pool, rgba);
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
          if (pictureOpen_) finishPicture(bytes, report, pool, rgba);
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
          if (pictureOpen_) finishPicture(bytes, report, pool, rgba);
          break;
        default:  // user data, sequence error, system start codes: skipped
          break;
      }
    }
    pos = next;
  }
  if (pictureOpen_) finishPicture(bytes, report, pool, rgba);
  return report;
}

PictureReport decodeToRgba(Decoder& decoder, std::span<const std::uint8_t> bytes, Rgba8Image& out, CscThresholds th,
                           SliceRunner* runner) {
  return decoder.decode(bytes, runner, RgbaOutput{&out, th});
}

}  // namespace vbim::ipu
