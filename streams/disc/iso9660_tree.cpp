#include "streams/disc/iso9660_tree.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <utility>

namespace vbim::streams::iso9660 {

namespace {

// A recorded name as sceCdSearchFile writes it: upper case, with a version (";1" when none).
std::string searchName(std::string_view recorded) {
  std::string r(recorded);
  if (r.find(';') == std::string::npos) r += ";1";
  for (char& c : r) c = static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
  return r;
}

// Why a file cannot be streamed from one contiguous extent, or empty when it can.
std::string layoutProblem(const DirectoryRecord& r) {
  if (r.multiExtent) {
    return "is recorded in several extents (a multi-extent file, ECMA-119, 4th edition, section 9.1.6); "
           "a streamed file must be one contiguous extent";
  }
  if (r.interleaved) {
    return "is recorded interleaved (file unit size and interleave gap, ECMA-119, 4th edition, sections 9.1.7 "
           "and 9.1.8); a streamed file must be one contiguous extent";
  }
  return {};
}

// Directory extents already read, as [first, end) LBAs, to refuse an overlapping one.
class VisitedExtents {
 public:
  // False (and nothing recorded) when [first, end) overlaps an extent already visited.
  bool visit(std::int64_t first, std::int64_t end) {
    if (first >= end) return true;  // an empty directory holds nothing to revisit
    auto next = spans_.lower_bound(first);
    if (next != spans_.end() && next->first < end) return false;
    if (next != spans_.begin() && std::prev(next)->second > first) return false;
    spans_.emplace(first, end);
    return true;
  }

 private:
  std::map<std::int64_t, std::int64_t> spans_;
};

struct Lister {
  std::function<std::vector<DirectoryRecord>(const DirectoryRecord&, std::string_view)> read;
  std::int64_t volumeSectors;
  VisitedExtents visited;
  std::vector<iop::DiscFile> out;

  // Lists `dir` (at `level`, the root being 1), shown with the prefix `shown` ("\\DATA\\").
  void list(const DirectoryRecord& dir, const std::string& shown, int level) {
    const std::vector<DirectoryRecord> records = read(dir, shown);
    // The records of one multi-extent file are consecutive, under one name, each but the last
    // flagged (ECMA-119, 4th edition, section 9.1.6): `flagged` is the last record, when it was one.
    const DirectoryRecord* flagged = nullptr;
    for (const DirectoryRecord& r : records) {
      const bool part = flagged != nullptr && flagged->identifier == r.identifier;
      flagged = !r.directory && r.multiExtent ? &r : nullptr;
      if (r.directory) {
        if (level >= kMaxDirectoryLevels) continue;
        const std::string name = shown + r.identifier + "\\";
        if (const std::string why = extentProblem(r, volumeSectors); !why.empty()) {
          throw iop::DiscError("directory '" + name + "' " + why + ": damaged image");
        }
        if (!visited.visit(r.extent, r.extent + r.sectors())) continue;
        list(r, name, level + 1);
      } else if (!part && layoutProblem(r).empty()) {
        iop::DiscFile f{shown + searchName(r.identifier), r.extent, r.bytes};
        if (const std::string why = extentProblem(r, volumeSectors); !why.empty()) {
          throw iop::DiscError("file '" + f.path + "' " + why + ": damaged image");
        }
        out.push_back(std::move(f));
      }
    }
  }
};

// "/video/day.pss" -> {"video", "day.pss"} (empty components, as in "//", are skipped).
std::vector<std::string_view> components(std::string_view path) {
  std::vector<std::string_view> r;
  while (!path.empty()) {
    const std::size_t slash = path.find('/');
    const std::string_view part = path.substr(0, slash);
    if (!part.empty()) r.push_back(part);
    if (slash == std::string_view::npos) break;
    path.remove_prefix(slash + 1);
  }
  return r;
}

}  // namespace

DirectoryTree::DirectoryTree(SectorReader read, PrimaryVolume volume)
    : read_(std::move(read)), volume_(std::move(volume)) {}

std::vector<DirectoryRecord> DirectoryTree::readDirectory(const DirectoryRecord& dir, std::string_view name) const {
  // The extent must lie inside the volume before any of it is read; that also bounds its size.
  if (const std::string why = extentProblem(dir, volume_.sectors); !why.empty()) {
    throw iop::DiscError("directory '" + std::string(name) + "' " + why + ": damaged image");
  }
  std::vector<DirectoryRecord> records;
  std::array<std::uint8_t, iop::kSectorBytes> sector{};
  for (std::int64_t k = 0; k < dir.sectors(); ++k) {
    read_(dir.extent + k, sector);
    const auto used = static_cast<std::size_t>(
        std::min<std::int64_t>(dir.bytes - k * static_cast<std::int64_t>(iop::kSectorBytes), iop::kSectorBytes));
    // Records never cross a sector; a zero length byte ends this sector's records (ECMA-119, 4th
    // edition, section 6.8.1.1).
    for (std::size_t offset = 0; offset < used;) {
      auto r = parseRecord(sector, offset, used, dir.extent + k);
      if (!r) break;
      offset += r->length;
      if (!r->selfOrParent()) records.push_back(std::move(*r));
    }
  }
  return records;
}

std::vector<iop::DiscFile> DirectoryTree::files() const {
  Lister lister{
      [this](const DirectoryRecord& d, std::string_view n) { return readDirectory(d, n); }, volume_.sectors, {}, {}};
  lister.visited.visit(volume_.root.extent, volume_.root.extent + volume_.root.sectors());
  lister.list(volume_.root, "\\", 1);
  return std::move(lister.out);
}

std::optional<iop::DiscFile> DirectoryTree::find(std::string_view path, std::string_view shownPath) const {
  const std::vector<std::string_view> parts = components(path);
  if (parts.empty()) return std::nullopt;
  DirectoryRecord dir = volume_.root;
  std::string shown = "\\";
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    // The directory entered here is at level i + 2 (the root is 1); ECMA-119, 4th edition, section
    // 6.8.2.1 allows 8 levels.
    if (static_cast<int>(i) + 2 > kMaxDirectoryLevels) return std::nullopt;
    const std::vector<DirectoryRecord> records = readDirectory(dir, shown);
    const auto sub = std::find_if(records.begin(), records.end(), [&](const DirectoryRecord& r) {
      return r.directory && nameKey(r.identifier) == parts[i];
    });
    if (sub == records.end()) return std::nullopt;
    dir = *sub;
    shown += sub->identifier + "\\";
  }
  const std::vector<DirectoryRecord> records = readDirectory(dir, shown);
  const auto file = std::find_if(records.begin(), records.end(), [&](const DirectoryRecord& r) {
    return !r.directory && nameKey(r.identifier) == parts.back();
  });
  if (file == records.end()) return std::nullopt;
  const std::string name(shownPath);
  // The first record of a multi-extent file comes first and carries the flag (section 9.1.6).
  if (const std::string why = layoutProblem(*file); !why.empty()) {
    throw iop::DiscError("file '" + name + "' " + why);
  }
  if (const std::string why = extentProblem(*file, volume_.sectors); !why.empty()) {
    throw iop::DiscError("file '" + name + "' " + why + ": damaged image");
  }
  return iop::DiscFile{{}, file->extent, file->bytes};
}

}  // namespace vbim::streams::iso9660
