// Explicit register bindings written in HLSL (`float a : register(c2)`, `Texture2D t : register(t1)`,
// `register(c0[1 + 1])`, `packoffset(c1.y)`), which xlate's reflection does not carry: the runner
// needs them to match vkd3d's slot-numbered uniforms and resources to parameters.
#pragma once

#include <string>

namespace conformance {

// The register index bound to global `name` for register class `letter` ('c', 't', 's', 'b'); -1
// when none is written. Index expressions are evaluated as fxc does (truncated: c0[0.6 + 0.6] = c1).
int explicitRegister(const std::string& source, const std::string& name, char letter);

// `name : packoffset(cN.y)` as a component offset (N*4 + 1); -1 when none is written.
int explicitPackOffset(const std::string& source, const std::string& name);

}  // namespace conformance
