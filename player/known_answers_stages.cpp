// The per-stage vectors (docs/porting.md, "Per-stage vectors"): what each step of the IPU decode
// and of the GS blend computes for chosen inputs, so a port that differs in a whole-picture hash of
// ipu.txt finds the stage and the block where it starts to differ.
//
// - vlc.txt: the run/level pairs and quantised coefficients of chosen blocks (ipu/block_walker.hpp);
// - idct.txt: dequantised coefficients in, the platform IDCT's results out, for the same blocks and
//   for random blocks over IEEE 1180's ranges and saturating blocks;
// - csc.txt: a macroblock's YCbCr in, its RGB32 / RGB16 out (ipu/csc.hpp);
// - draw.txt: the blend draw by draw of a short scripted sequence (gs/blend.hpp, gs/blend16.hpp).
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "gs/blend.hpp"
#include "gs/blend16.hpp"
#include "ipu/block_walker.hpp"
#include "ipu/csc.hpp"
#include "ipu/picture_decoder.hpp"
#include "player/known_answers.hpp"
#include "player/vector_pictures.hpp"
#include "runtime/error.hpp"

namespace vbim::player {

namespace {

// Blocks of the first picture of each stream's lightmap and sky: every block of its first
// kFirstMacroblocks macroblocks; and of the busiest intra lightmap picture (the most bytes), the
// kBusyMacroblocks macroblocks with the most bits.
constexpr int kFirstMacroblocks = 2;
constexpr int kBusyMacroblocks = 2;

struct ChosenPicture {
  std::string prefix;  // STREAM/lightmap|sky/frame=F, and /field=top|bottom for a field picture
  ipu::WalkedPicture walked;
  bool intraFrame = false;  // an intra frame picture: `decoded` holds it (checked equal to the walk's assembly)
  ipu::FrameStore decoded;
  std::vector<int> chosen;  // indices into walked.macroblocks
};

std::string joinInts(const std::int16_t* v, int n) {
  std::string s;
  for (int i = 0; i < n; ++i) s += (i ? "," : "") + std::to_string(v[i]);
  return s;
}

std::string hexBytes(const std::uint8_t* p, std::size_t n) {
  static const char* kDigits = "0123456789abcdef";
  std::string s(2 * n, '0');
  for (std::size_t i = 0; i < n; ++i) {
    s[2 * i] = kDigits[p[i] >> 4];
    s[2 * i + 1] = kDigits[p[i] & 15];
  }
  return s;
}

// Walks the first picture of `bytes` and decodes them with `idct`; the two must agree (the walk is
// what the vectors show, the decode is what the model computes): an intra frame picture's walk,
// assembled, is the decoded picture; any other picture's (P, B, a field) macroblocks are the
// decoder's, with the same bits each.
// `opening`: the stream's first picture, whose sequence header a later picture's bytes may lack.
ChosenPicture walkChecked(const std::string& prefix, const std::vector<std::uint8_t>& bytes, ipu::IdctKind idct,
                          const std::vector<std::uint8_t>* opening = nullptr) {
  ChosenPicture c;
  c.prefix = prefix;
  ipu::DecoderOptions options;
  options.idct = idct;
  options.freshStorePerDecode = true;
  options.recordMacroblocks = true;
  ipu::Decoder dec(options);
  if (opening != nullptr) dec.decode(*opening);
  const ipu::SequenceHeader* sequence = dec.hasSequence() ? &dec.sequence() : nullptr;
  std::string error;
  if (!ipu::walkPicture(bytes, c.walked, error, 0, sequence)) throw ConfigError(prefix + ": " + error);
  if (c.walked.pictureStructure != 3) c.prefix += c.walked.pictureStructure == 1 ? "/field=top" : "/field=bottom";
  c.intraFrame = c.walked.codingType == 1 && c.walked.pictureStructure == 3;
  const ipu::PictureReport r = dec.decode(bytes);
  if (c.intraFrame) {
    const ipu::FrameStore assembled = ipu::assembleIntraPicture(c.walked, idct);
    const ipu::FrameStore& f = dec.frame();
    if (!r.clean() || f.y != assembled.y || f.cb != assembled.cb || f.cr != assembled.cr) {
      throw ConfigError(prefix + ": the block walk and the decoder disagree (" + r.describe() + ")");
    }
    c.decoded = f;
    return c;
  }
  // Every picture the bytes hold (both fields of a frame) against the decoder's trace.
  std::vector<ipu::WalkedMacroblock> all = c.walked.macroblocks;
  for (int index = 1;; ++index) {
    ipu::WalkedPicture more;
    if (!ipu::walkPicture(bytes, more, error, index, sequence)) break;
    all.insert(all.end(), more.macroblocks.begin(), more.macroblocks.end());
  }
  const std::vector<ipu::MacroblockBits>& trace = dec.macroblockTrace();
  for (std::size_t i = 0; i < std::max(all.size(), trace.size()); ++i) {
    if (i >= all.size() || i >= trace.size() || static_cast<std::uint32_t>(all[i].address) != trace[i].address ||
        all[i].bits != trace[i].bits) {
      throw ConfigError(prefix + ": the block walk and the decoder disagree at macroblock " + std::to_string(i) +
                        " of the picture (" + r.describe() + ")");
    }
  }
  return c;
}

// The first `n` macroblocks of a P or B picture with coded non-intra blocks.
std::vector<int> firstCodedNonIntra(const ipu::WalkedPicture& p, int n) {
  std::vector<int> out;
  for (std::size_t m = 0; m < p.macroblocks.size() && static_cast<int>(out.size()) < n; ++m) {
    if (!p.macroblocks[m].intra && p.macroblocks[m].codedBlockPattern != 0) out.push_back(static_cast<int>(m));
  }
  return out;
}

std::vector<ChosenPicture> choosePictures(const std::vector<VectorStream>& streams, ipu::IdctKind idct) {
  std::vector<ChosenPicture> out;
  std::vector<std::uint8_t> busiest;  // the largest intra lightmap picture's bytes
  std::string busiestPrefix;
  std::vector<std::uint8_t> busiestOpening;  // its stream's first picture
  for (const VectorStream& s : streams) {
    const StreamPictures sp = picturesOf(s);
    for (const auto& [streamId, name] : {std::pair<int, const char*>{0xE0, "lightmap"}, {0xE1, "sky"}}) {
      const int id = streamId;  // a structured binding cannot be captured before C++20's P1091 in clang 14
      const auto first =
          std::find_if(sp.pictures.begin(), sp.pictures.end(), [&](const auto& p) { return p.first.first == id; });
      if (first == sp.pictures.end()) continue;
      const std::string prefix = s.label + "/" + name + "/frame=" + std::to_string(first->first.second);
      ChosenPicture c = walkChecked(prefix, first->second, idct);
      for (int m = 0; m < kFirstMacroblocks && m < static_cast<int>(c.walked.macroblocks.size()); ++m) {
        c.chosen.push_back(m);
      }
      out.push_back(std::move(c));
      if (id != 0xE0) continue;
      // The first P and the first B lightmap picture with coded non-intra blocks: the first of their
      // macroblocks that have them. A picture
      // after a GOP's first carries no sequence header: the opening picture's is in force.
      ipu::Decoder opening;
      opening.decode(first->second);
      bool havePredicted[2] = {false, false};
      for (const auto& [key, data] : sp.pictures) {
        std::string error;
        ipu::WalkedPicture probe;
        if (key.first != id ||
            !ipu::walkPicture(data, probe, error, 0, opening.hasSequence() ? &opening.sequence() : nullptr)) {
          continue;
        }
        const std::string at = s.label + "/" + name + "/frame=" + std::to_string(key.second);
        if (probe.codingType == 1 && probe.pictureStructure == 3 && data.size() > busiest.size()) {
          busiestPrefix = at;
          busiest = data;
          busiestOpening = first->second;
        }
        // The first of each type with a coded non-intra block (a still or flat picture has none).
        if (probe.codingType == 1 || havePredicted[probe.codingType - 2]) continue;
        if (firstCodedNonIntra(probe, 1).empty()) continue;
        havePredicted[probe.codingType - 2] = true;
        ChosenPicture p = walkChecked(at, data, idct, &first->second);
        p.chosen = firstCodedNonIntra(p.walked, kFirstMacroblocks);
        if (!p.chosen.empty()) out.push_back(std::move(p));
      }
    }
  }
  if (!busiest.empty()) {
    ChosenPicture c = walkChecked(busiestPrefix, busiest, idct, &busiestOpening);
    std::vector<int> order(c.walked.macroblocks.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
      return c.walked.macroblocks[static_cast<std::size_t>(a)].bits >
             c.walked.macroblocks[static_cast<std::size_t>(b)].bits;
    });
    // erase, not resize: GCC 12's -Warray-bounds misreads resize's grow path under -fsanitize=thread.
    if (order.size() > static_cast<std::size_t>(kBusyMacroblocks))
      order.erase(order.begin() + kBusyMacroblocks, order.end());
    std::sort(order.begin(), order.end());
    c.chosen = order;
    out.push_back(std::move(c));
  }
  return out;
}

std::string blockKey(const ChosenPicture& c, const ipu::WalkedMacroblock& mb) {
  return c.prefix + "/mb=" + std::to_string(mb.address);
}

// IEEE 1180-1990 §3.2's generator, in integers: randx = randx * 1103515245 + 12345 (32 bits),
// then a value uniformly in [-lo, hi] from bits 1..30.
class Ieee1180Random {
 public:
  int next(int lo, int hi) {
    randx_ = randx_ * 1103515245u + 12345u;
    const std::uint64_t i = randx_ & 0x7ffffffeu;
    return static_cast<int>(i * static_cast<std::uint64_t>(lo + hi + 1) / 0x7fffffffu) - lo;
  }

