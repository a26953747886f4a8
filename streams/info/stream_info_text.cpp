// `vbim info`'s text and the scan behind both of its forms.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <exception>
#include <fstream>

#include "runtime/error.hpp"
#include "streams/disc/stream_disc.hpp"
#include "streams/format.hpp"
#include "streams/info/stream_info.hpp"

namespace vbim::streams {

namespace {

constexpr std::size_t kTextBuckets = 24;  // rows of the bitrate table in text output

// printf into `out`: the text is the one `vbim info` has always printed, number for number.
__attribute__((format(printf, 2, 3))) void appendf(std::string& out, const char* format, ...) {
  std::va_list args;
  va_start(args, format);
  std::va_list again;
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  if (n > 0) {
    const std::size_t at = out.size();
    out.resize(at + static_cast<std::size_t>(n) + 1);
    std::vsnprintf(out.data() + at, static_cast<std::size_t>(n) + 1, format, again);
    out.resize(at + static_cast<std::size_t>(n));
  }
  va_end(again);
}

// Bytes per picture type and the GOP structure (stream order, split at GOP headers).
void typesAndGops(std::string& out, const StreamReport& r) {
  for (std::size_t t = 0; t < r.types.size(); ++t) {
    const TypeReport& tr = r.types[t];
    if (tr.pictures == 0) continue;
    appendf(out, "  %s pictures %9zu  bytes min %.0f  mean %.1f  max %.0f  (mean %.0f bits)\n",
            pictureTypeName(static_cast<PictureType>(t + 1)), tr.pictures, tr.bytes.min, tr.bytes.mean, tr.bytes.max,
            tr.bytes.mean * 8);
  }
  if (r.unknownType) appendf(out, "  unreadable picture headers %zu\n", r.unknownType);
  if (r.gops == 0) return;
  appendf(out, "  GOPs %zu (%zu closed, %zu open), %.0f..%.0f pictures (mean %.2f)\n", r.gops, r.closedGops,
          r.gops - r.closedGops, r.gopPictures.min, r.gopPictures.max, r.gopPictures.mean);
  constexpr std::size_t kShown = 4;  // distinct shapes listed; --json lists them all
  for (std::size_t i = 0; i < r.shapes.size() && i < kShown; ++i) {
    const GopShape& g = r.shapes[i];
    const bool longShape = g.pattern.size() > 48;
    appendf(out, "    %s%s x %zu\n", g.pattern.substr(0, 48).c_str(), longShape ? "..." : "", g.count);
  }
  if (r.shapes.size() > kShown) appendf(out, "    ... %zu more shapes\n", r.shapes.size() - kShown);
}

void descriptorText(std::string& out, const StreamInfo& info) {
  if (!info.scan.descriptor) {
    appendf(out, "descriptor: none (not a VBIM stream, or damaged); rates below assume %.3g frames/s\n", info.fps);
    return;
  }
  const Descriptor& d = *info.scan.descriptor;
  appendf(out,
          "descriptor: version %u, %u sectors; game rate %u/%u frames/s; %u frames per variant; loop to frame %u\n",
          d.intraOnly() ? Descriptor::kVersionIntra : Descriptor::kVersion, d.descriptorSectors, d.gameFps.num,
          d.gameFps.den, d.framesPerVariant, d.loopFrame);
  appendf(out, "  container: first PTS %lld, %u ticks (90 kHz) per frame; %u sectors in all\n",
          static_cast<long long>(d.firstPts), d.ptsPerFrame, d.totalSectors);
  for (const StreamEntry& s : d.streams) {
    appendf(out, "  stream %s %s %ux%u\n", hexId(s.id).c_str(), s.role == StreamRole::Lightmap ? "lightmap" : "sky",
            s.width, s.height);
  }
  for (const Variant& v : d.variants) {
    appendf(out, "  variant '%s': frames %u..%u, from sector %u\n", v.name.c_str(), v.firstFrame,
            v.firstFrame + d.framesPerVariant - 1, v.firstSector);
  }
}

void reportText(std::string& out, const StreamReport& r, double fps, bool fpsGuessed) {
  appendf(out, "\nstream %s: %zu pictures\n", hexId(r.id).c_str(), r.pictures);
  appendf(out, "  bytes per picture    min %.0f  mean %.1f  max %.0f\n", r.bytes.min, r.bytes.mean, r.bytes.max);
  typesAndGops(out, r);
  appendf(out, "  sectors per picture  min %.0f  mean %.2f  max %.0f   (sectors its bytes touch)\n", r.spanSectors.min,
          r.spanSectors.mean, r.spanSectors.max);
  appendf(out, "  sectors per frame    min %.0f  mean %.2f  max %.0f   (read to advance one frame, all streams)\n",
          r.stepSectors.min, r.stepSectors.mean, r.stepSectors.max);
  appendf(out, "  worst run            %u sectors for %u frames from frame %u (%.0f sectors/s at %.3g%s frames/s)\n",
          r.runSectors, r.runFrames, r.runStart, r.runSectors * fps / r.runFrames, fps, fpsGuessed ? " (guessed)" : "");
  appendf(out, "  read rate over time  (%u frames per row, Mbit/s of game time)\n", r.bucketFrames);
  double peak = 0;
  for (double b : r.bitsPerSecond) peak = std::max(peak, b);
  for (std::size_t i = 0; i < r.bitsPerSecond.size(); ++i) {
    const int bar = peak > 0 ? static_cast<int>(std::lround(40 * r.bitsPerSecond[i] / peak)) : 0;
    appendf(out, "    frames %5zu+ %9.3f |%.*s\n", i * r.bucketFrames, r.bitsPerSecond[i] / 1e6, bar,
            "########################################");
  }
}

void scanText(std::string& out, const StreamInfo& info) {
  const StreamScan& scan = info.scan;
  appendf(out, "%s: %llu bytes, %u sectors\n", info.shown.c_str(), static_cast<unsigned long long>(scan.fileBytes),
          scan.sectors);
  appendf(out, "packs: %s\n",
          scan.every2048 ? "every pack is 2048 bytes and well formed"
                         : "NOT every pack is a well-formed 2048-byte pack (see errors)");
  appendf(out, "mux rate: %u x 50 B/s = %.2f Mbit/s\n", scan.muxRate, scan.muxRate * 400.0 / 1e6);
  const DemuxStats& st = scan.stats;
  appendf(out, "system headers %llu, padding %llu bytes, skipped packets %llu\n",
          static_cast<unsigned long long>(st.systemHeaders), static_cast<unsigned long long>(st.paddingBytes),
          static_cast<unsigned long long>(st.skippedPackets));
  descriptorText(out, info);
  for (const StreamReport& r : info.reports) reportText(out, r, info.fps, info.fpsGuessed);
  appendf(out, "\nerrors: %zu\n", scan.errors.size());
  for (std::size_t i = 0; i < scan.errors.size() && i < 20; ++i)
    appendf(out, "  %s\n", scan.errors[i].describe().c_str());
  if (scan.errors.size() > 20) appendf(out, "  ... %zu more\n", scan.errors.size() - 20);
}

// A few lines from the authoring record; --json shows all of it.
void authoringText(std::string& out, const std::optional<nlohmann::ordered_json>& r) {
  if (!r) {
    appendf(out, "\nauthoring: none recorded (made by another tool, or before streams carried a record)\n");
    return;
  }
  const auto text = [&](const nlohmann::ordered_json& j, const char* key) {
    return j.contains(key) ? (j[key].is_string() ? j[key].get<std::string>() : j[key].dump()) : std::string("?");
  };
  appendf(out, "\nauthoring: %s by vbim %s (vbim info --json shows every setting)\n", text(*r, "source").c_str(),
          text(*r, "vbim_version").c_str());
  if (r->contains("terrain")) {
    const auto& t = (*r)["terrain"];
    appendf(out, "  terrain %s, %sx%s texels of %s m\n", text(t, "heightfield").c_str(), text(t, "width").c_str(),
            text(t, "height").c_str(), text(t, "cell_size_m").c_str());
  }
  if (r->contains("day")) {
    const auto& d = (*r)["day"];
    appendf(out, "  day %s h to %s h, %s frames per variant", text(d, "start_hour").c_str(),
            text(d, "end_hour").c_str(), text(d, "frames").c_str());
    if (d.contains("frame_hours") && d["frame_hours"].size() > 1) {
      appendf(out, " (frame 1 at %.2f h, last at %.2f h)", d["frame_hours"][1].get<double>(),
              d["frame_hours"].back().get<double>());
    }
    appendf(out, "\n");
  }
  if (!r->contains("terrain") && r->contains("frames") && r->contains("stream")) {
    // A stream made from image files or the synthetic generator: no terrain or day is recorded.
    const auto& f = (*r)["frames"];
    appendf(out, "  frames: lightmap %s, sky %s; %s per variant, one every %s s of game time\n",
            text(f, "lightmap").c_str(), text(f, "sky").c_str(), text((*r)["stream"], "frames_per_variant").c_str(),
            text((*r)["stream"], "frame_period_s").c_str());
  }
  if (!r->contains("variants")) return;
  for (const auto& v : (*r)["variants"]) {
    if (!v.contains("lighting")) {
      appendf(out, "  variant '%s': %s\n", text(v, "name").c_str(), v.dump().c_str());
      continue;
    }
    const auto& l = v["lighting"];
    appendf(out, "  variant '%s': latitude %s deg, day %s of the year, turbidity %s, sun %s klux\n",
            text(v, "name").c_str(), text(l, "lighting.latitude_deg").c_str(), text(l, "lighting.day_of_year").c_str(),
            text(l, "lighting.turbidity").c_str(), text(l, "lighting.sun_klux").c_str());
  }
}

// For a file that is MPEG video `vbim decode` reads, but no program stream in 2048-byte packs (the
// sector layout `vbim info` describes): what it is and how to see it here. Empty for anything else.
std::string otherMpegHint(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::array<char, 5> b{};
  if (!f.read(b.data(), b.size())) return {};
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(b[i]); };
  if (byte(0) != 0 || byte(1) != 0 || byte(2) != 1) return {};
  const std::string remux =
      "; `vbim decode` reads it as it is, and `vbim info` once it is remuxed into 2048-byte "
      "packs (`ffmpeg -i IN -c copy -f vob OUT.vob`)";
  if (byte(3) == 0xB3) return " (it is an MPEG video elementary stream)" + remux;
  // ISO/IEC 11172-1 2.4.3.2: an MPEG-1 pack header's fifth byte starts with the bits '0010'.
  if (byte(3) == 0xBA && (byte(4) >> 4) == 0x2)
    return " (it is an MPEG-1 system stream, as `ffmpeg -f mpeg` writes)" + remux;
  return {};
}

}  // namespace

