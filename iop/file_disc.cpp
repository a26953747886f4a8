#include "iop/file_disc.hpp"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace vbim::iop {

namespace {

std::string baseName(const std::string& p) {
  return std::filesystem::path(p).filename().string();
}

std::string upper(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
  return r;
}

// "\\VIDEO\\DAY.PSS;1" -> "DAY.PSS": the last path component, upper case, no version.
std::string leafKey(std::string_view path) {
  const auto slash = path.find_last_of("/\\");
  std::string_view leaf = slash == std::string_view::npos ? path : path.substr(slash + 1);
  const auto semi = leaf.find(';');
  if (semi != std::string_view::npos) leaf = leaf.substr(0, semi);
  return upper(leaf);
}

}  // namespace

FileDisc::FileDisc(std::string path, std::int64_t startLba, std::int64_t discSectors) : path_(std::move(path)) {
  std::error_code ec;
  if (!std::filesystem::exists(path_, ec)) throw DiscError(path_ + ": no such stream file");
  if (std::filesystem::is_directory(path_, ec)) throw DiscError(path_ + ": is a directory, expected a stream file");
  const auto size = std::filesystem::file_size(path_, ec);
  if (ec) throw DiscError(path_ + ": cannot read its size: " + ec.message());
  if (!in_.open(path_)) throw DiscError(path_ + ": cannot open for reading");
  if (size == 0) throw DiscError(path_ + ": is empty, expected at least one 2048-byte sector");
  if (size % kSectorBytes != 0) {
    const auto whole = size / kSectorBytes * kSectorBytes;
    throw DiscError(path_ + ": " + std::to_string(size) + " bytes is not a whole number of 2048-byte sectors; the " +
                    "last sector (byte offset " + std::to_string(whole) + ", LBA " +
                    std::to_string(startLba + static_cast<std::int64_t>(size / kSectorBytes)) +
                    ") is cut short: truncated stream?");
  }
  if (startLba < 0) throw DiscError(path_ + ": start LBA " + std::to_string(startLba) + " is negative");
  file_.path = baseName(path_);
  file_.lba = startLba;
  file_.bytes = static_cast<std::int64_t>(size);
  const std::int64_t end = startLba + file_.sectors();
  if (discSectors != 0 && discSectors < end) {
    throw DiscError(path_ + ": the file ends at LBA " + std::to_string(end) + ", beyond the disc's " +
                    std::to_string(discSectors) + " sectors");
  }
  discSectors_ = discSectors != 0 ? discSectors : end;
}

SectorReadResult FileDisc::read(std::int64_t lba, SectorSpan out) {
  if (lba < 0 || lba >= discSectors_) {
    return {false, describe() + ": LBA " + std::to_string(lba) + " is outside the disc (0.." +
                       std::to_string(discSectors_ - 1) + ")"};
  }
  if (lba < file_.lba || lba >= file_.lba + file_.sectors()) {
    std::memset(out.data(), 0, out.size());
    return {};
  }
  const auto offset = static_cast<std::streamoff>((lba - file_.lba) * static_cast<std::int64_t>(kSectorBytes));
  if (!in_.read(offset, out)) {
    return {false, path_ + ": read failed at byte offset " + std::to_string(offset) + " (LBA " + std::to_string(lba) +
                       "): the file changed or is unreadable"};
  }
  return {};
}

std::optional<DiscFile> FileDisc::find(std::string_view path) const {
  if (leafKey(path) != leafKey(file_.path)) return std::nullopt;
  return file_;
}

std::string FileDisc::describe() const {
  return path_ + " (bare stream at LBA " + std::to_string(file_.lba) + ")";
}

std::shared_ptr<FileDisc> bareFileDisc(const std::string& path) {
  const std::int64_t sectors = FileDisc(path, kBareFileLba).file().sectors();
  return std::make_shared<FileDisc>(path, kBareFileLba, kBareFileLba + sectors + kBareFilePadSectors);
}

}  // namespace vbim::iop
