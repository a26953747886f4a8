#include "lighting/normal_palette.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vbim::lighting {

namespace {

constexpr std::size_t kSample = 65536;  // k-means subsample size
constexpr int kGrid = 64;               // buckets over (n_x, n_y) in [-1, 1]^2
constexpr int kHalfGrid = kGrid / 2;
constexpr double kCell = 2.0 / kGrid;

double dot(const Vec3& a, const Vec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// Exact nearest palette entry (largest dot = smallest chord). Entries are bucketed by (n_x, n_y);
// rings of buckets are searched outwards until the ring cannot hold anything closer: the distance
// in the (n_x, n_y) plane never exceeds the chord between two unit vectors.
class NearestSearch {
 public:
  explicit NearestSearch(const std::array<Vec3, kPaletteSize>& pal) : pal_(pal), start_(kGrid * kGrid + 1, 0) {
    std::vector<int> cellOf(kPaletteSize);
    for (int k = 0; k < kPaletteSize; ++k) {
      cellOf[k] = cell(pal[k].y) * kGrid + cell(pal[k].x);
      ++start_[cellOf[k] + 1];
    }
    for (int c = 0; c < kGrid * kGrid; ++c) start_[c + 1] += start_[c];
    entries_.resize(kPaletteSize);
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (int k = 0; k < kPaletteSize; ++k) entries_[fill[cellOf[k]]++] = k;  // ascending k per cell
  }

  int find(const Vec3& n) const {
    const int cx = cell(n.x), cy = cell(n.y);
    int best = -1;
    double bestDot = -2, bestChord = 4;
    for (int ring = 0; ring < kGrid; ++ring) {
      if (best >= 0 && (ring - 1) * kCell > bestChord) break;
      for (int y = cy - ring; y <= cy + ring; ++y) {
        if (y < 0 || y >= kGrid) continue;
        const bool edgeRow = y == cy - ring || y == cy + ring;
        for (int x = cx - ring; x <= cx + ring; x += edgeRow ? 1 : 2 * ring) {
          if (x >= 0 && x < kGrid) scan(y * kGrid + x, n, best, bestDot);
          if (ring == 0) break;
        }
      }
      if (best >= 0) bestChord = std::sqrt(std::max(0.0, 2.0 - 2.0 * bestDot));
    }
    return best;
  }

 private:
  static int cell(float v) { return std::clamp(static_cast<int>((v + 1.0f) * kHalfGrid), 0, kGrid - 1); }
  void scan(int c, const Vec3& n, int& best, double& bestDot) const {
    for (int e = start_[c]; e < start_[c + 1]; ++e) {
      const int k = entries_[e];
      const double d = dot(pal_[k], n);
      if (d > bestDot || (d == bestDot && k < best)) {  // ties to the lower index: order-independent
        bestDot = d;
        best = k;
      }
    }
  }
  const std::array<Vec3, kPaletteSize>& pal_;
  std::vector<int> start_, entries_;
};

}  // namespace

NormalPalette buildNormalPalette(const std::vector<Vec3>& normals, int iterations) {
  NormalPalette pal;
  double minZ = 1.0;
  for (const Vec3& n : normals) minZ = std::min(minZ, static_cast<double>(n.z));
  // Fibonacci points on the cap z >= capZ, evenly spread by area.
  const double capZ = std::max(0.0, std::min(minZ, std::cos(std::numbers::pi / 180.0)));
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < kPaletteSize; ++k) {
    const double z = 1.0 - (1.0 - capZ) * (k + 0.5) / kPaletteSize;
    const double r = std::sqrt(std::max(0.0, 1 - z * z)), a = golden * k;
    pal.normals[k] = {static_cast<float>(r * std::cos(a)), static_cast<float>(r * std::sin(a)), static_cast<float>(z)};
  }
  // Lloyd iterations on an evenly strided subsample; empty clusters keep their point.
  const std::size_t stride = std::max<std::size_t>(1, normals.size() / kSample);
  for (int it = 0; it < iterations; ++it) {
    std::array<std::array<double, 4>, kPaletteSize> sum{};
    const NearestSearch search(pal.normals);
    for (std::size_t i = 0; i < normals.size(); i += stride) {
      const Vec3& n = normals[i];
      auto& s = sum[search.find(n)];
      s[0] += n.x;
      s[1] += n.y;
      s[2] += n.z;
      s[3] += 1;
    }
    for (int k = 0; k < kPaletteSize; ++k) {
      const auto& s = sum[k];
      const double len = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
      if (s[3] > 0 && len > 0) {
        pal.normals[k] = {static_cast<float>(s[0] / len), static_cast<float>(s[1] / len),
                          static_cast<float>(s[2] / len)};
      }
    }
  }
  const NearestSearch search(pal.normals);
  pal.index.resize(normals.size());
  for (std::size_t i = 0; i < normals.size(); ++i) pal.index[i] = static_cast<std::uint8_t>(search.find(normals[i]));
  return pal;
}

double maxPaletteError(const NormalPalette& pal, const std::vector<Vec3>& normals) {
  double worst = 0;
  for (std::size_t i = 0; i < normals.size(); ++i) {
    const double d = std::clamp(dot(pal.normals[pal.index[i]], normals[i]), -1.0, 1.0);
    worst = std::max(worst, std::acos(d));
  }
  return worst;
}

}  // namespace vbim::lighting
