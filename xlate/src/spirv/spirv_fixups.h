// Step 4b: HLSL semantics that glslang's SPIR-V gets wrong, corrected on the SPIR-V it emits,
// before legalisation (spirv-opt's inlining, folding and dead-code passes) can fold the wrong
// meaning into constants. Each fix-up is one function in spirv_fixups.cpp, with the reason and the
// test that shows it; hlslToSpirv runs them all, in order, on every module.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

// Applies every fix-up to `m` (an unoptimised glslang module); true when one changed it.
bool applySpirvFixups(ParsedSpirv& m);

// fxc folds constants and refuses a division whose divisor folds to zero: integer `/` and `%` at
// every shader model, float `/` and `%` at SM2-3 (SM4+ computes inf/NaN). Locals are forwarded
// first (inlining and store-to-load forwarding, no arithmetic folding, which would erase the
// division); returns true when such a division remains. Run on the unoptimised module.
bool dividesByConstantZero(const std::vector<std::uint32_t>& words, bool floatsToo);

// spirv-opt's legalisation passes for HLSL (what glslang runs when its optimizer is on): inlining,
// scalar replacement and forwarding of opaque values (samplers passed to functions), dead code.
// Returns false (and leaves `words` as they were) when spirv-opt refuses the module.
// `sm2or3`: integers are floats (spirv_integer_fixups.h), also where folding meets them.
bool legalizeSpirv(std::vector<std::uint32_t>& words, std::string* error, bool sm2or3 = false);

// Another round of scalar replacement and store forwarding, for a module that still has a local
// resource variable after legalizeSpirv (unset_static_resources.h): run only then, so every other
// module's GLSL stays as it was.
bool forwardResourceCopies(std::vector<std::uint32_t>& words, std::string* error);

}  // namespace fxport::xlate
