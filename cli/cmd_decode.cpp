// vbim decode STREAM --out DIR --format png|exr|yuv: every picture of a stream through the IPU
// decoder (no timing). STREAM is an MPEG program stream (a VBIM stream: 2048-byte packs, video
// 0xE0 / 0xE1) or a raw MPEG-1/2 video elementary stream (.m2v / .m1v).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "cli/output_dir.hpp"
#include "imageio/exr_writer.hpp"
#include "imageio/png_writer.hpp"
#include "ipu/csc.hpp"
#include "ipu/elementary_stream.hpp"
#include "ipu/picture_decoder.hpp"
#include "ipu/simd/simd_kernels.hpp"
#include "runtime/worker_pool.hpp"

namespace vbim::cli {
namespace {

// A piece of the elementary stream and where it came from in the file.
struct Segment {
  std::size_t esOffset;
  std::size_t fileOffset;
};

struct Demuxed {
  std::vector<std::uint8_t> es;
  std::vector<Segment> segments;  // ascending esOffset
  int streamId = -1;
  std::vector<std::string> warnings;
  std::size_t fileOffsetOf(std::size_t esOffset) const {
    std::size_t lo = 0, hi = segments.size();
    while (hi - lo > 1) {
      const std::size_t mid = (lo + hi) / 2;
      if (segments[mid].esOffset <= esOffset)
        lo = mid;
      else
        hi = mid;
    }
    return segments.empty() ? esOffset : segments[lo].fileOffset + (esOffset - segments[lo].esOffset);
  }
};

bool startCodeAt(const std::vector<std::uint8_t>& d, std::size_t i) {
  return i + 3 < d.size() && d[i] == 0 && d[i + 1] == 0 && d[i + 2] == 1;
}

// A minimal MPEG-1/2 program stream reader (ISO/IEC 13818-1 §2.5.3): packs, system headers, PES
// packets of one video stream. `vbim decode` takes any program stream (MPEG-1 system streams, packs
// of any size), while vbim::streams::Demuxer reads VBIM's one-pack-per-2048-byte-sector layout the
// way the EE receives it; so this byte-level reader stays here, in the tool.
Demuxed demuxProgramStream(const std::vector<std::uint8_t>& d, int wantStream, const std::string& name) {
  Demuxed out;
  std::size_t i = 0;
  auto resync = [&](const std::string& why) {
    out.warnings.push_back(name + ": byte " + std::to_string(i) + ": " + why + "; skipping to the next pack");
    std::size_t j = i + 1;
    while (j + 3 < d.size() && !(startCodeAt(d, j) && d[j + 3] == 0xBA)) ++j;
    i = j + 3 < d.size() ? j : d.size();
  };
  while (i + 4 <= d.size()) {
    if (!startCodeAt(d, i)) {
      resync("expected a start code (00 00 01)");
      continue;
    }
    const int id = d[i + 3];
    if (id == 0xB9) break;  // MPEG_program_end_code
    if (id == 0xBA) {       // pack header
      if (i + 5 > d.size()) break;
      std::size_t len;
      if ((d[i + 4] & 0xC0) == 0x40) {  // MPEG-2
        if (i + 14 > d.size()) break;
        len = 14 + (d[i + 13] & 7);
      } else if ((d[i + 4] & 0xF0) == 0x20) {  // MPEG-1
        len = 12;
      } else {
        resync("pack header of neither MPEG-1 nor MPEG-2 form");
        continue;
      }
      i += len;
      continue;
    }
    if (id < 0xB9) {
      resync("a video start code (0x" + std::to_string(id) + ") outside a PES packet");
      continue;
    }
    if (i + 6 > d.size()) break;
    const std::size_t len = (static_cast<std::size_t>(d[i + 4]) << 8) | d[i + 5];
    const std::size_t end = i + 6 + len;
    if (end > d.size()) {
      out.warnings.push_back(name + ": byte " + std::to_string(i) + ": PES packet runs past the end of the file");
    }
    const std::size_t stop = end > d.size() ? d.size() : end;
    const bool video = id >= 0xE0 && id <= 0xEF;
    if (video && out.streamId < 0 && (wantStream < 0 || wantStream == id)) out.streamId = id;
    if (video && id == out.streamId) {
      std::size_t p = i + 6;
      if (p < stop && (d[p] & 0xC0) == 0x80) {  // MPEG-2 PES header
        if (p + 3 <= stop)
          p += 3 + d[p + 2];
        else
          p = stop;
      } else {  // MPEG-1: stuffing, STD buffer, PTS/DTS
        while (p < stop && d[p] == 0xFF) ++p;
        if (p < stop && (d[p] & 0xC0) == 0x40) p += 2;
        if (p < stop && (d[p] & 0xF0) == 0x20)
          p += 5;
        else if (p < stop && (d[p] & 0xF0) == 0x30)
          p += 10;
        else if (p < stop && d[p] == 0x0F)
          p += 1;
      }
      if (p < stop) {
        out.segments.push_back({out.es.size(), p});
        out.es.insert(out.es.end(), d.begin() + static_cast<std::ptrdiff_t>(p),
                      d.begin() + static_cast<std::ptrdiff_t>(stop));
      }
    }
    i = stop;
  }
  return out;
}

std::vector<std::uint8_t> readFile(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw Exit(2, path + ": cannot open the file");
  return std::vector<std::uint8_t>((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

struct Options {
  std::string input;
  std::string outDir;
  std::string format = "png";
  std::string stream;
  unsigned threads = 0;
  bool force = false;
  bool strict = false;
  int th0 = 0;
  int th1 = 0;
};

constexpr std::uint8_t kPrefix[3] = {0, 0, 1};

void run(const Options& o) {
  const std::vector<std::uint8_t> file = readFile(o.input);
  Demuxed dm;
  if (file.size() >= 4 && startCodeAt(file, 0) && file[3] == 0xBA) {
    int want = -1;
    if (!o.stream.empty()) want = static_cast<int>(std::stoul(o.stream, nullptr, 0));
    dm = demuxProgramStream(file, want, o.input);
    if (dm.streamId < 0)
      throw Exit(1, o.input + ": MPEG program stream without " +
                        (want < 0 ? std::string("a video stream (PES id 0xE0..0xEF)") : "video stream " + o.stream));
  } else if (std::search(file.begin(), file.end(), std::begin(kPrefix), std::end(kPrefix)) != file.end()) {
    // A video elementary stream; if it lacks a sequence header the decoder says so.
    dm.es = file;
    dm.segments.push_back({0, 0});
  } else {
    throw Exit(1, o.input +
                      ": byte 0: not an MPEG program stream or video elementary stream "
                      "(expected 00 00 01 BA or 00 00 01 B3)");
  }
  for (const std::string& w : dm.warnings) std::cerr << "vbim decode: warning: " << w << "\n";

  OutputDir dir(o.outDir, o.force);
  ipu::DecoderOptions options;
  options.kernels = &ipu::simdKernels();  // same bytes as the scalar reference, faster
  ipu::Decoder decoder(options);
  std::unique_ptr<WorkerPool> pool;
  if (o.threads > 1) pool = std::make_unique<WorkerPool>(o.threads - 1);
  std::string where;
  if (dm.streamId >= 0) {
    static const char kHex[] = "0123456789ABCDEF";
    where = std::string(" (video stream 0x") + kHex[(dm.streamId >> 4) & 15] + kHex[dm.streamId & 15] + ")";
  }

  int pictures = 0;
  int pendingField = 0;  // parity of a first field waiting for its second
  long concealed = 0;
  std::size_t issues = 0;
  Rgba8Image rgba;
  Yuv420Image yuv;
  std::vector<float> floats;
  for (const ipu::AccessUnit& au : ipu::splitAccessUnits(dm.es)) {
    const auto bytes = std::span(dm.es).subspan(au.offset, au.size);
    const ipu::PictureReport r = pool ? decoder.decode(bytes, *pool) : decoder.decode(bytes);
    for (const ipu::DecodeIssue& is : r.issues) {
      std::cerr << "vbim decode: " << o.input << where << ": byte " << dm.fileOffsetOf(au.offset + is.byteOffset);
      if (is.mbX >= 0) std::cerr << ", picture " << pictures << " macroblock (" << is.mbX << "," << is.mbY << ")";
      std::cerr << ": " << ipu::issueName(is.kind) << "\n";
    }
    if (r.issueCount > r.issues.size())
      std::cerr << "vbim decode: ... and " << (r.issueCount - r.issues.size()) << " more issues in this picture\n";
    issues += r.issueCount;
    if (r.undecodable) {
      const ipu::IssueKind k = r.issues.empty() ? ipu::IssueKind::kBadHeader : r.issues.back().kind;
      throw Exit(1, o.input + where + ": byte " + std::to_string(dm.fileOffsetOf(au.offset)) +
                        ": cannot decode: " + ipu::issueName(k));
    }
    if (!r.produced) continue;
    // A field picture completes its frame only with the second field (of the other parity).
    const int structure = decoder.picture().pictureStructure;
    if (structure != 3) {
      if (pendingField == 0 || pendingField == structure) {
        pendingField = structure;
        continue;
      }
      pendingField = 0;
    }
    concealed += r.macroblocksConcealed;
    char name[64];
    std::snprintf(name, sizeof name, "frame_%05d.%s", pictures, o.format.c_str());
    const int w = decoder.width(), h = decoder.height();
    if (o.format == "yuv") {
      ipu::copyToYuv420(decoder.frame(), w, h, yuv);
      std::ofstream f(dir.path(name), std::ios::binary);
      f.write(reinterpret_cast<const char*>(yuv.y.data()), static_cast<std::streamsize>(yuv.y.size()));
      f.write(reinterpret_cast<const char*>(yuv.cb.data()), static_cast<std::streamsize>(yuv.cb.size()));
      f.write(reinterpret_cast<const char*>(yuv.cr.data()), static_cast<std::streamsize>(yuv.cr.size()));
      if (!f) throw Exit(1, dir.path(name).string() + ": cannot write");
    } else {
      ipu::convertToRgba32(decoder.frame(), w, h, ipu::CscThresholds{o.th0, o.th1}, rgba, decoder.kernels().cscRow);
      // GS alpha 0x80 = 1.0: PNG alpha 255 = 2 * a (clamped), EXR alpha = a / 128.
      if (o.format == "png") {
        for (std::size_t i = 3; i < rgba.pixels.size(); i += 4)
          rgba.pixels[i] = static_cast<std::uint8_t>(rgba.pixels[i] >= 0x80 ? 255 : rgba.pixels[i] * 2);
        imageio::writePng(dir.path(name), imageio::ImageView<std::uint8_t>{w, h, 4, rgba.pixels.data()});
      } else {
        floats.resize(rgba.pixels.size());
        for (std::size_t i = 0; i < rgba.pixels.size(); ++i)
          floats[i] = (i % 4 == 3) ? rgba.pixels[i] / 128.0f : rgba.pixels[i] / 255.0f;
        imageio::writeExr(dir.path(name), imageio::ImageView<float>{w, h, 4, floats.data()});
      }
    }
    ++pictures;
  }
  if (pictures == 0) {
    if (!decoder.hasSequence()) throw Exit(1, o.input + where + ": no sequence header: nothing can be decoded");
    throw Exit(1, o.input + where + ": no picture could be decoded");
  }
  if (o.strict && issues > 0) throw Exit(1, o.input + where + ": " + std::to_string(issues) + " issues (--strict)");
  dir.commit();
  std::cout << "decoded " << pictures << " pictures " << decoder.width() << "x" << decoder.height() << " ("
            << (decoder.sequence().mpeg2 ? "MPEG-2" : "MPEG-1") << ")" << where << " to " << o.outDir << "/ as "
            << o.format;
  if (issues) std::cout << "; " << issues << " issues, " << concealed << " macroblocks concealed";
  std::cout << "\n";
}

}  // namespace

void addDecode(CLI::App& app) {
  auto* cmd = app.add_subcommand("decode", "Decode every picture of a stream with the IPU model (no timing)");
  auto o = std::make_shared<Options>();
  cmd->add_option("stream", o->input, "MPEG program stream (VBIM stream) or MPEG-1/2 video elementary stream")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", o->outDir, "Output directory (written completely or not at all)")->required();
  cmd->add_option("--format", o->format, "png (RGBA, GS alpha doubled), exr (half float) or yuv (planar 4:2:0)")
      ->check(CLI::IsMember({"png", "exr", "yuv"}));
  cmd->add_option("--stream-id", o->stream, "PES stream id to decode, e.g. 0xE1 (default: the first video stream)");
  cmd->add_option("--threads", o->threads, "Slice-parallel decode on this many host threads (same bytes out)");
  cmd->add_option("--th0", o->th0, "SETTH TH0: pixels with R, G, B all below it become transparent black")
      ->check(CLI::Range(0, 511));
  cmd->add_option("--th1", o->th1, "SETTH TH1: pixels with R, G, B all below it get alpha 0x40")
      ->check(CLI::Range(0, 511));
  cmd->add_flag("--force", o->force, "Replace a non-empty output directory");
  cmd->add_flag("--strict", o->strict, "Fail (exit 1) if any picture needed concealment");
  cmd->callback([o] { run(*o); });
}

}  // namespace vbim::cli
