// vbim info: what a VBIM stream holds, read sector by sector with the model's reader.
#include <cmath>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/info_json.hpp"
#include "cli/option_checks.hpp"
#include "iop/error.hpp"
#include "streams/disc/stream_disc.hpp"
#include "streams/format.hpp"
#include "streams/stream_stats.hpp"

namespace vbim::cli {

namespace {

using namespace vbim::streams;

constexpr std::size_t kTextBuckets = 24;  // rows of the bitrate table in text output

// Bytes per picture type and the GOP structure (stream order, split at GOP headers).
void printTypesAndGops(const StreamReport& r) {
  for (std::size_t t = 0; t < r.types.size(); ++t) {
    const TypeReport& tr = r.types[t];
    if (tr.pictures == 0) continue;
    std::printf("  %s pictures %9zu  bytes min %.0f  mean %.1f  max %.0f  (mean %.0f bits)\n",
                pictureTypeName(static_cast<PictureType>(t + 1)), tr.pictures, tr.bytes.min, tr.bytes.mean,
                tr.bytes.max, tr.bytes.mean * 8);
  }
  if (r.unknownType) std::printf("  unreadable picture headers %zu\n", r.unknownType);
  if (r.gops == 0) return;
  std::printf("  GOPs %zu (%zu closed, %zu open), %.0f..%.0f pictures (mean %.2f)\n", r.gops, r.closedGops,
              r.gops - r.closedGops, r.gopPictures.min, r.gopPictures.max, r.gopPictures.mean);
  constexpr std::size_t kShown = 4;  // distinct shapes listed; --json lists them all
  for (std::size_t i = 0; i < r.shapes.size() && i < kShown; ++i) {
    const GopShape& g = r.shapes[i];
    const bool longShape = g.pattern.size() > 48;
    std::printf("    %s%s x %zu\n", g.pattern.substr(0, 48).c_str(), longShape ? "..." : "", g.count);
  }
  if (r.shapes.size() > kShown) std::printf("    ... %zu more shapes\n", r.shapes.size() - kShown);
}

void printText(const std::string& path, const StreamScan& scan, const std::vector<StreamReport>& reports, double fps,
               bool fpsGuessed) {
  std::printf("%s: %llu bytes, %u sectors\n", path.c_str(), static_cast<unsigned long long>(scan.fileBytes),
              scan.sectors);
  std::printf("packs: %s\n", scan.every2048 ? "every pack is 2048 bytes and well formed"
                                            : "NOT every pack is a well-formed 2048-byte pack (see errors)");
  std::printf("mux rate: %u x 50 B/s = %.2f Mbit/s\n", scan.muxRate, scan.muxRate * 400.0 / 1e6);
  const DemuxStats& st = scan.stats;
  std::printf("system headers %llu, padding %llu bytes, skipped packets %llu\n",
              static_cast<unsigned long long>(st.systemHeaders), static_cast<unsigned long long>(st.paddingBytes),
              static_cast<unsigned long long>(st.skippedPackets));
  if (scan.descriptor) {
    const Descriptor& d = *scan.descriptor;
    std::printf(
        "descriptor: version %u, %u sectors; game rate %u/%u frames/s; %u frames per variant; loop to frame %u\n",
        d.intraOnly() ? Descriptor::kVersionIntra : Descriptor::kVersion, d.descriptorSectors, d.gameFps.num,
        d.gameFps.den, d.framesPerVariant, d.loopFrame);
    std::printf("  container: first PTS %lld, %u ticks (90 kHz) per frame; %u sectors in all\n",
                static_cast<long long>(d.firstPts), d.ptsPerFrame, d.totalSectors);
    for (const StreamEntry& s : d.streams) {
      std::printf("  stream %s %s %ux%u\n", hexId(s.id).c_str(), s.role == StreamRole::Lightmap ? "lightmap" : "sky",
                  s.width, s.height);
    }
    for (const Variant& v : d.variants) {
      std::printf("  variant '%s': frames %u..%u, from sector %u\n", v.name.c_str(), v.firstFrame,
                  v.firstFrame + d.framesPerVariant - 1, v.firstSector);
    }
  } else {
    std::printf("descriptor: none (not a VBIM stream, or damaged); rates below assume %.3g frames/s\n", fps);
  }
  for (const StreamReport& r : reports) {
    std::printf("\nstream %s: %zu pictures\n", hexId(r.id).c_str(), r.pictures);
    std::printf("  bytes per picture    min %.0f  mean %.1f  max %.0f\n", r.bytes.min, r.bytes.mean, r.bytes.max);
    printTypesAndGops(r);
    std::printf("  sectors per picture  min %.0f  mean %.2f  max %.0f   (sectors its bytes touch)\n", r.spanSectors.min,
                r.spanSectors.mean, r.spanSectors.max);
    std::printf("  sectors per frame    min %.0f  mean %.2f  max %.0f   (read to advance one frame, all streams)\n",
                r.stepSectors.min, r.stepSectors.mean, r.stepSectors.max);
    std::printf("  worst run            %u sectors for %u frames from frame %u (%.0f sectors/s at %.3g%s frames/s)\n",
                r.runSectors, r.runFrames, r.runStart, r.runSectors * fps / r.runFrames, fps,
                fpsGuessed ? " (guessed)" : "");
    std::printf("  read rate over time  (%u frames per row, Mbit/s of game time)\n", r.bucketFrames);
    double peak = 0;
    for (double b : r.bitsPerSecond) peak = std::max(peak, b);
    for (std::size_t i = 0; i < r.bitsPerSecond.size(); ++i) {
      const int bar = peak > 0 ? static_cast<int>(std::lround(40 * r.bitsPerSecond[i] / peak)) : 0;
      std::printf("    frames %5zu+ %9.3f |%.*s\n", i * r.bucketFrames, r.bitsPerSecond[i] / 1e6, bar,
                  "########################################");
    }
  }
  std::printf("\nerrors: %zu\n", scan.errors.size());
  for (std::size_t i = 0; i < scan.errors.size() && i < 20; ++i)
    std::printf("  %s\n", scan.errors[i].describe().c_str());
  if (scan.errors.size() > 20) std::printf("  ... %zu more\n", scan.errors.size() - 20);
}

// A few lines from the authoring record; --json shows all of it.
void printAuthoring(const std::optional<nlohmann::ordered_json>& r) {
  if (!r) {
    std::printf("\nauthoring: none recorded (made by another tool, or before streams carried a record)\n");
    return;
  }
  const auto text = [&](const nlohmann::ordered_json& j, const char* key) {
    return j.contains(key) ? (j[key].is_string() ? j[key].get<std::string>() : j[key].dump()) : std::string("?");
  };
  std::printf("\nauthoring: %s by vbim %s (vbim info --json shows every setting)\n", text(*r, "source").c_str(),
              text(*r, "vbim_version").c_str());
  if (r->contains("terrain")) {
    const auto& t = (*r)["terrain"];
    std::printf("  terrain %s, %sx%s texels of %s m\n", text(t, "heightfield").c_str(), text(t, "width").c_str(),
                text(t, "height").c_str(), text(t, "cell_size_m").c_str());
  }
  if (r->contains("day")) {
    const auto& d = (*r)["day"];
    std::printf("  day %s h to %s h, %s frames per variant", text(d, "start_hour").c_str(), text(d, "end_hour").c_str(),
                text(d, "frames").c_str());
    if (d.contains("frame_hours") && d["frame_hours"].size() > 1) {
      std::printf(" (frame 1 at %.2f h, last at %.2f h)", d["frame_hours"][1].get<double>(),
                  d["frame_hours"].back().get<double>());
    }
    std::printf("\n");
  }
  if (!r->contains("terrain") && r->contains("frames") && r->contains("stream")) {
    // A stream made from image files or the synthetic generator: no terrain or day is recorded.
    const auto& f = (*r)["frames"];
    std::printf("  frames: lightmap %s, sky %s; %s per variant, one every %s s of game time\n",
                text(f, "lightmap").c_str(), text(f, "sky").c_str(), text((*r)["stream"], "frames_per_variant").c_str(),
                text((*r)["stream"], "frame_period_s").c_str());
  }
  if (r->contains("variants")) {
    for (const auto& v : (*r)["variants"]) {
      if (!v.contains("lighting")) {
        std::printf("  variant '%s': %s\n", text(v, "name").c_str(), v.dump().c_str());
        continue;
      }
      const auto& l = v["lighting"];
      std::printf("  variant '%s': latitude %s deg, day %s of the year, turbidity %s, sun %s klux\n",
                  text(v, "name").c_str(), text(l, "lighting.latitude_deg").c_str(),
                  text(l, "lighting.day_of_year").c_str(), text(l, "lighting.turbidity").c_str(),
                  text(l, "lighting.sun_klux").c_str());
    }
  }
}

}  // namespace

void addInfo(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("info", "Inspect a VBIM stream: streams, frames, sectors per frame, bitrate, descriptor");
  auto path = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  auto file = std::make_shared<std::string>();
  cmd->add_option("STREAM", *path, "Stream file, or an ISO 9660 disc image")->required()->check(inputFile());
  cmd->add_option("--file", *file,
                  "The stream on a disc image, e.g. '\\DATA\\DAY.VBI;1' (default: its only VBIM stream)");
  cmd->add_flag("--json", *json, "Machine-readable output");
  cmd->footer(
      "Examples:\n"
      "  vbim info streams/samples/day_clear.vbim\n"
      "  vbim info streams/samples/day_clear.vbim --json\n");
  cmd->callback([path, json, file] {
    StreamScan scan;
    std::optional<iop::DiscFile> onImage;  // where the stream lies on a disc image
    try {
      if (streams::isIsoImage(*path) || !file->empty()) {
        streams::StreamDisc disc = streams::openStreamDisc(*path, *file);
        onImage = disc.file;
        scan = scanStream(streams::readDiscFile(*disc.disc, disc.file));
      } else {
        scan = scanStreamFile(*path);
      }
    } catch (const std::exception& e) {  // a scan's own checks throw std::exceptions too: bad input
      throw Exit(2, e.what());
    }
    // How the stream was made, when it says (a record after its video sectors).
    std::optional<nlohmann::ordered_json> record;
    if (scan.descriptor) {
      try {
        const streams::StreamDisc disc = streams::openStreamDisc(*path, *file);
        if (const auto text = streams::readAuthoringRecord(*disc.disc, disc.file)) {
          record = nlohmann::ordered_json::parse(*text);
        }
      } catch (const std::exception&) {
        // Not whole sectors or not JSON: the defects are reported below; no record shown.
      }
    }
    const std::string shown =
        onImage ? *path + " " + onImage->path + " (LBA " + std::to_string(onImage->lba) + ")" : *path;
    if (scan.pictures.empty() && scan.stats.badSectors == scan.stats.sectors) {
      throw Exit(2, shown + ": not an MPEG-2 program stream with 2048-byte packs: " +
                        (scan.errors.empty() ? std::string("empty file") : scan.errors.front().describe()));
    }
    const bool guessed = !scan.descriptor;
    const double fps = guessed ? 25.0 : scan.descriptor->gameFps.value();
    std::size_t frames = 0;
    for (const PictureRecord& p : scan.pictures) frames += p.streamId == kLightmapStream;
    const auto perRow = static_cast<std::uint32_t>((frames + kTextBuckets - 1) / kTextBuckets);
    const auto reports = summarise(scan, fps, *json ? 1 : std::max<std::uint32_t>(1, perRow));
    if (*json) {
      const nlohmann::json j = infoJson(*path, onImage, scan, reports, record);
      // Text read from a damaged stream (descriptor names, the authoring record) may not be UTF-8:
      // such bytes are written as U+FFFD, so the document is always valid JSON, and said so.
      std::string text;
      try {
        text = j.dump(2);
      } catch (const nlohmann::json::type_error&) {
        text = j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
        std::cerr << "vbim info: warning: " << shown
                  << ": text in the stream is not UTF-8; its bytes are replaced by U+FFFD in the JSON\n";
      }
      std::cout << text << "\n";
    } else {
      printText(shown, scan, reports, fps, guessed);
      printAuthoring(record);
    }
    if (!scan.errors.empty()) {
      throw Exit(2, shown + ": " + std::to_string(scan.errors.size()) +
                        " defects found (first: " + scan.errors.front().describe() + ")");
    }
  });
}

}  // namespace vbim::cli
