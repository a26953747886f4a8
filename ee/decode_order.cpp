#include "ee/decode_order.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace vbim::ee {

DecodeOrder::DecodeOrder(const streams::Descriptor& d, int s) : frames_(d.framesPerVariant) {
  const std::vector<streams::IndexEntry>& index = d.index[static_cast<std::size_t>(s)];
  const std::size_t n = index.size();
  types_.resize(n);
  gopStart_.resize(n);
  rank_.assign(n, 0);
  byRank_.assign(n, 0);
  nextInFile_.assign(n, -1);
  for (std::size_t g = 0; g < n; ++g) {
    types_[g] = index[g].type;
    gopStart_[g] = index[g].gopStart;
    if (types_[g] != streams::PictureType::I) intraOnly_ = false;
  }
  const auto frames = static_cast<std::size_t>(frames_);
  for (std::size_t v = 0; frames > 0 && v < n / frames; ++v) {
    std::int64_t previousReference = -1;
    for (std::size_t f = 0; f < frames; ++f) {
      const std::size_t g = v * frames + f;
      const auto fi = static_cast<std::int64_t>(f);
      if (types_[g] == streams::PictureType::B) {
        rank_[g] = fi + 1;
      } else {
        rank_[g] = previousReference + 1;
        previousReference = fi;
      }
    }
    // Every variant ends on a reference (Descriptor::validate refuses one that ends on a B
    // picture), so the ranks are a permutation of 0..F-1.
    for (std::size_t f = 0; f < frames; ++f) {
      const std::size_t g = v * frames + f;
      if (rank_[g] < frames_) byRank_[v * frames + static_cast<std::size_t>(rank_[g])] = static_cast<std::int64_t>(f);
    }
  }
  // File order: by the sector and offset of each picture's first byte.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::tie(index[a].sector, index[a].offset) < std::tie(index[b].sector, index[b].offset);
  });
  for (std::size_t i = 0; i + 1 < n; ++i) nextInFile_[order[i]] = static_cast<std::int64_t>(order[i + 1]);
}

std::int64_t DecodeOrder::rank(int v, std::int64_t f, std::int64_t runStart) const {
  if (f == runStart) return runStart;
  return rank_[static_cast<std::size_t>(v * frames_ + f)];
}

std::int64_t DecodeOrder::frameAtRank(int v, std::int64_t r, std::int64_t runStart) const {
  if (r == runStart) return runStart;
  return byRank_[static_cast<std::size_t>(v * frames_ + r)];
}

std::int64_t DecodeOrder::resumeFrame(int v, std::int64_t f) const {
  while (f > 0 && !gopStart_[static_cast<std::size_t>(v * frames_ + f)]) --f;
  return f;
}

}  // namespace vbim::ee