 private:
  std::uint32_t randx_ = 1;
};

// round(2^15 x C(u) x cos((2x + 1) u pi / 16)), C(0) = sqrt(1/8), else 1/2: the forward DCT of
// the random blocks in integers, so they are the same on every machine.
constexpr std::int32_t kFdct[8][8] = {{11585, 11585, 11585, 11585, 11585, 11585, 11585, 11585},
                                      {16069, 13623, 9102, 3196, -3196, -9102, -13623, -16069},
                                      {15137, 6270, -6270, -15137, -15137, -6270, 6270, 15137},
                                      {13623, -3196, -16069, -9102, 9102, 16069, 3196, -13623},
                                      {11585, -11585, -11585, 11585, 11585, -11585, -11585, 11585},
                                      {9102, -16069, 3196, 13623, -13623, -3196, 16069, -9102},
                                      {6270, -15137, 15137, -6270, -6270, 15137, -15137, 6270},
                                      {3196, -9102, 13623, -16069, 16069, -13623, 9102, -3196}};

// A random pixel block in [-lo, hi] (times sign), forward transformed, rounded and saturated to
// [-2048, 2047]: IEEE 1180's test input.
void ieee1180Block(Ieee1180Random& rng, int lo, int hi, int sign, std::int16_t* coeffs) {
  std::int64_t pixels[64];
  for (std::int64_t& p : pixels) p = std::int64_t{sign} * rng.next(lo, hi);
  std::int64_t rows[64];
  for (int y = 0; y < 8; ++y) {
    for (int u = 0; u < 8; ++u) {
      std::int64_t s = 0;
      for (int x = 0; x < 8; ++x) s += pixels[8 * y + x] * kFdct[u][x];
      rows[8 * y + u] = s;
    }
  }
  for (int v = 0; v < 8; ++v) {
    for (int u = 0; u < 8; ++u) {
      std::int64_t s = 0;
      for (int y = 0; y < 8; ++y) s += rows[8 * y + u] * kFdct[v][y];
      const std::int64_t r = (s + (std::int64_t{1} << 29)) >> 30;  // floor(s / 2^30 + 1/2)
      coeffs[8 * v + u] = static_cast<std::int16_t>(std::clamp<std::int64_t>(r, -2048, 2047));
    }
  }
}

// An intra block's entries end with the samples IDEC writes; a non-intra block's result is its
// residual, which the EE adds to the prediction (BDEC writes it as signed 16-bit samples).
void addIdctEntry(std::string& t, const std::string& key, const std::int16_t* coeffs, ipu::IdctKind idct,
                  bool intra = true) {
  std::int16_t result[64];
  ipu::idctResult(idct, coeffs, result);
  t += key + "/in " + joinInts(coeffs, 64) + "\n";
  t += key + "/result " + joinInts(result, 64) + "\n";
  if (!intra) return;
  std::int16_t pixels[64];
  for (int i = 0; i < 64; ++i) pixels[i] = static_cast<std::int16_t>(std::clamp<int>(result[i], 0, 255));
  t += key + "/pixels " + joinInts(pixels, 64) + "\n";
}

// SETTH values of the threshold outputs, as ipu.txt's.
constexpr ipu::CscThresholds kThresholds{32, 96};

void addCscEntry(std::string& t, const std::string& key, const ipu::FrameStore& mb) {
  std::vector<std::uint8_t> in(mb.y);
  in.insert(in.end(), mb.cb.begin(), mb.cb.end());
  in.insert(in.end(), mb.cr.begin(), mb.cr.end());
  t += key + "/ycbcr " + hexBytes(in.data(), in.size()) + "\n";
  for (const bool th : {false, true}) {
    const ipu::CscThresholds thresholds = th ? kThresholds : ipu::CscThresholds{};
    const std::string suffix = th ? "_th" : "";
    Rgba8Image rgba;
    ipu::convertToRgba32(mb, 16, 16, thresholds, rgba);
    t += key + "/rgb32" + suffix + " " + hexBytes(rgba.pixels.data(), rgba.pixels.size()) + "\n";
    for (const bool dither : {false, true}) {
      std::vector<std::uint16_t> px;
      ipu::convertToRgb16(mb, 16, 16, thresholds, dither, px);
      std::vector<std::uint8_t> bytes;
      for (const std::uint16_t p : px) {
        bytes.push_back(static_cast<std::uint8_t>(p & 0xFF));
        bytes.push_back(static_cast<std::uint8_t>(p >> 8));
      }
      t += key + "/" + (dither ? "rgb16_dither" : "rgb16") + suffix + " " + hexBytes(bytes.data(), bytes.size()) + "\n";
    }
  }
}

// Macroblock (mbX, mbY) of a frame store as a one-macroblock store.
ipu::FrameStore macroblockOf(const ipu::FrameStore& fs, int mbX, int mbY) {
  ipu::FrameStore mb;
  mb.reset(1, 1);
  const auto lumaStride = static_cast<std::size_t>(fs.lumaStride);
  const auto chromaStride = static_cast<std::size_t>(fs.chromaStride);
  const auto x0 = static_cast<std::size_t>(mbX);
  const auto y0 = static_cast<std::size_t>(mbY);
  for (std::size_t r = 0; r < 16; ++r) {
    for (std::size_t x = 0; x < 16; ++x) mb.y[16 * r + x] = fs.y[(16 * y0 + r) * lumaStride + 16 * x0 + x];
  }
  for (std::size_t r = 0; r < 8; ++r) {
    for (std::size_t x = 0; x < 8; ++x) {
      const std::size_t at = (8 * y0 + r) * chromaStride + 8 * x0 + x;
      mb.cb[8 * r + x] = fs.cb[at];
      mb.cr[8 * r + x] = fs.cr[at];
    }
  }
  return mb;
}

std::string idctHeaderLine(ipu::IdctKind idct) {
  return "# IDCT: " + std::string(ipu::idctKindName(idct)) +
         " (platform parameter ipu.idct, docs/timing/ipu.md#idct)\n";
}

}  // namespace

