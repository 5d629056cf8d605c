// Step 4b: HLSL semantics that glslang's SPIR-V gets wrong, corrected on the SPIR-V it emits,
// before legalisation (spirv-opt's inlining, folding and dead-code passes) can fold the wrong
// meaning into constants. Each fix-up is one function in spirv_fixups.cpp, with the reason and the
// test that shows it; hlslToSpirv runs them all, in order, on every module.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace fxport::xlate {

// Applies every fix-up to `words` (an unoptimised glslang module) in place.
void applySpirvFixups(std::vector<std::uint32_t>& words);

// spirv-opt's legalisation passes for HLSL (what glslang runs when its optimizer is on): inlining,
// scalar replacement and forwarding of opaque values (samplers passed to functions), dead code.
// Returns false (and leaves `words` as they were) when spirv-opt refuses the module.
bool legalizeSpirv(std::vector<std::uint32_t>& words, std::string* error);

}  // namespace fxport::xlate
