#include "streams/stream_stats.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <stdexcept>

#include "streams/crc32.hpp"
#include "streams/format.hpp"

namespace vbim::streams {

namespace {

class Scanner {
 public:
  void feed(std::span<const std::uint8_t> sector, std::uint32_t lsn) {
    demux_.feed(sector, lsn);
    if (!scan_.muxRate && demux_.lastPack().muxRate) scan_.muxRate = demux_.lastPack().muxRate;
    collect();
  }
  StreamScan finish(std::uint64_t bytes) {
    demux_.finish();
    collect();
    scan_.fileBytes = bytes;
    scan_.sectors = static_cast<std::uint32_t>(bytes / kSectorBytes);
    scan_.descriptor = demux_.descriptor();
    scan_.errors = demux_.errors();
    if (scan_.descriptor && bytes < std::uint64_t{scan_.descriptor->totalSectors} * kSectorBytes) {
      scan_.errors.push_back(
          StreamError{ErrorKind::ShortSector, bytes, static_cast<std::uint32_t>(bytes / kSectorBytes),
                      "stream ends after " + std::to_string(bytes) + " bytes; its descriptor says " +
                          std::to_string(scan_.descriptor->totalSectors) + " sectors (truncated stream)"});
    }
    scan_.stats = demux_.stats();
    scan_.every2048 = bytes % kSectorBytes == 0 && scan_.stats.badSectors == 0 && bytes > 0;
    return std::move(scan_);
  }

 private:
  void collect() {
    for (const Picture& p : demux_.pictures()) {
      scan_.pictures.push_back(PictureRecord{p.streamId, p.firstSector, p.lastSector, p.byteOffset,
                                             static_cast<std::uint32_t>(p.data.size()), crc32(p.data), p.pts, p.frame,
                                             p.damaged, readPictureHeader(p.data)});
    }
    demux_.pictures().clear();
  }
  Demuxer demux_;
  StreamScan scan_;
};

Summary summarise(const std::vector<double>& v) {
  Summary s;
  if (v.empty()) return s;
  s.min = *std::min_element(v.begin(), v.end());
  s.max = *std::max_element(v.begin(), v.end());
  double sum = 0;
  for (double x : v) sum += x;
  s.mean = sum / static_cast<double>(v.size());
  return s;
}

// Picture types and GOP shapes of one stream's pictures (in stream order).
void typesAndGops(const std::vector<const PictureRecord*>& pics, StreamReport& r) {
  std::array<std::vector<double>, 3> bytes;
  std::vector<double> gopLengths;
  std::vector<std::pair<std::uint16_t, char>> gop;  // temporal_reference, type of the GOP so far
  const auto closeGop = [&] {
    if (gop.empty()) return;
    std::stable_sort(gop.begin(), gop.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::string pattern;
    for (const auto& [tr, type] : gop) pattern += type;
    gopLengths.push_back(static_cast<double>(gop.size()));
    auto it = std::find_if(r.shapes.begin(), r.shapes.end(), [&](const GopShape& s) { return s.pattern == pattern; });
    if (it == r.shapes.end()) {
      r.shapes.push_back(GopShape{pattern, 1});
    } else {
      ++it->count;
    }
    gop.clear();
  };
  bool inGop = false;
  for (const PictureRecord* p : pics) {
    if (!p->header) {
      ++r.unknownType;
      continue;
    }
    const PictureHeaderInfo& h = *p->header;
    const auto t = static_cast<std::size_t>(h.type) - 1;
    bytes[t].push_back(p->bytes);
    if (h.gopHeader) {
      closeGop();
      inGop = true;
      ++r.gops;
      if (h.closedGop) ++r.closedGops;
    }
    if (inGop) gop.emplace_back(h.temporalReference, pictureTypeName(h.type)[0]);
  }
  closeGop();
  for (std::size_t t = 0; t < 3; ++t) r.types[t] = TypeReport{bytes[t].size(), summarise(bytes[t])};
  r.gopPictures = summarise(gopLengths);
}

}  // namespace

StreamScan scanStream(std::span<const std::uint8_t> bytes) {
  Scanner sc;
  std::uint32_t lsn = 0;
  for (std::size_t pos = 0; pos < bytes.size(); pos += kSectorBytes, ++lsn)
    sc.feed(bytes.subspan(pos, std::min(kSectorBytes, bytes.size() - pos)), lsn);
  return sc.finish(bytes.size());
}

StreamScan scanStreamFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open the stream file");
  Scanner sc;
  std::vector<std::uint8_t> sector(kSectorBytes);
  std::uint64_t total = 0;
  for (std::uint32_t lsn = 0;; ++lsn) {
    in.read(reinterpret_cast<char*>(sector.data()), static_cast<std::streamsize>(sector.size()));
    const auto got = static_cast<std::size_t>(in.gcount());
    if (got == 0) break;
    total += got;
    sc.feed(std::span<const std::uint8_t>(sector.data(), got), lsn);
    if (got < kSectorBytes) break;
  }
  if (in.bad()) throw std::runtime_error(path.string() + ": read error");
  return sc.finish(total);
}

std::vector<StreamReport> summarise(const StreamScan& scan, double gameFps, std::uint32_t bucketFrames) {
  std::map<std::uint8_t, std::vector<const PictureRecord*>> byStream;
  for (const PictureRecord& p : scan.pictures) byStream[p.streamId].push_back(&p);
  std::vector<StreamReport> out;
  for (const auto& [id, pics] : byStream) {
    StreamReport r;
    r.id = id;
    r.pictures = pics.size();
    std::vector<double> bytes, span, step;
    std::vector<std::uint32_t> start;  // sector where each picture starts, plus the end of the stream
    for (const PictureRecord* p : pics) {
      bytes.push_back(p->bytes);
      span.push_back(p->lastSector - p->firstSector + 1.0);
      start.push_back(p->firstSector);
    }
    start.push_back(scan.sectors);
    for (std::size_t k = 0; k + 1 < start.size(); ++k) step.push_back(start[k + 1] - double(start[k]));
    r.bytes = summarise(bytes);
    r.spanSectors = summarise(span);
    r.stepSectors = summarise(step);
    const std::size_t n = pics.size();
    r.runFrames = static_cast<std::uint32_t>(std::clamp<double>(std::round(gameFps), 1, std::max<double>(1, n)));
    for (std::size_t k = 0; k + r.runFrames <= n; ++k) {
      const std::uint32_t sectors = start[k + r.runFrames] - start[k];
      if (sectors > r.runSectors) {
        r.runSectors = sectors;
        r.runStart = static_cast<std::uint32_t>(k);
      }
    }
    r.bucketFrames = std::max<std::uint32_t>(1, bucketFrames);
    for (std::size_t k = 0; k < n; k += r.bucketFrames) {
      const std::size_t e = std::min(n, k + r.bucketFrames);
      const double seconds = static_cast<double>(e - k) / gameFps;
      r.bitsPerSecond.push_back((start[e] - start[k]) * double(kSectorBytes) * 8.0 / seconds);
    }
    typesAndGops(pics, r);
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace vbim::streams