VectorFile vlcVectors(const std::vector<VectorStream>& streams) {
  std::string t =
      "# vbim known answers: the VLC and run/level stage of IDEC for chosen blocks (ipu/block_walker.hpp)\n"
      "# Blocks: every block of the first 2 macroblocks of each stream's first lightmap and sky picture, and the\n"
      "#   2 macroblocks with the most bits of the largest intra lightmap picture; of a stream with P and B\n"
      "#   pictures (BDEC), also the first 2 macroblocks with coded non-intra blocks of the first P and the first\n"
      "#   B lightmap picture that have some. mb=M: macroblock address (row x macroblocks per row + column; a\n"
      "#   field picture, /field=top|bottom after frame=F, counts its own rows); block=B: 0-3 luma (top left,\n"
      "#   top right, bottom left, bottom right), 4 Cb, 5 Cr; a non-intra macroblock lists its coded blocks.\n"
      "# KEY vlc/STREAM/lightmap|sky/frame=F/mb=M  VALUE quantiser_scale_code=Q,dct_type=frame|field; in a P or B\n"
      "#   picture then ,macroblock_type=T (the sum of quant 1, motion_forward 2, motion_backward 4, pattern 8,\n"
      "#   intra 16),coded_block_pattern=C (bit 5 block 0 .. bit 0 block 5)\n"
      "# KEY .../mb=M/block=B/runlevel  VALUE intra: dc_size=S dc_differential=D, then each AC coefficient as\n"
      "#   RUN:LEVEL (esc:RUN:LEVEL when escape-coded), then eob; non-intra: each coefficient as RUN:LEVEL from\n"
      "#   scan position 0 (a first code '1s' is 0:1 or 0:-1), then eob\n"
      "# KEY .../mb=M/block=B/quantised  VALUE the 64 quantised coefficients QF[v][u] in natural (raster) order,\n"
      "#   comma-separated: an intra QF[0][0] is the predicted DC (predictor + differential), the others the\n"
      "#   levels\n";
  // The walk does not depend on the IDCT; the default decodes the pictures it is checked against.
  for (const ChosenPicture& c : choosePictures(streams, ipu::kDefaultIdct)) {
    for (const int m : c.chosen) {
      const ipu::WalkedMacroblock& mb = c.walked.macroblocks[static_cast<std::size_t>(m)];
      const std::string key = "vlc/" + blockKey(c, mb);
      t += key + " quantiser_scale_code=" + std::to_string(mb.quantiserScaleCode) +
           ",dct_type=" + (mb.fieldDct ? "field" : "frame");
      if (c.walked.codingType != 1) {
        t += ",macroblock_type=" + std::to_string(mb.type) +
             ",coded_block_pattern=" + std::to_string(mb.codedBlockPattern);
      }
      t += "\n";
      for (int b = 0; b < 6; ++b) {
        const ipu::WalkedBlock& blk = mb.blocks[static_cast<std::size_t>(b)];
        if (!blk.coded) continue;
        std::string rl = blk.intra ? "dc_size=" + std::to_string(blk.dcSize) +
                                         " dc_differential=" + std::to_string(blk.dcDifferential) + " "
                                   : "";
        for (const ipu::RunLevel& p : blk.ac) {
          rl += std::string(p.escape ? "esc:" : "") + std::to_string(p.run) + ":" + std::to_string(p.level) + " ";
        }
        rl += "eob";
        t += key + "/block=" + std::to_string(b) + "/runlevel " + rl + "\n";
        t += key + "/block=" + std::to_string(b) + "/quantised " + joinInts(blk.quantised.data(), 64) + "\n";
      }
    }
  }
  return VectorFile{"vlc.txt", t};
}

