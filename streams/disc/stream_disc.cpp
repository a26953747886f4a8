#include "streams/disc/stream_disc.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <fstream>

#include "iop/file_disc.hpp"
#include "streams/descriptor_probe.hpp"
#include "streams/disc/iso_disc.hpp"
#include "streams/record_packs.hpp"

namespace vbim::streams {

namespace {

// "\DATA\DAY.VBI;1 (LBA 300, 186368 bytes)" for the lists in messages.
std::string listed(const std::vector<iop::DiscFile>& files) {
  std::string r;
  for (const iop::DiscFile& f : files) {
    r += "\n  " + f.path + " (LBA " + std::to_string(f.lba) + ", " + std::to_string(f.bytes) + " bytes)";
  }
  return r;
}

// The stream's descriptor when `file` is a VBIM stream (the reader's check, on the disc's sectors).
std::optional<Descriptor> descriptorOf(iop::SectorSource& disc, const iop::DiscFile& file) {
  const auto read = [&](std::int64_t s, std::span<std::uint8_t, kSectorBytes> out) {
    const iop::SectorReadResult r = disc.read(file.lba + s, iop::SectorSpan(out));
    return r.ok ? std::string() : r.error;
  };
  try {
    return probeDescriptor(file.sectors(), read, disc.describe() + ", file '" + file.path + "'").descriptor;
  } catch (const StreamProbeError&) {
    return std::nullopt;
  }
}

bool isVbimStream(iop::SectorSource& disc, const iop::DiscFile& file) {
  return file.bytes >= static_cast<std::int64_t>(iop::kSectorBytes) && descriptorOf(disc, file).has_value();
}

StreamDisc onImage(const std::string& path, const std::string& name) {
  auto iso = std::make_shared<IsoDisc>(path);
  const std::vector<iop::DiscFile> files = iso->files();
  std::vector<iop::DiscFile> streams;
  for (const iop::DiscFile& f : files) {
    if (isVbimStream(*iso, f)) streams.push_back(f);
  }
  StreamDisc r;
  r.image = true;
  if (!name.empty()) {
    auto f = iso->find(name);
    if (!f) {
      throw iop::DiscError(
          path + ": no file '" + name + "' on the disc image; " +
          (streams.empty() ? "its files are:" + listed(files) : "its VBIM streams are:" + listed(streams)));
    }
    r.file = *f;
    r.file.path = name;
  } else if (streams.size() == 1) {
    r.file = streams.front();
  } else if (streams.empty()) {
    throw iop::DiscError(path + ": no VBIM stream on the disc image" +
                         (files.empty() ? std::string(" (it holds no files)") : "; its files are:" + listed(files)));
  } else {
    throw iop::DiscError(path + ": " + std::to_string(streams.size()) +
                         " VBIM streams on the disc image; pick one with --file, e.g. --file '" + streams.front().path +
                         "':" + listed(streams));
  }
  r.disc = std::move(iso);
  return r;
}

}  // namespace

bool isIsoImage(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  // Volume descriptor type byte, then the standard identifier (ECMA-119 8.1.1, 8.1.2).
  std::array<char, 6> id{};
  in.seekg(16 * static_cast<std::streamoff>(iop::kSectorBytes));
  in.read(id.data(), id.size());
  return in.gcount() == static_cast<std::streamsize>(id.size()) && std::memcmp(id.data() + 1, "CD001", 5) == 0;
}

StreamDisc openStreamDisc(const std::string& path, const std::string& file) {
  std::error_code ec;
  if (!std::filesystem::is_directory(path, ec) && isIsoImage(path)) return onImage(path, file);
  if (!file.empty()) {
    throw iop::DiscError(path + ": --file '" + file + "' picks a file on an ISO 9660 disc image, but this is a " +
                         "bare stream file (no volume descriptor at LBA 16)");
  }
  // A bare stream file at kBareFileLba, with zero sectors after it for the drive's read-ahead.
  auto bare = iop::bareFileDisc(path);
  StreamDisc r;
  r.file = bare->file();
  r.disc = std::move(bare);
  return r;
}

std::vector<std::uint8_t> readDiscFile(iop::SectorSource& disc, const iop::DiscFile& file) {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(file.sectors()) * iop::kSectorBytes);
  for (std::int64_t s = 0; s < file.sectors(); ++s) {
    const iop::SectorSpan out(bytes.data() + s * static_cast<std::int64_t>(iop::kSectorBytes), iop::kSectorBytes);
    const iop::SectorReadResult r = disc.read(file.lba + s, out);
    if (!r.ok) throw iop::DiscError(r.error);
  }
  bytes.resize(static_cast<std::size_t>(file.bytes));
  return bytes;
}

std::optional<std::string> readAuthoringRecord(iop::SectorSource& disc, const iop::DiscFile& file) {
  const std::optional<Descriptor> descriptor = descriptorOf(disc, file);
  if (!descriptor) return std::nullopt;
  const std::int64_t video = descriptor->totalSectors;
  // A record of a few thousand frames' hours and every lighting key fits in a handful of packs.
  constexpr std::int64_t kMaxRecordSectors = 256;
  iop::DiscFile tail = file;
  tail.lba = file.lba + video;
  tail.bytes = std::min(file.sectors() - video, kMaxRecordSectors) * static_cast<std::int64_t>(iop::kSectorBytes);
  if (tail.bytes <= 0) return std::nullopt;
  return findAuthoringRecord(readDiscFile(disc, tail));
}

}  // namespace vbim::streams
