#include "ipu/picture_decoder.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <thread>

#include "ipu/quant_tables.hpp"
#include "ipu/start_code.hpp"

namespace vbim::ipu {

// Streaming slice-parallel decode: while the caller is still finding the slices of a picture, the
// runner's threads decode the rows already found. The caller closes a group (the slices of one
// macroblock row, rows strictly increasing) as soon as the next row starts and publishes it; every
// participant claims groups in order with an atomic cursor and waits (yielding) for the next one
// until the scan is done; the caller then joins in. Slices after a row that goes backwards (or past
// the reserved capacity, which is never reallocated while others read it) are decoded serially
// after the join, in stream order, so a later slice of a row still overwrites an earlier one as in
// the serial decode. Results are merged in group order: the same bytes as the serial decode.
struct Decoder::Streaming {
  bool active = false;
  bool stopped = false;  // later slices go to `tail`
  int lastRow = -1;
  std::size_t groups = 0;  // groups closed (caller side)
  std::vector<std::size_t> groupStart;
  std::vector<Slice> tail;
  const std::uint8_t* bytes = nullptr;
  const Slice* slices = nullptr;  // slices_.data(), stable while streaming
  SliceRunner* runner = nullptr;
  std::function<void()> participant;
  std::atomic<std::size_t> published{0};
  std::atomic<std::size_t> cursor{0};
  std::atomic<bool> scanDone{false};
};

Decoder::Decoder(DecoderOptions options) : options_(options), streaming_(std::make_unique<Streaming>()) {
  streaming_->participant = [this] { decodeGroups(); };
}
Decoder::~Decoder() = default;
void Decoder::startStreaming(const std::uint8_t* bytes, SliceRunner* pool) {
  Streaming& st = *streaming_;
  st.active = false;
  if (pool == nullptr || pool->threads() == 0 || params_.mpeg1 || params_.tallPicture) return;
  const auto rows = static_cast<std::size_t>(params_.mbRows);
  slices_.clear();
  slices_.reserve(std::max(slices_.capacity(), 2 * rows + 16));
  st.groupStart.assign(rows + 2, 0);
  if (jobResults_.size() < rows + 1) jobResults_.resize(rows + 1);
  st.stopped = false;
  st.lastRow = -1;
  st.groups = 0;
  st.tail.clear();
  st.bytes = bytes;
  st.slices = slices_.data();
  st.runner = pool;
  st.published.store(0, std::memory_order_relaxed);
  st.cursor.store(0, std::memory_order_relaxed);
  st.scanDone.store(false, std::memory_order_relaxed);
  st.active = pool->startEach(st.participant);  // the threads start after everything above is set
}

// Closes the open group (the slices since the last boundary) and publishes it.
void Decoder::closeGroup() {
  Streaming& st = *streaming_;
  if (slices_.size() == st.groupStart[st.groups]) return;
  st.groupStart[st.groups + 1] = slices_.size();
  ++st.groups;
  st.published.store(st.groups, std::memory_order_release);
}

void Decoder::addSlice(const Slice& slice) {
  Streaming& st = *streaming_;
  if (!st.stopped && (slice.row < st.lastRow || slices_.size() == slices_.capacity())) {
    closeGroup();
    st.stopped = true;
  }
  if (st.stopped) {
    st.tail.push_back(slice);
    return;
  }
  if (slice.row != st.lastRow) closeGroup();
  st.lastRow = slice.row;
  slices_.push_back(slice);
}

void Decoder::decodeGroups() {
  Streaming& st = *streaming_;
  for (;;) {
    const std::size_t g = st.cursor.fetch_add(1, std::memory_order_relaxed);
    for (;;) {
      if (g < st.published.load(std::memory_order_acquire)) break;
      if (st.scanDone.load(std::memory_order_acquire)) {
        if (g < st.published.load(std::memory_order_acquire)) break;
        return;
      }
      std::this_thread::yield();
    }
    JobResult& r = jobResults_[g];
    r.report = PictureReport{};
    r.trace.clear();
    SliceOutput out{&r.report, &decoded_, decodedStride_, options_.recordMacroblocks ? &r.trace : nullptr};
    for (std::size_t j = st.groupStart[g]; j < st.groupStart[g + 1]; ++j) {
      const Slice& sl = st.slices[j];
      decodeSlice(params_, sl.code, st.bytes + sl.begin, st.bytes + sl.end, sl.begin, out);
    }
  }
}

void Decoder::finishStreaming(PictureReport& report) {
  Streaming& st = *streaming_;
  if (!st.stopped) closeGroup();
  st.scanDone.store(true, std::memory_order_release);
  decodeGroups();  // the caller takes part
  st.runner->join();
  st.active = false;
  for (std::size_t g = 0; g < st.groups; ++g) {
    const JobResult& r = jobResults_[g];
    report.issueCount += r.report.issueCount;
    report.fieldDctMacroblocks += r.report.fieldDctMacroblocks;
    for (const DecodeIssue& issue : r.report.issues)
      if (report.issues.size() < PictureReport::kMaxIssues) report.issues.push_back(issue);
    trace_.insert(trace_.end(), r.trace.begin(), r.trace.end());
  }
  SliceOutput out{&report, &decoded_, decodedStride_, options_.recordMacroblocks ? &trace_ : nullptr};
  for (const Slice& sl : st.tail) decodeSlice(params_, sl.code, st.bytes + sl.begin, st.bytes + sl.end, sl.begin, out);
}

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
  // One row of flags per cache line multiple, so jobs on neighbouring rows never share a line.
  decodedStride_ = (p.mbWidth + 63) / 64 * 64;
  decoded_.assign(static_cast<std::size_t>(decodedStride_) * p.mbRows, 0);
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
  const bool streamed = streaming_->active;
  const bool parallel =
      !streamed && pool && pool->threads() > 0 && !params_.mpeg1 && !params_.tallPicture && slices_.size() > 1;
  std::size_t lastEnd = slices_.empty() ? 0 : slices_.back().end;
  if (streamed) {
    if (!streaming_->tail.empty()) lastEnd = streaming_->tail.back().end;
    finishStreaming(report);
  } else if (parallel) {
    // MPEG-2 slices never leave their row, so jobs of whole rows write disjoint parts of the frame
    // and of decoded_ (rows padded to a cache line); reports and traces are merged in job order,
    // so the result never depends on which thread ran which job. Slices in row order (stable: a
    // later slice of the same row still overwrites an earlier one, as in the serial decode).
    auto byRow = [](const Slice& a, const Slice& b) { return a.row < b.row; };
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
      for (std::size_t j = jobStarts_[k]; j < jobStarts_[k + 1]; ++j) {
        const Slice& sl = slices_[j];
        decodeSlice(params_, sl.code, d + sl.begin, d + sl.end, sl.begin, out);
      }
    });
    for (std::size_t k = 0; k < jobs; ++k) {
      const JobResult& r = jobResults_[k];
      report.issueCount += r.report.issueCount;
      report.fieldDctMacroblocks += r.report.fieldDctMacroblocks;
      for (const DecodeIssue& issue : r.report.issues)
        if (report.issues.size() < PictureReport::kMaxIssues) report.issues.push_back(issue);
      trace_.insert(trace_.end(), r.trace.begin(), r.trace.end());
    }
  } else {
    SliceOutput out{&report, &decoded_, decodedStride_, options_.recordMacroblocks ? &trace_ : nullptr};
    for (const Slice& sl : slices_) decodeSlice(params_, sl.code, d + sl.begin, d + sl.end, sl.begin, out);
  }
  slices_.clear();
  int done = 0;
  int firstMissing = -1;
  const int mbCount = params_.mbWidth * params_.mbRows;
  for (int y = 0; y < params_.mbRows; ++y) {
    const std::uint8_t* flags = decoded_.data() + static_cast<std::size_t>(y) * decodedStride_;
    const int rowDone = static_cast<int>(std::count(flags, flags + params_.mbWidth, std::uint8_t{1}));
    done += rowDone;
    if (rowDone < params_.mbWidth && firstMissing < 0)
      firstMissing = y * params_.mbWidth + static_cast<int>(std::find(flags, flags + params_.mbWidth, 0) - flags);
  }
  report.macroblocksDecoded += done;
  const int missing = mbCount - done;
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
          if (pictureValid_) startStreaming(d, pool);
        }
        if (pictureValid_) {
          int row = code - 1;
          if (params_.tallPicture && !params_.mpeg1) row += static_cast<int>(br.peek(3)) << 7;
          if (streaming_->active) {
            addSlice(Slice{code, row, payload, next});
          } else {
            slices_.push_back(Slice{code, row, payload, next});
          }
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