VectorFile idctVectors(const std::vector<VectorStream>& streams, ipu::IdctKind idct) {
  std::string t =
      "# vbim known answers: the IDCT stage of IDEC (ipu/block_walker.hpp idctResult, ipu/idct_libmpeg2.hpp)\n"
      "# KEY idct/STREAM/lightmap|sky/frame=F/mb=M/block=B/in  VALUE the 64 dequantised coefficients F[v][u]\n"
      "#   (natural order, comma-separated; saturated to -2048..2047, MPEG-2 mismatch control applied): the\n"
      "#   blocks of vlc.txt; a non-intra block's with the non-intra matrix and (2 QF + sign(QF)) (§7.4.2.3)\n"
      "# KEY .../result  VALUE the IDCT's 64 results (raster order) before any clip; of a non-intra block, the\n"
      "#   residual BDEC writes (signed 16-bit) and the EE adds to the prediction, clamping the sum to 0..255\n"
      "# KEY .../pixels  VALUE the 64 samples IDEC writes for an intra block: result clamped to 0..255 (intra\n"
      "#   blocks only)\n"
      "# KEY idct/ieee1180/-LO..HI/sign=S/K/...  the same for random blocks of IEEE 1180-1990: pixels\n"
      "#   uniform in [-LO, HI] times S from its generator (randx = randx * 1103515245 + 12345, 32 bits;\n"
      "#   value (randx & 0x7ffffffe) * (LO + HI + 1) / 0x7fffffff - LO, in integers), forward transformed\n"
      "#   and rounded (in integers, player/known_answers_stages.cpp), saturated to -2048..2047\n"
      "# KEY idct/saturating/NAME/...  blocks at the ends of the coefficient range\n" +
      idctHeaderLine(idct);
  for (const ChosenPicture& c : choosePictures(streams, idct)) {
    for (const int m : c.chosen) {
      const ipu::WalkedMacroblock& mb = c.walked.macroblocks[static_cast<std::size_t>(m)];
      for (int b = 0; b < 6; ++b) {
        const ipu::WalkedBlock& blk = mb.blocks[static_cast<std::size_t>(b)];
        if (!blk.coded) continue;
        addIdctEntry(t, "idct/" + blockKey(c, mb) + "/block=" + std::to_string(b), blk.dequantised.data(), idct,
                     blk.intra);
      }
    }
  }
  // IEEE 1180's ranges and both signs, a few blocks each (one generator run per range and sign).
  constexpr int kRandomBlocks = 4;
  const int ranges[][2] = {{256, 255}, {5, 5}, {300, 300}};
  for (const auto& r : ranges) {
    for (const int sign : {1, -1}) {
      Ieee1180Random rng;
      for (int k = 0; k < kRandomBlocks; ++k) {
        std::int16_t coeffs[64];
        ieee1180Block(rng, r[0], r[1], sign, coeffs);
        addIdctEntry(t,
                     "idct/ieee1180/-" + std::to_string(r[0]) + ".." + std::to_string(r[1]) +
                         "/sign=" + (sign > 0 ? "+1" : "-1") + "/" + std::to_string(k),
                     coeffs, idct);
      }
    }
  }
  // Blocks no encoder makes but a decoder must survive: every coefficient at a limit, alternating
  // limits (the row pass's sums at their largest), the DC alone at each limit, F[7][7] alone.
  struct Saturating {
    const char* name;
    std::int16_t (*at)(int i);
  };
  const Saturating saturating[] = {
      {"all_2047", [](int) -> std::int16_t { return 2047; }},
      {"all_-2048", [](int) -> std::int16_t { return -2048; }},
      {"checkerboard", [](int i) -> std::int16_t { return ((i >> 3) + i) & 1 ? -2048 : 2047; }},
      {"rows_alternating", [](int i) -> std::int16_t { return (i >> 3) & 1 ? -2048 : 2047; }},
      {"dc_2047", [](int i) -> std::int16_t { return i == 0 ? 2047 : 0; }},
      {"dc_-2048", [](int i) -> std::int16_t { return i == 0 ? -2048 : 0; }},
      {"f77_1", [](int i) -> std::int16_t { return i == 63 ? 1 : 0; }},
      {"first_row_2047", [](int i) -> std::int16_t { return i < 8 ? 2047 : 0; }},
  };
  for (const Saturating& s : saturating) {
    std::int16_t coeffs[64];
    for (int i = 0; i < 64; ++i) coeffs[i] = s.at(i);
    addIdctEntry(t, std::string("idct/saturating/") + s.name, coeffs, idct);
  }
  return VectorFile{"idct.txt", t};
}

