#include "ipu/ipu_unit.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>

#include "ipu/block_walker.hpp"
#include "ipu/start_code.hpp"

namespace vbim::ipu {
namespace {

// The timing needs the macroblock trace. On an IDEC stream a macroblock the IPU conceals is
// mid-grey, never the picture decoded before (the shared stream decodes the lightmap's and the
// sky's pictures in turn), and the same whatever came before, as in replay, which decodes each
// picture alone. A BDEC stream keeps its frames: P and B pictures predict from them.
DecoderOptions streamOptions(DecoderOptions o, const IpuParams& p, DecodePath path) {
  o.recordMacroblocks = true;
  o.idct = idctKindOf(p);  // the platform's IDCT
  o.freshStorePerDecode = path == DecodePath::kIdec;
  return o;
}

// A P or B picture among `bytes` (picture_coding_type, ISO/IEC 13818-2 §6.2.3).
bool hasPredictedPicture(std::span<const std::uint8_t> bytes) {
  const std::uint8_t* d = bytes.data();
  const std::size_t n = bytes.size();
  for (std::size_t pos = findStartCode(d, n, 0); pos + 5 < n; pos = findStartCode(d, n, pos + 4)) {
    if (d[pos + 3] != 0x00) continue;
    const int type = (d[pos + 5] >> 3) & 7;  // after 10 bits of temporal_reference
    if (type == 2 || type == 3) return true;
  }
  return false;
}

// What the IDEC command's timing and log take from the decoder after its picture (not the report).
IdecDecode idecDecodeOf(const Decoder& dec) {
  IdecDecode d;
  d.trace = dec.macroblockTrace();
  d.sequence = dec.sequence();
  d.picture = dec.picture();
  d.mbWidth = dec.frame().mbWidth;
  d.mbHeight = dec.frame().mbHeight;
  d.width = dec.width();
  d.height = dec.height();
  return d;
}

// A shared decode's image: `whole` (whole macroblocks) when it has the picture's size, else a new
// image of its top-left width x height, as submit() crops the unshared path's (never written back
// into `whole`: it may be the twin's).
std::shared_ptr<Rgba8Image> croppedTo(std::shared_ptr<Rgba8Image> whole, int width, int height) {
  if (whole->width == width && whole->height == height) return whole;
  auto cropped = std::make_shared<Rgba8Image>(width, height);
  for (int y = 0; y < height; ++y) std::memcpy(cropped->row(y), whole->row(y), static_cast<std::size_t>(width) * 4);
  return cropped;
}

// libmpeg's CSC command converts at most 0x3FF macroblocks (MBC is 11 bits; _MPEG_CSCImage
// splits larger pictures).
constexpr std::int64_t kCscMaxMacroblocks = 0x3FF;
constexpr std::uint32_t kCscInQwordsPerMacroblock = 24;  // 384 bytes of 8-bit YCbCr 4:2:0

}  // namespace

IpuUnit::IpuUnit(Scheduler& s, const IpuParams& p, Tracer* tracer, DecoderOptions options, EeFlowCosts ee)
    : s_(s),
      p_(p),
      tracer_(tracer && tracer->enabled() ? tracer : nullptr),
      options_(options),
      ee_(ee),
      timeline_(p),
      commands_(s, 1, "ipu.commands") {
  if (tracer_) track_ = tracer_->track("ipu");
  openStream(DecodePath::kIdec);
  s_.spawn("ipu", run(*this));
}

StreamId IpuUnit::openStream(DecodePath path) {
  if (path == DecodePath::kBdec && tracer_ && !eeTrackOpen_) {
    eeTrack_ = tracer_->track("ee");
    eeTrackOpen_ = true;
  }
  streams_.push_back(Stream{path, std::make_unique<Decoder>(streamOptions(options_, p_, path))});
  return streams_.size() - 1;
}

Task<TimedPicture> IpuUnit::decode(StreamId stream, std::span<const std::uint8_t> bytes, Rgba8Image& out,
                                   CscThresholds th) {
  const Stream& st = streams_.at(stream);
  if (st.path == DecodePath::kIdec ? share_ == nullptr : st.flowShare == nullptr) {
    co_return co_await decodeUnshared(stream, bytes, out, th);
  }
  // Through the shared decodes, so they know what this decoder was given; the image may be the
  // twin's, so its bytes are copied.
  auto image = std::make_shared<Rgba8Image>(std::move(out));
  TimedPicture result = co_await decode(stream, bytes, image, th);
  out = *image;
  co_return result;
}

Task<TimedPicture> IpuUnit::decodeUnshared(StreamId stream, std::span<const std::uint8_t> bytes, Rgba8Image& out,
                                           CscThresholds th) {
  Stream& st = streams_.at(stream);
  Decoder& dec = *st.decoder;
  TimedPicture result;
  result.started = s_.now();
  const auto shared = std::make_shared<Command>(s_);
  Command& cmd = *shared;
  cmd.arrival = s_.now();
  if (st.path == DecodePath::kIdec) {
    if (hasPredictedPicture(bytes)) {
      // IDEC decodes intra macroblocks only: nothing is decoded, the stream's frames stay as they were.
      result.report.undecodable = true;
      result.report.add(IssueKind::kPredictedPictureOnIdec, 0);
      result.finished = s_.now();
      co_return result;
    }
    // Decode into out's buffer: when it already has the picture's size (a recycled image), nothing
    // is allocated or cleared; every byte is written either way.
    cmd.staged = std::move(out);
    out = Rgba8Image{};
    result.report = dec.decode(bytes, runner_, RgbaOutput{&cmd.staged, th, true});
    if (!result.report.produced) {
      result.finished = s_.now();
      co_return result;
    }
    const IdecDecode d = idecDecodeOf(dec);
    co_return co_await submitIdec(shared, std::move(result), bytes, d, th, out);
  }
  // The BDEC flow.
  result.report = dec.decode(bytes, runner_);
  if (!result.report.produced) {
    result.finished = s_.now();
    co_return result;
  }
  const PictureHeader& pic = dec.picture();
  stageFlow(cmd, bytes, dec.sequence(), pic, dec.macroblockTrace());
  if (recordCommands_) {
    result.ctrl = ipuCtrl(dec.sequence(), pic);
    planFlowWords(cmd, bytes, dec);
  }
  const FrameStore* shown = dec.displayFrame();
  int width = 0;
  int height = 0;
  if (shown != nullptr) {
    width = dec.displayWidth();
    height = dec.displayHeight();
    result.outputQwords = stageDisplayCsc(cmd, dec, *shown, th, out);
  }
  co_return co_await submit(shared, std::move(result), out, width, height);
}

// IDEC path: the command's timing (and log) from its picture's decode, then the command itself.
Task<TimedPicture> IpuUnit::submitIdec(std::shared_ptr<Command> shared, TimedPicture result,
                                       std::span<const std::uint8_t> bytes, const IdecDecode& d, CscThresholds th,
                                       Rgba8Image& out) {
  Command& cmd = *shared;
  const std::size_t mbs = static_cast<std::size_t>(d.mbWidth) * d.mbHeight;
  CommandTiming& tm = cmd.timing;
  tm.arrival = s_.now();
  tm.inQwords = static_cast<std::uint32_t>((bytes.size() + 15) / 16);
  // Per macroblock (raster order): the qwords holding its last bit, and its bit count. Concealed
  // macroblocks cost the base only and need no further input.
  std::vector<std::uint32_t> endByte(mbs, 0);
  tm.bits.assign(mbs, 0);
  for (const MacroblockBits& m : d.trace) {
    if (m.address < mbs) {
      endByte[m.address] = m.endByte;
      tm.bits[m.address] = m.bits;
    }
  }
  tm.restart = idecRestarts(d.trace, mbs);
  tm.qwordsPerRow = qwordsPerRow();
  result.idecCommands = 1 + std::count(tm.restart.begin(), tm.restart.end(), std::uint8_t{1});
  result.commands.idec = result.idecCommands;
  result.outputQwords = static_cast<std::int64_t>(mbs) * kRowsPerMacroblock * qwordsPerRow();
  if (recordCommands_) {
    result.ctrl = ipuCtrl(d.sequence, d.picture);
    planIdecWords(cmd, bytes, d, th);
  }
  result.displayed = true;
  tm.needQwords.resize(mbs);
  std::uint32_t need = 0;
  for (std::size_t i = 0; i < mbs; ++i) {
    need = std::max(need, std::min(tm.inQwords, (endByte[i] + 15) / 16));
    tm.needQwords[i] = need;
  }
  co_return co_await submit(shared, std::move(result), out, d.width, d.height);
}

void IpuUnit::shareDecodes(SharedDecodes& shared, int side) {
  share_ = &shared;
  shareSide_ = side;
}

Task<TimedPicture> IpuUnit::decode(StreamId stream, std::span<const std::uint8_t> bytes,
                                   std::shared_ptr<Rgba8Image>& out, CscThresholds th) {
  Stream& st = streams_.at(stream);
  if (st.path == DecodePath::kBdec && st.flowShare != nullptr)
    co_return co_await decodeFlowShared(stream, bytes, out, th);
  if (share_ == nullptr || st.path != DecodePath::kIdec || hasPredictedPicture(bytes)) {
    co_return co_await decodeUnshared(stream, bytes, *out, th);
  }
  TimedPicture result;
  result.started = s_.now();
  const auto shared = std::make_shared<Command>(s_);
  Command& cmd = *shared;
  cmd.arrival = s_.now();
  cmd.inPlace = true;  // the image is `out` (or the twin's), not cmd.staged
  std::optional<SharedDecodes::Taken> taken = share_->take(shareSide_, bytes, th);
  if (!taken) {
    share_->prepare(shareSide_, st.decoder, streamOptions(options_, p_, st.path), bytes);
    Decoder& dec = *st.decoder;
    const bool pendingBefore = dec.fieldPending();
    // Into out's buffer, as the unshared path does (every byte written), and cropped to the
    // picture's size as submit() would (a new image: the old one may be the twin's).
    PictureReport report = dec.decode(bytes, runner_, RgbaOutput{out.get(), th, true});
    taken.emplace(SharedDecodes::Taken{idecDecodeOf(dec), out});
    taken->decode.report = std::move(report);
    const IdecDecode& d = taken->decode;
    // Nothing to show: the image stays the caller's.
    taken->image = d.report.produced ? croppedTo(out, d.width, d.height) : nullptr;
    share_->publish(shareSide_, bytes, th, pendingBefore, dec, taken->decode, taken->image);
  }
  result.report = taken->decode.report;
  if (!result.report.produced) {
    *out = Rgba8Image{};  // as the unshared path leaves it
    result.finished = s_.now();
    co_return result;
  }
  out = taken->image;  // the caller reads it only once this returns
  co_return co_await submitIdec(shared, std::move(result), bytes, taken->decode, th, *out);
}

// The BDEC flow through shared decodes: the twin's decode of the same picture after the same
// pictures (its report, macroblock trace and displayed image) when it made it first, else this
// IPU's own, offered to the twin. The flow's timing is planned from the trace either way.
Task<TimedPicture> IpuUnit::decodeFlowShared(StreamId stream, std::span<const std::uint8_t> bytes,
                                             std::shared_ptr<Rgba8Image>& out, CscThresholds th) {
  Stream& st = streams_.at(stream);
  SharedDecodes& share = *st.flowShare;
  TimedPicture result;
  result.started = s_.now();
  const auto shared = std::make_shared<Command>(s_);
  Command& cmd = *shared;
  cmd.arrival = s_.now();
  std::optional<SharedDecodes::Taken> taken = share.take(st.flowSide, bytes, th);
  if (!taken) {
    share.prepare(st.flowSide, st.decoder, streamOptions(options_, p_, st.path), bytes);
    Decoder& dec = *st.decoder;
    const bool pendingBefore = dec.fieldPending();
    PictureReport report = dec.decode(bytes, runner_);
    taken.emplace(SharedDecodes::Taken{idecDecodeOf(dec), nullptr});
    IdecDecode& d = taken->decode;
    d.report = std::move(report);
    const FrameStore* shown = d.report.produced ? dec.displayFrame() : nullptr;
    d.shown = shown != nullptr;
    if (shown != nullptr) {
      // Into out's buffer, whole macroblocks as the unshared path converts them, then cropped.
      d.mbWidth = shown->mbWidth;
      d.mbHeight = shown->mbHeight;
      d.width = dec.displayWidth();
      d.height = dec.displayHeight();
      convertToRgba32(*shown, shown->mbWidth * 16, shown->mbHeight * 16, th, *out, dec.kernels().cscRow);
      taken->image = croppedTo(out, d.width, d.height);
    }
    share.publish(st.flowSide, bytes, th, pendingBefore, dec, taken->decode, taken->image);
  }
  const IdecDecode& d = taken->decode;
  result.report = d.report;
  if (!result.report.produced) {
    result.finished = s_.now();
    co_return result;
  }
  stageFlow(cmd, bytes, d.sequence, d.picture, d.trace);
  int width = 0;
  int height = 0;
  if (d.shown) {
    width = d.width;
    height = d.height;
    result.outputQwords = stageCscTiming(cmd, d.mbWidth, d.mbHeight);
    cmd.inPlace = true;  // the image is taken->image, `out` from here on
    out = taken->image;  // the caller reads it only once this returns
  }
  co_return co_await submit(shared, std::move(result), *out, width, height);
}

void IpuUnit::shareFlowDecodes(StreamId stream, SharedDecodes& shared, int side) {
  Stream& st = streams_.at(stream);
  if (st.path != DecodePath::kBdec) throw std::logic_error("shareFlowDecodes: not a BDEC stream");
  st.flowShare = &shared;
  st.flowSide = side;
  shared.attach(side, &st.decoder);
  if (recordCommands_) {
    shared.leave(side, st.decoder, streamOptions(options_, p_, st.path));
    st.flowShare = nullptr;
  }
}

void IpuUnit::recordCommands() {
  recordCommands_ = true;
  for (Stream& st : streams_) {
    if (st.flowShare == nullptr) continue;
    st.flowShare->leave(st.flowSide, st.decoder, streamOptions(options_, p_, st.path));
    st.flowShare = nullptr;
  }
}

Task<TimedPicture> IpuUnit::flush(StreamId stream, Rgba8Image& out, CscThresholds th) {
  Stream& st = streams_.at(stream);
  // The end changes the decoder outside the shared log: up to date first, then its own.
  if (st.flowShare != nullptr) {
    st.flowShare->leave(st.flowSide, st.decoder, streamOptions(options_, p_, st.path));
    st.flowShare = nullptr;
  }
  TimedPicture result;
  result.started = s_.now();
  result.finished = s_.now();
  if (st.path != DecodePath::kBdec || !st.decoder->flushDisplay()) co_return result;
  const Decoder& dec = *st.decoder;
  const FrameStore& shown = *dec.displayFrame();
  const auto shared = std::make_shared<Command>(s_);
  Command& cmd = *shared;
  cmd.arrival = s_.now();
  cmd.flow = true;  // no picture: only the CSC
  cmd.flowTiming.recordCommands = recordCommands_;
  result.report.produced = true;
  result.outputQwords = stageDisplayCsc(cmd, dec, shown, th, out);
  co_return co_await submit(shared, std::move(result), out, dec.displayWidth(), dec.displayHeight());
}

std::int64_t IpuUnit::stageDisplayCsc(Command& cmd, const Decoder& dec, const FrameStore& shown, CscThresholds th,
                                      Rgba8Image& out) const {
  cmd.staged = std::move(out);
  out = Rgba8Image{};
  convertToRgba32(shown, shown.mbWidth * 16, shown.mbHeight * 16, th, cmd.staged, dec.kernels().cscRow);
  return stageCscTiming(cmd, shown.mbWidth, shown.mbHeight);
}

void IpuUnit::stageFlow(Command& cmd, std::span<const std::uint8_t> bytes, const SequenceHeader& seq,
                        const PictureHeader& pic, const std::vector<MacroblockBits>& trace) {
  // Field DCT is possible only in an MPEG-2 frame picture without frame_pred_frame_dct (§6.3.10).
  const bool fieldDct = seq.mpeg2 && pic.pictureStructure == 3 && !pic.framePredFrameDct;
  cmd.flow = true;
  cmd.flowWork = buildFlow(bytes, trace, pic.codingType == 1, fieldDct);
}

std::int64_t IpuUnit::stageCscTiming(Command& cmd, int mbWidth, int mbHeight) const {
  cmd.hasCsc = true;
  const std::size_t mbs = static_cast<std::size_t>(mbWidth) * mbHeight;
  cmd.timing.csc = true;
  cmd.timing.qwordsPerRow = qwordsPerRow();
  cmd.timing.inQwords = static_cast<std::uint32_t>(mbs) * kCscInQwordsPerMacroblock;
  cmd.timing.bits.assign(mbs, 0);
  cmd.timing.restart.assign(mbs, 0);
  cmd.timing.needQwords.resize(mbs);
  for (std::size_t i = 0; i < mbs; ++i)
    cmd.timing.needQwords[i] = static_cast<std::uint32_t>(i + 1) * kCscInQwordsPerMacroblock;
  return static_cast<std::int64_t>(mbs) * kRowsPerMacroblock * qwordsPerRow();
}

// IDEC path: BCLR with the bit position of the first slice start code in its qword (toIPU DMA
// starts on a 16-byte boundary; the picture's bytes are taken to start on one), SETTH when the
// thresholds are not 0, then one IDEC per slice the timing restarts IDEC at. FB skips the start
// code, the slice header and the first address increment (a longer skip than FB's 6 bits is done by
// FDECs first); DTD = !frame_pred_frame_dct (P-IPU ipuIDEC); SGN = 0; OFM and DTE the output's.
void IpuUnit::planIdecWords(Command& cmd, std::span<const std::uint8_t> bytes, const IdecDecode& d,
                            CscThresholds th) const {
  const PictureHeader& pic = d.picture;
  const std::vector<SliceStart> slices = sliceStarts(bytes, d.sequence, pic, d.mbWidth, d.mbHeight);
  const bool dtd = d.sequence.mpeg2 && pic.pictureStructure == 3 && !pic.framePredFrameDct;
  cmd.planned.clear();
  cmd.planned.push_back({bclrWord(slices.empty() ? 0 : static_cast<int>(8 * (slices.front().offset & 15))), -1});
  if (th.th0 != 0 || th.th1 != 0) cmd.planned.push_back({setthWord(th.th0, th.th1), -1});
  const auto sliceAt = [&](std::uint32_t address) -> const SliceStart* {
    for (const SliceStart& s : slices) {
      if (s.address == address) return &s;
    }
    return nullptr;
  };
  const auto idec = [&](const SliceStart* s, std::int64_t mb) {
    int fb = s != nullptr ? s->fb : 0;
    while (fb > 63) {
      const int k = std::min(fb - 63, 63);
      cmd.planned.push_back({fdecWord(k), mb});
      fb -= k;
    }
    cmd.planned.push_back({idecWord(fb, s != nullptr ? s->qsc : 0, dtd, false, rgb16_ && dither_, rgb16_), mb});
  };
  // The first IDEC covers the picture up to the first restart, with the first slice decoded.
  const std::vector<MacroblockBits>& trace = d.trace;
  const auto first = std::find_if(trace.begin(), trace.end(), [](const MacroblockBits& m) { return m.sliceStart; });
  idec(first != trace.end() ? sliceAt(first->address) : nullptr, 0);
  const std::vector<std::uint8_t>& restart = cmd.timing.restart;
  for (std::size_t i = 0; i < restart.size(); ++i) {
    if (restart[i] != 0) idec(sliceAt(static_cast<std::uint32_t>(i)), static_cast<std::int64_t>(i));
  }
}

// BDEC path: each macroblock's words as libmpeg issues them (ee/mpeg/src/libmpeg.c _mpeg12_slice,
// _mpeg12_dec_mb; libmpeg_core.c _MPEG_BDEC), from a walk of the picture (ipu/block_walker.hpp):
// its VDEC and FDEC reads with FB = each FDEC's width, and BDEC with FB = 0 (the EE has skipped
// the header with its FDECs), QSC = the quantiser_scale_code in force (the macroblock's own with
// the quant flag), DT = its dct_type, DCR = 1 after a slice start, a skipped or a non-intra
// macroblock (libmpeg's m_fDCRst, §7.2.1), MBI = intra. A picture the walk cannot follow (a
// damaged one the decoder concealed) keeps the counts' words: FDEC and VDEC with FB = 0, BDEC with
// its slice's QSC and DT = 0.
void IpuUnit::planFlowWords(Command& cmd, std::span<const std::uint8_t> bytes, const Decoder& dec) const {
  FlowPicture& f = cmd.flowWork;
  cmd.flowTiming.recordCommands = true;
  std::vector<WalkedMacroblock> walked;
  bool followed = true;
  for (int index = 0;; ++index) {
    WalkedPicture pic;
    std::string error;
    if (!walkPicture(bytes, pic, error, index, &dec.sequence())) {
      followed = index > 0 && error.rfind("no slice of picture", 0) == 0;
      break;
    }
    for (WalkedMacroblock& mb : pic.macroblocks) walked.push_back(std::move(mb));
  }
  std::size_t next = 0;
  for (const FlowMacroblock& m : f.macroblocks) {
    if (m.skipped) continue;
    followed = followed && next < walked.size() && walked[next].address == static_cast<int>(m.address);
    ++next;
  }
  if (followed && next == walked.size()) {
    f.macroblockWords.clear();
    std::size_t k = 0;
    bool reset = true;  // libmpeg's m_fDCRst
    for (FlowMacroblock& m : f.macroblocks) {
      if (m.skipped) {
        reset = true;
        continue;
      }
      const WalkedMacroblock& w = walked[k++];
      if (w.sliceStart) reset = true;
      m.wordsBegin = static_cast<std::uint32_t>(f.macroblockWords.size());
      m.wordCount = static_cast<std::uint32_t>(w.eeWords.size());
      f.macroblockWords.insert(f.macroblockWords.end(), w.eeWords.begin(), w.eeWords.end());
      if (m.bdec) m.bdecWord = bdecWord(0, w.quantiserScaleCode, w.fieldDct, reset, w.intra);
      reset = !w.intra;
    }
    return;
  }
  const FrameStore& fs = dec.frame();
  const std::vector<SliceStart> slices = sliceStarts(bytes, dec.sequence(), dec.picture(), fs.mbWidth, fs.mbHeight);
  int qsc = 0;
  bool lastIntra = false;
  for (FlowMacroblock& m : f.macroblocks) {
    if (m.sliceStart) {
      for (const SliceStart& s : slices) {
        if (s.address == m.address) qsc = s.qsc;
      }
    }
    if (m.bdec) m.bdecWord = bdecWord(0, qsc, false, m.sliceStart || !lastIntra, m.intra);
    lastIntra = !m.skipped && m.intra;
  }
}

// The planned words with their times, now that the command's schedule is final.
void IpuUnit::logCommands(const Command& cmd, TimedPicture& result) const {
  std::vector<IssuedCommand>& out = result.issued;
  out.clear();
  const CommandTiming& tm = cmd.timing;
  if (!cmd.flow) {
    const std::size_t mbs = tm.mbBegin.size();
    if (mbs == 0) return;
    for (std::size_t k = 0; k < cmd.planned.size(); ++k) {
      const Command::PlannedWord& w = cmd.planned[k];
      const auto mb = static_cast<std::size_t>(std::max<std::int64_t>(w.mb, 0));
      // Issued idec_start_cycles before its first macroblock begins.
      const Tick begin = tm.mbBegin[mb] - p_.idec_start_cycles;
      if (opcodeOf(w.word) != IpuOpcode::kIdec) {
        out.push_back({w.word, begin, begin});
        continue;
      }
      std::size_t next = mbs;  // the next IDEC's first macroblock
      for (std::size_t j = k + 1; j < cmd.planned.size(); ++j) {
        if (opcodeOf(cmd.planned[j].word) == IpuOpcode::kIdec) {
          next = static_cast<std::size_t>(cmd.planned[j].mb);
          break;
        }
      }
      out.push_back({w.word, begin, tm.mbEnd[std::max(next, mb + 1) - 1]});
    }
    return;
  }
  out = cmd.flowTiming.commands;
  if (!cmd.hasCsc || tm.mbEnd.empty()) return;
  // _MPEG_CSCImage: BCLR (suspend), CSC of at most kCscMaxMacroblocks each, BCLR (resume).
  const Tick decodeEnd = cmd.flowTiming.decodeEnd;
  out.push_back({bclrWord(0), decodeEnd, decodeEnd});
  const std::size_t mbs = tm.mbEnd.size();
  for (std::size_t a = 0; a < mbs; a += static_cast<std::size_t>(kCscMaxMacroblocks)) {
    const std::size_t b = std::min(mbs, a + static_cast<std::size_t>(kCscMaxMacroblocks));
    const Tick begin = a == 0 ? tm.arrival : tm.mbBegin[a];
    out.push_back({cscWord(static_cast<int>(b - a), rgb16_ && dither_, rgb16_), begin, tm.mbEnd[b - 1]});
  }
  out.push_back({bclrWord(0), tm.mbEnd.back(), tm.mbEnd.back()});
}

// Plans the command, hands it to the "ipu" process and waits for its last event; then `out` gets
// the staged output cropped to width x height (if the command has output).
Task<TimedPicture> IpuUnit::submit(std::shared_ptr<Command> shared, TimedPicture result, Rgba8Image& out, int width,
                                   int height) {
  Command& cmd = *shared;
  retire();
  plan(cmd);
  inFlight_.push_back(shared);
  if (recordQwords_ && !cmd.flow) recorded_.push_back(shared);
  co_await commands_.push(shared);
  while (!cmd.done) co_await cmd.finishedEvent.wait();
  if (cmd.inPlace) {
    result.displayed = true;
  } else if (!cmd.flow || cmd.hasCsc) {
    // The picture is in memory: the caller sees it whole (no one reads it while the DMA runs).
    if (cmd.staged.width == width && cmd.staged.height == height) {
      out = std::move(cmd.staged);  // whole macroblocks are the picture: hand the buffer over
    } else {
      if (out.width != width || out.height != height) out = Rgba8Image(width, height);
      for (int y = 0; y < out.height; ++y)
        std::memcpy(out.row(y), cmd.staged.row(y), static_cast<std::size_t>(out.width) * 4);
    }
    result.displayed = true;
  }
  result.finished = s_.now();
  result.outputStalls = cmd.timing.stalls;
  if (cmd.flow) {
    const FlowTiming& ft = cmd.flowTiming;
    result.commands = ft.counts;
    result.decodeEnd = ft.decodeEnd;
    result.eeBusy = ft.eeBusy;
    result.eeWait = ft.eeWait;
    result.outputStalls += ft.outputStalls;
    if (cmd.hasCsc) {
      const auto mbs = static_cast<std::int64_t>(cmd.timing.needQwords.size());
      result.commands.csc += (mbs + kCscMaxMacroblocks - 1) / kCscMaxMacroblocks;
      result.commands.bclr += 2;  // _ipu_suspend's BCLR before the CSC, _ipu_resume's after it
      result.eeBusy += fromEeCycles(ee_.csc_setup_cycles);
    }
  }
  if (recordCommands_) logCommands(cmd, result);
  co_return result;
}

void IpuUnit::plan(Command& c) {
  c.before = timeline_.state();
  if (!c.flow) {
    timeline_.plan(c.timing, inStalls_, outStalls_, recordQwords_);
    return;
  }
  // The EE starts the picture when the IPU is done with the previous command.
  const IpuTimeline::State& st = timeline_.state();
  FlowTiming& ft = c.flowTiming;
  ft.arrival = std::max({c.arrival, st.coreFree, st.toIpuFree, st.fromIpuFree});
  planFlow(c.flowWork, p_, ee_, inStalls_, outStalls_, ft);
  timeline_.advanceTo(std::max({ft.decodeEnd, ft.inFree, ft.ipuFree, ft.fromFree}));
  if (c.hasCsc) {
    c.timing.arrival = ft.decodeEnd + fromEeCycles(ee_.csc_setup_cycles);
    timeline_.plan(c.timing, inStalls_, outStalls_, false);
  }
}

Tick IpuUnit::quietAfter(const Command& c) {
  if (!c.flow || c.hasCsc) return c.timing.quietAfter;
  const FlowTiming& ft = c.flowTiming;
  return std::max({ft.decodeEnd, ft.inFree, ft.ipuFree, ft.fromFree});
}

// The spans of an IDEC command, or of a CSC command of the BDEC flow (no decode spans), as the
// qword-stepping model recorded them, at the tick they ended. Each time is read again on waking: a
// DMA stall may have moved it later.
Task<void> IpuUnit::traceCommand(const Command& cmd, bool cscOnly) {
  Scheduler& s = s_;
  const CommandTiming& tm = cmd.timing;
  // Per macroblock (a few us) only in full detail; otherwise the same label throughout, so the
  // tracer joins a busy stretch into one span (at 290 macroblocks/s the two spans per macroblock
  // were 150 MB of trace.json per simulated hour).
  const bool fine = tracer_->detail() == TraceDetail::Full;
  if (cscOnly && !fine) {
    // The BDEC flow's display CSC in coalesced detail: one span for the command (its macroblocks
    // wait for their input from EE memory, so per-macroblock spans never touch and were not joined).
    if (tm.mbEnd.empty()) co_return;
    while (s.now() < tm.mbEnd.back()) co_await s.until(tm.mbEnd.back());
    tracer_->span(track_, tm.mbDecoded.front(), tm.mbEnd.back(), "csc");
    co_return;
  }
  std::size_t stall = 0;
  const Tick restartCycles = p_.slice_restart_cycles + p_.idec_start_cycles;
  for (std::size_t i = 0; i < tm.mbEnd.size(); ++i) {
    // The EE's restart of IDEC at a slice start code: the IPU core idles.
    if (tm.restart[i] != 0 && restartCycles > 0) {
      while (s.now() < tm.mbBegin[i]) co_await s.until(tm.mbBegin[i]);
      tracer_->span(track_, tm.mbBegin[i] - restartCycles, tm.mbBegin[i], "idec restart");
    }
    while (s.now() < tm.mbDecoded[i]) co_await s.until(tm.mbDecoded[i]);
    if (!cscOnly) tracer_->span(track_, tm.mbBegin[i], tm.mbDecoded[i], fine ? "idec" : "decode");
    // CSC rows that waited for room (full detail), then the macroblock's end. A stall that starts
    // while this sleeps can add a row stall ending before the tick it wakes at: that span is
    // recorded then, in order, with its own times.
    for (;;) {
      if (fine && stall < tm.rowStalls.size() && tm.rowStalls[stall].mb == i) {
        if (s.now() < tm.rowStalls[stall].end) {
          co_await s.until(tm.rowStalls[stall].end);
          continue;
        }
        tracer_->span(track_, tm.rowStalls[stall].ready, tm.rowStalls[stall].end, "out stall");
        ++stall;
        continue;
      }
      if (s.now() >= tm.mbEnd[i]) break;
      co_await s.until(tm.mbEnd[i]);
    }
    tracer_->span(track_, tm.mbDecoded[i], tm.mbEnd[i], fine || cscOnly ? "csc" : "decode");
  }
}

// The BDEC flow in coalesced detail: one `decode` span per unit (the EE, the IPU) per picture, from
// its first busy tick to its last, as strip mode shows one span per vsync (docs/player.md). Per
// macroblock the EE and the IPU take turns, so their spans never touch and were not joined: 114 MB
// of trace.json for 600 s of a 512x512 GOP-12 stream. Each end is read again on waking (a DMA stall
// may move it later).
Task<void> IpuUnit::traceFlowCoalesced(const Command& cmd) {
  std::array<bool, 2> done{false, false};
  for (;;) {
    std::array<Tick, 2> begin{kNever, kNever};
    std::array<Tick, 2> end{-1, -1};
    for (const FlowSpan& sp : cmd.flowTiming.spans) {
      begin[sp.track] = std::min(begin[sp.track], sp.begin);
      end[sp.track] = std::max(end[sp.track], sp.end);
    }
    int next = -1;
    for (int k = 0; k < 2; ++k) {
      if (!done[k] && end[k] >= 0 && (next < 0 || end[k] < end[next])) next = k;
    }
    if (next < 0) co_return;
    if (s_.now() < end[next]) {
      co_await s_.until(end[next]);
      continue;
    }
    tracer_->span(next == 0 ? eeTrack_ : track_, begin[next], end[next], "decode");
    done[next] = true;
  }
}

// Sleeps from one observable event of the command to the next: the end of each trace span and the
// last qword's write.
Task<void> IpuUnit::run(IpuUnit& u) {
  Scheduler& s = u.s_;
  for (;;) {
    const CommandRef ref = co_await u.commands_.pop();
    if (ref->flow) {
      if (u.tracer_ && u.tracer_->detail() == TraceDetail::Full) {
        // Spans ending before a stall keep their place in the order; later ones are re-read.
        for (std::size_t i = 0; i < ref->flowTiming.spans.size(); ++i) {
          while (s.now() < ref->flowTiming.spans[i].end) co_await s.until(ref->flowTiming.spans[i].end);
          const FlowSpan& sp = ref->flowTiming.spans[i];
          u.tracer_->span(sp.track == 0 ? u.eeTrack_ : u.track_, sp.begin, sp.end, sp.label);
        }
      } else if (u.tracer_) {
        co_await u.traceFlowCoalesced(*ref);
      }
      while (s.now() < ref->flowTiming.decodeEnd) co_await s.until(ref->flowTiming.decodeEnd);
      if (ref->hasCsc) {
        if (u.tracer_) {
          const Tick setup = ref->timing.arrival;
          if (setup > ref->flowTiming.decodeEnd) {
            while (s.now() < setup) co_await s.until(setup);
            u.tracer_->span(u.eeTrack_, ref->flowTiming.decodeEnd, setup,
                            u.tracer_->detail() == TraceDetail::Full ? "csc setup" : "decode");
          }
          co_await u.traceCommand(*ref, true);
        }
      }
    } else if (u.tracer_) {
      co_await u.traceCommand(*ref, false);
    }
    if (!ref->flow || ref->hasCsc) {
      // The last qword's DMA period starts where the stepping model started it, so the caller
      // resumes in the same order among the events of that tick.
      const CommandTiming& tm = ref->timing;
      while (s.now() < tm.lastResume) co_await s.until(tm.lastResume);
      while (s.now() < tm.finished) co_await s.until(tm.finished);
    }
    ref->done = true;
    ref->finishedEvent.notify();
  }
}

void IpuUnit::retire() {
  while (!inFlight_.empty() && quietAfter(*inFlight_.front()) < s_.now()) inFlight_.pop_front();
}

// A stall moves nothing before now: plan again from the oldest command with an event still ahead.
void IpuUnit::replan() {
  retire();
  if (inFlight_.empty()) return;
  timeline_.restore(inFlight_.front()->before);
  for (const CommandRef& c : inFlight_) plan(*c);
}

void IpuUnit::stallInputDma(Tick duration) {
  if (inStalls_.add(s_.now(), duration)) replan();
}

void IpuUnit::stallOutputDma(Tick duration) {
  if (outStalls_.add(s_.now(), duration)) replan();
}

std::vector<CommandTiming::Qwords> IpuUnit::qwordLog() const {
  std::vector<CommandTiming::Qwords> log;
  for (const CommandRef& c : recorded_) log.push_back(c->timing.qwords);
  return log;
}

}  // namespace vbim::ipu
