// Render and sampler state assignments -> canonical StateAssignment rows / SamplerStateDesc.
// DX9 names (`AlphaBlendEnable`, `SrcBlend = SrcAlpha`, numeric D3DBLEND codes ...) and DX10 state
// objects (`SetBlendState(b, float4(0,0,0,0), 0xFFFFFFFF)`) end up in the same vocabulary, so the
// runtime has one mapping onto its cached state objects.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

class SourceMap;

struct StateContext {
    const EffectSyntax& syntax;
    const SourceMap& map;
    std::vector<Diagnostic>& diagnostics;  // errors and warnings are appended here
    // The effect's parameters, for states that name one (`AlphaRef = <AlphaReference>;`): the row
    // gets the parameter's index. nullptr where no pass states are translated.
    const std::vector<Parameter>* parameters = nullptr;
};

enum class StateResult {
    Applied,    // rows appended
    Ignored,    // a fixed-function state with no meaning for shaders (warning added)
    Failed,     // error added; the pass is invalid
    NotAState,  // a shader assignment (VertexShader, SetPixelShader ...) for the caller
};

StateResult translatePassAssignment(const FxAssignment& assignment, StateContext& context,
                                    std::vector<StateAssignment>& out);

// One `sampler_state { ... }` entry. `Texture = <T>` sets textureParameter. A filter, address,
// anisotropy, level or bias read from a parameter (`MinFilter = <Filter>;`) goes to
// `fromParameters` as written, for resolveSamplerStateParameter once the parameters are known
// (without `fromParameters` it is an error). Returns false after adding an error.
bool translateSamplerAssignment(const FxAssignment& assignment, StateContext& context, SamplerStateDesc& state,
                                std::string& textureParameter, std::vector<FxAssignment>* fromParameters = nullptr);

// A sampler state a D3D9 pass sets per texture stage (`MinFilter[1] = Linear;`), lower case: what
// a pass gives the sampler at register s<n> of its pixel shader (asm or HLSL).
bool isTextureStageSamplerState(const std::string& lower);

// Each state `over` sets replaces `base`'s (a pass's MinFilter[0] over a sampler_state's).
void overlaySamplerState(SamplerStateDesc& base, const SamplerStateDesc& over);

// A sampler state translateSamplerAssignment left to `fromParameters`, with the parameter (element)
// resolved against `context.parameters`. False after adding an error.
bool resolveSamplerStateParameter(const FxAssignment& assignment, StateContext& context, SamplerStateParameter& out);

// The D3D9 fixed-function states (lower case) a pass or sampler may set: accepted, ignored, and
// warned about (FX1303). Tests set each one.
const std::set<std::string>& fixedFunctionStateNames();

}  // namespace fxport::xlate