VectorFile cscVectors(const std::vector<VectorStream>& streams, ipu::IdctKind idct) {
  std::string t =
      "# vbim known answers: the CSC stage per macroblock (ipu/csc.hpp)\n"
      "# KEY csc/STREAM/lightmap|sky/frame=F/mb=M/ycbcr  VALUE the macroblock IDEC decoded (the macroblocks of\n"
      "#   vlc.txt's intra frame pictures; the CSC does not depend on how a picture was coded): 384 bytes in hex, Y 16 "
      "rows of 16, then Cb 8 rows of 8, then Cr 8 rows of 8\n"
      "# KEY csc/synthetic/NAME/ycbcr  the same for made-up macroblocks: ramps, range ends, the SETTH edges\n"
      "# KEY .../OUTPUT  VALUE the CSC output in hex, 16 rows of 16 pixels top to bottom (the macroblock's\n"
      "#   order in the fromIPU FIFO): rgb32 (OFM 0: R G B A bytes), rgb16 (OFM 1, DTE 0), rgb16_dither\n"
      "#   (DTE 1) as little-endian 16-bit pixels (bits 0-4 R, 5-9 G, 10-14 B, 15 A); _th: SETTH TH0 = 32,\n"
      "#   TH1 = 96. The dither is indexed by the pixel's position in the macroblock (a macroblock starts on a\n"
      "#   multiple of 16, so its position in the picture gives the same index).\n" +
      idctHeaderLine(idct) + "#   (the YCbCr of the stream macroblocks is its output)\n";
  for (const ChosenPicture& c : choosePictures(streams, idct)) {
    if (!c.intraFrame) continue;  // the CSC converts whole frames: the intra pictures' macroblocks show it
    for (const int m : c.chosen) {
      const ipu::WalkedMacroblock& mb = c.walked.macroblocks[static_cast<std::size_t>(m)];
      addCscEntry(t, "csc/" + blockKey(c, mb), macroblockOf(c.decoded, mb.mbX, mb.mbY));
    }
  }
  struct Synthetic {
    const char* name;
    int (*y)(int x, int r);
    int (*cb)(int x, int r);
    int (*cr)(int x, int r);
  };
  const Synthetic synthetic[] = {
      {"ramps", [](int x, int r) { return 16 * r + x; }, [](int x, int) { return 36 * x + 2; },
       [](int, int r) { return 36 * r + 1; }},
      {"range_ends",
       [](int x, int r) {
         return (x + r) % 4 == 0 ? 0 : (x + r) % 4 == 1 ? 255 : (x + r) % 4 == 2 ? 16 : 235;
       },
       [](int x, int r) { return (x + 2 * r) % 3 == 0   ? 0
                                 : (x + 2 * r) % 3 == 1 ? 255
                                                        : 128; },
       [](int x, int r) { return (2 * x + r) % 3 == 0   ? 255
                                 : (2 * x + r) % 3 == 1 ? 0
                                                        : 128; }},
      {"thresholds", [](int x, int r) { return r < 8 ? 36 + x : 91 + x; }, [](int x, int) { return 124 + x; },
       [](int, int r) { return 132 - r; }},
  };
  for (const Synthetic& s : synthetic) {
    ipu::FrameStore mb;
    mb.reset(1, 1);
    std::size_t i = 0;
    for (int r = 0; r < 16; ++r) {
      for (int x = 0; x < 16; ++x) mb.y[i++] = static_cast<std::uint8_t>(s.y(x, r));
    }
    i = 0;
    for (int r = 0; r < 8; ++r) {
      for (int x = 0; x < 8; ++x, ++i) {
        mb.cb[i] = static_cast<std::uint8_t>(s.cb(x, r));
        mb.cr[i] = static_cast<std::uint8_t>(s.cr(x, r));
      }
    }
    addCscEntry(t, std::string("csc/synthetic/") + s.name, mb);
  }
  return VectorFile{"csc.txt", t};
}

