// A `uniform` resource parameter of a loose shader's entry point (fxc /E, D3DCompile), given no value:
// Cg-era HLSL (OGRE's Bloom2_ps20.cg `float4 main(..., uniform sampler RT : register(s0), ...)`,
// D3DCompile'd as ps_2_0 or ps_4_0_level_9_1). fxc makes it a global of the shader, on the register
// the parameter names; numeric ones are declared as effect parameters by the parser
// (declareUniformEntryParameters). A sampler, texture or buffer must be parsed as a global object to
// get its unit, so it is declared at the end of the text (on its last line: every line keeps its
// number), once per name, with its `register(...)`, and the text is parsed again; the entry
// wrapper passes that global. In an effect, whose compile statement must give an object its value,
// such a parameter stays an error (FX1403; tests/fixtures/broken/uniform_sampler_without_value.fx).
#pragma once

#include <string>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::string uniformResourceParametersDeclared(const std::string& preprocessed, const EffectSyntax& syntax);

}  // namespace fxport::xlate
