// INTERNAL, GL-free: which optimisation passes this build has. Each pass is one CMake option,
// FXPORT_PASS_<NAME> (runtime/graphics/CMakeLists.txt), that leaves its sources out of the library;
// the device then behaves as with that optimisation switched off in DeviceOptimizations. The core
// reaches a pass only under `if constexpr` on these flags, so a pass left out is neither called nor
// linked (a discarded statement needs no definition of what it names).
#pragma once

#include "optimization_passes_built.h"  // generated: FXPORT_PASS_<NAME> 0 or 1

namespace fxport {

// Compute passes and texel copies (gl/passes/, registered through createComputePasses).
inline constexpr bool kComputePassesBuilt = FXPORT_PASS_COMPUTE != 0;
// Lazy depth storage (device/passes/depth_storage.cpp): without it every depth/stencil buffer is
// made with its target, as with DeviceOptimizations::LazyDepthStorage off.
inline constexpr bool kLazyDepthBuilt = FXPORT_PASS_LAZY_DEPTH != 0;
// Pending clears with their folds (device/passes/pending_clear.cpp): without them every clear is
// executed as it comes and nothing is pending, as with DeferClears and DropCoveredClears off.
inline constexpr bool kPendingClearsBuilt = FXPORT_PASS_PENDING_CLEARS != 0;

}  // namespace fxport
