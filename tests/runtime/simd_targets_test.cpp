// runtime/simd/targets.hpp reads the CPU's Highway targets itself, so that no product program loads
// libhwy.so. Here it must agree with Highway's own detection (hwy::SupportedTargets) on every target
// the kernels are compiled for, and a forced target must be the one the dispatch index names.
#include <gtest/gtest.h>

#include <hwy/highway.h>
#include <hwy/targets.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "runtime/simd/targets.hpp"

namespace {

// HWY_EMU128 and HWY_SCALAR are always there; Highway 1.0.3 names only one of them.
constexpr std::int64_t kVectorTargets = HWY_TARGETS & ~(HWY_SCALAR | HWY_EMU128);

TEST(SimdTargets, AgreeWithHighwaysOwnDetection) {
  const std::int64_t ours = vbim::simd::supportedTargets() & kVectorTargets;
  const std::int64_t highways = hwy::SupportedTargets() & kVectorTargets;
  EXPECT_EQ(ours, highways) << "ours " << std::hex << ours << ", Highway's " << highways;
}

TEST(SimdTargets, EveryCpuRunsTheScalarFallback) {
  EXPECT_NE(vbim::simd::supportedTargets() & HWY_SCALAR, 0);
  EXPECT_NE(vbim::simd::supportedTargets() & HWY_EMU128, 0);
}

TEST(SimdTargets, ForEachTargetForcesEachTargetBestFirstAndGivesTheCpusChoiceBack) {
  const std::int64_t before = vbim::simd::supportedTargets();
  const std::size_t indexBefore = vbim::simd::chosenTarget().GetIndex();
  std::vector<std::int64_t> seen;
  std::vector<std::size_t> indices;
  vbim::simd::forEachTarget(HWY_TARGETS, [&](std::int64_t target) {
    EXPECT_EQ(vbim::simd::supportedTargets(), target);
    seen.push_back(target);
    indices.push_back(vbim::simd::chosenTarget().GetIndex());
  });
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.back(), HWY_SCALAR & HWY_TARGETS ? HWY_SCALAR : HWY_EMU128);  // the fallback comes last
  for (std::size_t i = 1; i < seen.size(); ++i) {
    EXPECT_LT(seen[i - 1], seen[i]);        // lower bits are better targets
    EXPECT_LT(indices[i - 1], indices[i]);  // and come first in the dispatch tables
  }
  // The first target forced is the best one, the one the dispatch picks without forcing.
  EXPECT_EQ(indices.front(), indexBefore);
  EXPECT_EQ(vbim::simd::supportedTargets(), before);
  EXPECT_EQ(vbim::simd::chosenTarget().GetIndex(), indexBefore);
}

TEST(SimdTargets, ForEachTargetGivesTheCpusChoiceBackWhenTheCallThrows) {
  const std::int64_t before = vbim::simd::supportedTargets();
  EXPECT_THROW(vbim::simd::forEachTarget(HWY_TARGETS, [](std::int64_t) { throw std::runtime_error("stop"); }),
               std::runtime_error);
  EXPECT_EQ(vbim::simd::supportedTargets(), before);
}

}  // namespace
