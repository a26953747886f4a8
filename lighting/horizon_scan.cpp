#include "lighting/horizon_scan.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "lighting/fixed_angle.hpp"
#include "lighting/hull_scan.hpp"
#include "runtime/worker_pool.hpp"

namespace vbim::lighting {

namespace {

constexpr int kBandLanes = 64;  // lines scanned side by side: one row of a band is 256 contiguous bytes
constexpr int kRowBlock = 16;

// Metres of rise per height unit over metres of run per step along direction d.
double slopeScale(const Terrain& t, int d) {
  const GridStep s = kGridSteps[d];
  const double run = t.cellSize * ((s.dc != 0 && s.dr != 0) ? std::sqrt(2.0) : 1.0);
  return t.heightStep / run;
}

// dh / dk as a correctly rounded double first, so equal ratios give equal codes however the hull
// reached them.
std::uint16_t horizonCode(const HullPoint* top, const HullPoint& p, double scale) {
  if (top == nullptr || top->h <= p.h) return 0;
  const double ratio = static_cast<double>(top->h - p.h) / static_cast<double>(top->x - p.x);
  return codeFromTangent(ratio * scale);
}

// E and W: each row is a line, contiguous in memory.
void scanRowBlock(const Terrain& t, int d, int r0, int r1, std::uint16_t* out, std::vector<HullPoint>& stack) {
  const int dc = kGridSteps[d].dc;
  const double scale = slopeScale(t, d);
  stack.resize(static_cast<std::size_t>(t.width));
  for (int r = r0; r < r1; ++r) {
    int depth = 0;
    HullPoint hp{};
    const std::int32_t* row = t.heights.data() + static_cast<std::size_t>(r) * t.width;
    std::uint16_t* orow = out + static_cast<std::size_t>(r) * t.width;
    for (int k = 0; k < t.width; ++k) {
      const int c = dc > 0 ? t.width - 1 - k : k;  // far end first
      const HullPoint p{dc > 0 ? c : -c, row[c]};
      orow[c] = horizonCode(hullPush(stack.data(), depth, 1, p, hp), p, scale);
    }
  }
}

// Columns and diagonals: a band of adjacent lines is walked row by row from the far row, one stack
// per line with the stack levels interleaved, so each step touches neighbouring memory.
void scanBand(const Terrain& t, int d, int j0, int j1, std::uint16_t* out, std::vector<HullPoint>& pool) {
  const int dc = kGridSteps[d].dc, dr = kGridSteps[d].dr;
  const int shear = dc * dr;  // a line keeps j = c - shear * r
  const double scale = slopeScale(t, d);
  const int lanes = j1 - j0;
  const int maxLen = dc == 0 ? t.height : std::min(t.width, t.height);
  pool.resize(static_cast<std::size_t>(maxLen + 1) * kBandLanes);
  int depth[kBandLanes] = {};
  for (int k = 0; k < t.height; ++k) {
    const int r = dr > 0 ? t.height - 1 - k : k;
    const int x = dr > 0 ? r : -r;
    const int cBase = j0 + shear * r;  // column of lane 0 in this row
    const int l0 = std::max(0, -cBase), l1 = std::min(lanes, t.width - cBase);
    const std::int32_t* row = t.heights.data() + static_cast<std::size_t>(r) * t.width;
    std::uint16_t* orow = out + static_cast<std::size_t>(r) * t.width;
    for (int l = l0; l < l1; ++l) {
      const int c = cBase + l;
      const HullPoint p{x, row[c]};
      HullPoint hp;
      orow[c] = horizonCode(hullPush(pool.data() + l, depth[l], kBandLanes, p, hp), p, scale);
    }
  }
}

struct WorkItem {
  int direction;
  int begin, end;  // rows (E, W) or line indices j = c - dc * dr * r (others)
};

std::vector<WorkItem> workItems(const Terrain& t, int direction) {
  std::vector<WorkItem> items;
  const GridStep s = kGridSteps[direction];
  if (s.dr == 0) {
    for (int r = 0; r < t.height; r += kRowBlock) items.push_back({direction, r, std::min(t.height, r + kRowBlock)});
    return items;
  }
  // j = c - shear * r over the whole grid.
  const int shear = s.dc * s.dr;
  const int jMin = shear > 0 ? -(t.height - 1) : 0;
  const int jMax = shear < 0 ? t.width - 1 + t.height - 1 : t.width - 1;
  for (int j = jMin; j <= jMax; j += kBandLanes) items.push_back({direction, j, std::min(jMax + 1, j + kBandLanes)});
  return items;
}

void runItem(const Terrain& t, const WorkItem& w, std::uint16_t* out) {
  thread_local std::vector<HullPoint> scratch;
  if (kGridSteps[w.direction].dr == 0) {
    scanRowBlock(t, w.direction, w.begin, w.end, out, scratch);
  } else {
    scanBand(t, w.direction, w.begin, w.end, out, scratch);
  }
}

}  // namespace

void scanHorizon(const Terrain& t, int direction, std::uint16_t* out) {
  for (const WorkItem& w : workItems(t, direction)) runItem(t, w, out);
}

HorizonMaps computeHorizons(const Terrain& t, WorkerPool* pool) {
  HorizonMaps maps;
  maps.width = t.width;
  maps.height = t.height;
  std::vector<WorkItem> items;
  for (int d = 0; d < kDirections; ++d) {
    maps.code[d].assign(t.texels(), 0);
    const auto more = workItems(t, d);
    items.insert(items.end(), more.begin(), more.end());
  }
  auto run = [&](std::size_t i) { runItem(t, items[i], maps.code[items[i].direction].data()); };
  if (pool != nullptr) {
    pool->parallelFor(items.size(), run);
  } else {
    for (std::size_t i = 0; i < items.size(); ++i) run(i);
  }
  return maps;
}

void scanHorizonBruteForce(const Terrain& t, int direction, std::uint16_t* out) {
  const GridStep s = kGridSteps[direction];
  const double scale = slopeScale(t, direction);
  for (int r = 0; r < t.height; ++r) {
    for (int c = 0; c < t.width; ++c) {
      const HullPoint p{0, t.at(c, r)};
      HullPoint best{};
      bool any = false;
      for (int k = 1;; ++k) {
        const int cc = c + k * s.dc, rr = r + k * s.dr;
        if (cc < 0 || cc >= t.width || rr < 0 || rr >= t.height) break;
        const HullPoint q{k, t.at(cc, rr)};
        if (!any || !slopeAtMost(p, q, best)) best = q;  // strictly steeper replaces
        any = true;
      }
      out[static_cast<std::size_t>(r) * t.width + c] = horizonCode(any ? &best : nullptr, p, scale);
    }
  }
}

}  // namespace vbim::lighting
