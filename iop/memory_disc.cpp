#include "iop/memory_disc.hpp"

#include <algorithm>
#include <cstring>

namespace vbim::iop {

MemoryDisc::MemoryDisc(std::int64_t sectors, std::string name) : sectors_(sectors), name_(std::move(name)) {
  if (sectors <= 0) throw DiscError(name_ + ": a disc needs at least one sector");
}

std::uint8_t MemoryDisc::patternByte(std::int64_t lba, std::size_t i) {
  if (i < 8) return static_cast<std::uint8_t>(static_cast<std::uint64_t>(lba) >> (8 * i));
  return static_cast<std::uint8_t>((static_cast<std::uint64_t>(lba) + i) & 0xFF);
}

void MemoryDisc::addFile(std::string path, std::int64_t lba, std::vector<std::uint8_t> bytes) {
  DiscFile f{std::move(path), lba, static_cast<std::int64_t>(bytes.size())};
  if (lba < 0 || lba + f.sectors() > sectors_) {
    throw DiscError(name_ + ": file '" + f.path + "' at LBA " + std::to_string(lba) + " does not fit on the disc");
  }
  for (const auto& [start, p] : files_) {
    if (lba < start + p.file.sectors() && start < lba + f.sectors()) {
      throw DiscError(name_ + ": file '" + f.path + "' at LBA " + std::to_string(lba) + " overlaps '" + p.file.path +
                      "'");
    }
  }
  files_[lba] = Placed{std::move(f), std::move(bytes)};
}

void MemoryDisc::addPatternFile(std::string path, std::int64_t lba, std::int64_t sectors) {
  std::vector<std::uint8_t> none;
  addFile(std::move(path), lba, none);
  auto& p = files_[lba];
  p.file.bytes = sectors * static_cast<std::int64_t>(kSectorBytes);
  if (lba + sectors > sectors_) {
    files_.erase(lba);
    throw DiscError(name_ + ": pattern file at LBA " + std::to_string(lba) + " does not fit on the disc");
  }
}

SectorReadResult MemoryDisc::read(std::int64_t lba, SectorSpan out) {
  if (lba < 0 || lba >= sectors_) {
    return {false, name_ + ": LBA " + std::to_string(lba) + " is outside the disc"};
  }
  std::memset(out.data(), 0, out.size());
  auto it = files_.upper_bound(lba);
  if (it == files_.begin()) return {};
  --it;
  const Placed& p = it->second;
  const std::int64_t rel = lba - p.file.lba;
  if (rel >= p.file.sectors()) return {};
  if (p.bytes.empty()) {
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = patternByte(lba, i);
    return {};
  }
  const auto off = static_cast<std::size_t>(rel) * kSectorBytes;
  const std::size_t n = std::min(kSectorBytes, p.bytes.size() - off);
  std::memcpy(out.data(), p.bytes.data() + off, n);
  return {};
}

std::optional<DiscFile> MemoryDisc::find(std::string_view path) const {
  auto norm = [](std::string_view s) {
    std::string r;
    for (char c : s) {
      if (c == ';') break;
      if (c == '\\') c = '/';
      if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
      r.push_back(c);
    }
    while (!r.empty() && r.front() == '/') r.erase(r.begin());
    return r;
  };
  const std::string key = norm(path);
  for (const auto& [start, p] : files_) {
    if (norm(p.file.path) == key) return p.file;
  }
  return std::nullopt;
}

}  // namespace vbim::iop