namespace {

constexpr int kDrawWidth = 8;
constexpr int kDrawHeight = 4;

// A decoded frame of the draw sequences: the pattern image with the alpha the IPU writes (0x80, or
// 0x40 for every fifth pixel as SETTH TH1 would).
Rgba8Image drawFrame(int seed) {
  Rgba8Image img = patternImage(kDrawWidth, kDrawHeight, seed);
  for (std::size_t p = 0; p < img.pixels.size() / 4; ++p) img.pixels[4 * p + 3] = p % 5 == 0 ? 0x40 : 0x80;
  return img;
}

struct Draw {
  int frame;  // 0: A, 1: B
  int fix;
};

void addDrawSequence(std::string& t, const std::string& name, const std::vector<Draw>& draws, gs::ColClamp clamp,
                     bool ct16) {
  Rgba8Image frames[2] = {drawFrame(1), drawFrame(2)};
  if (ct16) {
    for (Rgba8Image& f : frames) {
      Rgba8Image staged;
      gs::staging16FromRgb32(f, staged);
      f = staged;
    }
  }
  Rgba8Image dst(kDrawWidth, kDrawHeight);  // all zero, as the presenter's texture starts
  for (std::size_t k = 0; k < draws.size(); ++k) {
    const Draw& d = draws[k];
    const Rgba8Image& src = frames[d.frame];
    gs::BlendSpec spec = gs::makeBlendSpec(d.fix, clamp);
    spec.psmct16 = ct16;
    spec.dither = ct16 && d.fix != 0x80;  // DTHE off for the copy
    const std::string key = "draw/" + name + "/" + std::to_string(k);
    char fix[8];
    std::snprintf(fix, sizeof fix, "0x%02X", d.fix);
    t += key + "/setup fix=" + fix + ",colclamp=" + (clamp == gs::ColClamp::Clamp ? "clamp" : "wrap") +
         ",psm=" + (ct16 ? "ct16" : "ct32") + ",dthe=" + (spec.dither ? "1" : "0") + "\n";
    t += key + "/source " + hexBytes(src.pixels.data(), src.pixels.size()) + "\n";
    t += key + "/destination " + hexBytes(dst.pixels.data(), dst.pixels.size()) + "\n";
    const std::size_t stride = static_cast<std::size_t>(kDrawWidth) * 4;
    if (ct16) {
      gs::blend16Rect(dst.pixels.data(), stride, src.pixels.data(), stride, kDrawWidth, kDrawHeight, 0, 0, spec);
    } else {
      gs::blendSpanScalar(dst.pixels.data(), src.pixels.data(), dst.pixels.size() / 4, spec);
    }
    t += key + "/result " + hexBytes(dst.pixels.data(), dst.pixels.size()) + "\n";
  }
}

}  // namespace

