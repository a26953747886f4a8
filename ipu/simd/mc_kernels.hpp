// Highway versions of motion compensation's kernels (ipu/mc_kernels.hpp), with the instruction set
// chosen at run time (no -march=native), bit-identical to scalarMcKernels().
#pragma once

#include "ipu/mc_kernels.hpp"

namespace vbim::ipu {

const McKernels& simdMcKernels();
// The kernels of the best target allowed at this moment, not cached: tests run them on every target
// (vbim::simd::setTargetsForTest).
McKernels simdMcKernelsOfCurrentTarget();

}  // namespace vbim::ipu
