#include "streams/disc/iso_disc.hpp"

#include <cdio/ds.h>
#include <cdio/iso9660.h>

#include <filesystem>
#include <fstream>
#include <system_error>

namespace vbim::streams {

namespace {
iso9660_t* handle(void* p) {
  return static_cast<iso9660_t*>(p);
}

// A recorded name as sceCdSearchFile writes it: upper case, with a version (";1" when none).
std::string searchName(std::string_view recorded) {
  std::string r(recorded);
  if (r.find(';') == std::string::npos) r += ";1";
  for (char& c : r) c = static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
  return r;
}

void listDirectory(iso9660_t* iso, const std::string& dir, const std::string& shown, int depth,
                   std::vector<iop::DiscFile>& out) {
  CdioList_t* entries = iso9660_ifs_readdir(iso, dir.c_str());
  if (entries == nullptr) return;
  struct Entry {
    std::string name;
    bool directory;
    std::int64_t lba, bytes;
  };
  std::vector<Entry> found;
  for (CdioListNode_t* n = _cdio_list_begin(entries); n != nullptr; n = _cdio_list_node_next(n)) {
    const auto* st = static_cast<const iso9660_stat_t*>(_cdio_list_node_data(n));
    const std::string name = st->filename;
    if (name == "." || name == ".." || name.empty() || name[0] == '\0' || name[0] == '\1') continue;
    found.push_back({name, st->type == iso9660_stat_s::_STAT_DIR, static_cast<std::int64_t>(st->lsn),
                     static_cast<std::int64_t>(st->size)});
  }
  iso9660_filelist_free(entries);
  for (const Entry& e : found) {
    if (e.directory) {
      // ECMA-119 6.8.2.1 allows 8 directory levels; a deeper tree is damaged or looping.
      if (depth < 8) listDirectory(iso, dir + e.name + "/", shown + e.name + "\\", depth + 1, out);
    } else {
      out.push_back({shown + searchName(e.name), e.lba, e.bytes});
    }
  }
}
}  // namespace

std::string IsoDisc::normalisePath(std::string_view path) {
  std::string r;
  for (char c : path) {
    if (c == ';') break;  // version suffix
    if (c == '\\') c = '/';
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    r.push_back(c);
  }
  if (r.empty() || r.front() != '/') r.insert(r.begin(), '/');
  if (r.size() > 1 && r.back() == '.') r.pop_back();  // "FILE." (no extension) as ISO names it
  return r;
}

IsoDisc::IsoDisc(std::string path) : path_(std::move(path)) {
  std::error_code ec;
  if (!std::filesystem::exists(path_, ec)) throw iop::DiscError(path_ + ": no such disc image");
  if (std::filesystem::is_directory(path_, ec)) throw iop::DiscError(path_ + ": is a directory, expected an ISO image");
  const auto bytes = std::filesystem::file_size(path_, ec);
  if (ec) throw iop::DiscError(path_ + ": cannot read its size: " + ec.message());
  {
    std::ifstream probe(path_, std::ios::binary);
    if (!probe) throw iop::DiscError(path_ + ": cannot open for reading");
  }
  // The primary volume descriptor lives at LBA 16 (ECMA-119 8.4): an image must reach past it.
  constexpr std::uint64_t kPvdEnd = 17 * iop::kSectorBytes;
  if (bytes < kPvdEnd) {
    throw iop::DiscError(path_ + ": " + std::to_string(bytes) + " bytes is too short for ISO 9660: the primary " +
                         "volume descriptor is at byte offset 32768 (LBA 16)");
  }
  iso_ = iso9660_open(path_.c_str());
  if (iso_ == nullptr) throw iop::DiscError(path_ + ": cannot open as an ISO 9660 image");
  iso9660_pvd_t pvd;
  if (!iso9660_ifs_read_pvd(handle(iso_), &pvd)) {
    iso9660_close(handle(iso_));
    iso_ = nullptr;
    throw iop::DiscError(path_ + ": no ISO 9660 primary volume descriptor at LBA 16 (byte offset 32768)");
  }
  sectors_ = iso9660_get_pvd_space_size(&pvd);
  const std::uint64_t need = static_cast<std::uint64_t>(sectors_) * iop::kSectorBytes;
  if (sectors_ <= 0 || bytes < need) {
    iso9660_close(handle(iso_));
    iso_ = nullptr;
    throw iop::DiscError(path_ + ": truncated: the volume holds " + std::to_string(sectors_) + " sectors (" +
                         std::to_string(need) + " bytes) but the image has " + std::to_string(bytes) +
                         " bytes; the first missing sector is LBA " + std::to_string(bytes / iop::kSectorBytes));
  }
}

IsoDisc::~IsoDisc() {
  if (iso_ != nullptr) iso9660_close(handle(iso_));
}

iop::SectorReadResult IsoDisc::read(std::int64_t lba, iop::SectorSpan out) {
  if (lba < 0 || lba >= sectors_) {
    return {false, path_ + ": LBA " + std::to_string(lba) + " is outside the volume (0.." +
                       std::to_string(sectors_ - 1) + ")"};
  }
  const long n = iso9660_iso_seek_read(handle(iso_), out.data(), static_cast<lsn_t>(lba), 1);
  if (n != static_cast<long>(iop::kSectorBytes)) {
    return {false, path_ + ": read of LBA " + std::to_string(lba) + " (byte offset " +
                       std::to_string(lba * static_cast<std::int64_t>(iop::kSectorBytes)) + ") failed"};
  }
  return {};
}

std::vector<iop::DiscFile> IsoDisc::files() const {
  std::vector<iop::DiscFile> out;
  listDirectory(handle(iso_), "/", "\\", 0, out);
  return out;
}

std::optional<iop::DiscFile> IsoDisc::find(std::string_view path) const {
  // sceCdSearchFile names are upper case with a version ("\\VIDEO\\DAY.PSS;1"); mastering tools
  // differ on whether they record the version, so try the name as recorded both ways.
  const std::string lower = normalisePath(path);
  std::string upper = lower;
  for (char& c : upper) c = static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
  iso9660_stat_t* st = nullptr;
  for (const std::string& key : {upper, upper + ";1", lower}) {
    st = iso9660_ifs_stat_translate(handle(iso_), key.c_str());
    if (st == nullptr) st = iso9660_ifs_stat(handle(iso_), key.c_str());
    if (st != nullptr) break;
  }
  if (st == nullptr) return std::nullopt;
  iop::DiscFile f;
  f.path = std::string(path);
  f.lba = st->lsn;
  f.bytes = st->size;
  const bool isFile = st->type == iso9660_stat_s::_STAT_FILE;
  iso9660_stat_free(st);
  if (!isFile) return std::nullopt;
  if (f.lba + f.sectors() > sectors_) {
    throw iop::DiscError(path_ + ": file '" + std::string(path) + "' at LBA " + std::to_string(f.lba) + " runs past " +
                         "the end of the volume (" + std::to_string(sectors_) + " sectors): damaged image");
  }
  return f;
}

}  // namespace vbim::streams