VectorFile drawVectors() {
  std::string t =
      "# vbim known answers: the blend draw by draw (gs/blend.hpp, gs/blend16.hpp): the lightmap draw of\n"
      "#   docs/porting.md on an 8x4 texture at (0, 0), starting all zero, in a scripted sequence of frames\n"
      "# KEY draw/SEQUENCE/K/setup  VALUE fix=FIX (ALPHA_1.FIX),colclamp=clamp|wrap (COLCLAMP),psm=ct32|ct16,\n"
      "#   dthe=0|1 (DTHE, the GS dither with DIMX of docs/porting.md)\n"
      "# KEY .../source  VALUE the texture the sprite reads (Cs, As), RGBA bytes in hex, rows top to bottom\n"
      "# KEY .../destination  VALUE the lightmap before the draw (Cd); the previous draw's result\n"
      "# KEY .../result  VALUE the lightmap after the draw\n"
      "# Frames: A (pattern seed 1) and B (seed 2) of frame_hash.txt's pattern, alpha 0x80, every fifth pixel\n"
      "#   0x40. ct32: the first frame copied in (FIX 0x80), then FIX 0x40 toward B and A. ct32_wrap: COLCLAMP\n"
      "#   0 with FIX 0xC0 (overshoot wraps). ct16: the PSMCT16 path, texels as the GS expands them (5-bit\n"
      "#   value << 3, A = 0x80 when bit 15 is set); the source is the IPU's dithered RGB16 of the frame read\n"
      "#   through TEXA (TA0 0x80, TA1 0x40); the copy without DTHE, the blends with it\n";
  addDrawSequence(t, "ct32", {{0, 0x80}, {1, 0x40}, {1, 0x40}, {1, 0x40}, {0, 0x40}}, gs::ColClamp::Clamp, false);
  addDrawSequence(t, "ct32_wrap", {{0, 0x80}, {1, 0xC0}, {0, 0xC0}}, gs::ColClamp::Wrap, false);
  addDrawSequence(t, "ct16", {{0, 0x80}, {1, 0x40}, {1, 0x40}, {1, 0x40}, {0, 0x40}}, gs::ColClamp::Clamp, true);
  return VectorFile{"draw.txt", t};
}

}  // namespace vbim::player