StreamInfo inspectStream(const std::string& path, const std::string& file, bool perPicture) {
  StreamInfo info;
  info.path = path;
  try {
    if (isIsoImage(path) || !file.empty()) {
      const StreamDisc disc = openStreamDisc(path, file);
      info.onImage = disc.file;
      info.scan = scanStream(readDiscFile(*disc.disc, disc.file));
    } else {
      info.scan = scanStreamFile(path);
    }
  } catch (const std::exception& e) {  // a scan's own checks throw std::exceptions too: bad input
    throw Error(e.what());
  }
  // How the stream was made, when it says (a record after its video sectors).
  if (info.scan.descriptor) {
    try {
      const StreamDisc disc = openStreamDisc(path, file);
      if (const auto text = readAuthoringRecord(*disc.disc, disc.file)) {
        info.record = nlohmann::ordered_json::parse(*text);
      }
    } catch (const std::exception&) {
      // Not whole sectors or not JSON: the defects are reported; no record shown.
    }
  }
  const std::optional<iop::DiscFile>& on = info.onImage;
  info.shown = on ? path + " " + on->path + " (LBA " + std::to_string(on->lba) + ")" : path;
  const StreamScan& scan = info.scan;
  if (scan.pictures.empty() && scan.stats.badSectors == scan.stats.sectors) {
    throw Error(info.shown + ": not an MPEG-2 program stream with 2048-byte packs: " +
                (scan.errors.empty() ? std::string("empty file") : scan.errors.front().describe()) +
                (on ? std::string() : otherMpegHint(path)));
  }
  info.fpsGuessed = !scan.descriptor;
  info.fps = info.fpsGuessed ? 25.0 : scan.descriptor->gameFps.value();
  std::size_t frames = 0;
  for (const PictureRecord& p : scan.pictures) frames += p.streamId == kLightmapStream;
  const auto perRow = static_cast<std::uint32_t>((frames + kTextBuckets - 1) / kTextBuckets);
  info.reports = summarise(scan, info.fps, perPicture ? 1 : std::max<std::uint32_t>(1, perRow));
  return info;
}

std::string infoText(const StreamInfo& info) {
  std::string out;
  scanText(out, info);
  authoringText(out, info.record);
  return out;
}

}  // namespace vbim::streams
