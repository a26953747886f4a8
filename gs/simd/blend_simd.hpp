// SIMD blend kernels, chosen at run time (runtime/simd/targets.hpp; never -march=native: the
// build must run anywhere, valgrind included). Lives in its own target, vbim_gs_simd, because the
// kernels need Highway's headers; the model (vbim_gs) takes any BlendKernels and defaults to the scalar
// reference. The tests prove every compiled target bit-identical to gs/blend.hpp.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "gs/blend.hpp"

namespace vbim::gs::simd {

// Kernels for the best target this CPU supports, except that AVX2 runs them where AVX-512 is there
// too (blend_simd.cpp says why); name() is the Highway target ("AVX2", "SSE4").
const BlendKernels& kernels();

// Runs fn once per compiled target the CPU supports, with dispatch forced to that target (tests);
// restores normal dispatch afterwards. fn receives the target name.
void forEachTarget(const std::function<void(const std::string& target)>& fn);

}  // namespace vbim::gs::simd
