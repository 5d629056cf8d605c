// Pass states that feed the registers of shader-assembly (asm { }) shaders, as D3D9 effects set
// them: `VertexShaderConstant4[0] = <WorldViewProj>;`, `PixelShaderConstantF[1] = <Tint>;` (also
// VertexShaderConstant/1/2/3, PixelShaderConstant/1/2/3/4, and literal values such as
// `VertexShaderConstant1[9] = {0, 0, 0, 1};`), and for an asm pixel shader the texture stages it
// samples: `Sampler[0] = (MySampler);`, `Texture[0] = <MyTexture>;`, `MinFilter[0] = Linear;` ...
// and the bump-environment states texbem/texbeml/bem read (`BumpEnvMat00[1] = 0.5;` ...).
//
// Register contents follow D3DX: a parameter fills as many consecutive registers as it occupies in
// a shader (all of them, whatever the digit in the state's name says), each register float4 with
// missing components 0. A matrix is packed as HLSL packs it: column_major (the default) puts
// column i in register n+i, `row_major` puts row i there. So with XNA's row-vector matrices
// `m4x4 oPos, v0, c0` computes mul(v0, WorldViewProj), as fxc's own code for `mul(v, M)` does
// (and as the DirectX SDK's asm samples relied on when they set untransposed matrices).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "d3d9asm/d3d9_asm.h"
#include "rewrite/fx_rewrite.h"
#include "fx/render_states.h"

namespace fxport::xlate {

// One texture stage of an asm pixel shader.
struct AsmTextureStage {
    std::string textureParameter;  // Texture[n] = <T>, or the texture of Sampler[n]'s sampler_state
    SamplerStateDesc state;        // Sampler[n]'s sampler_state, then the pass's MinFilter[n] ... on top
    std::optional<TextureKind> kind;
    std::string signature;         // what decides the stage, for the shader's cache key
};

struct AsmPassBindings {
    AsmBindings vertex, pixel;
    std::map<int, AsmTextureStage> stages;
    std::string vertexSignature, pixelSignature;  // constants as bound, for the shader's cache key
};

// Reads the pass's register states for the stages whose shader is shader assembly and marks the
// assignments it consumed (`consumed[i]` for pass.assignments[i]); the others stay render states.
// Problems (a parameter that cannot fill registers, an unknown sampler) are appended as diagnostics.
AsmPassBindings collectAsmPassBindings(const FxPass& pass, bool vertexIsAsm, bool pixelIsAsm, const RewrittenEffect& rewritten,
                                       StateContext& context, std::vector<bool>& consumed);

// The same texture-stage states for an HLSL pixel shader (D3D9 sets the stage whatever the shader
// is written in: stage n is the sampler at register s<n>): `Texture[n] = <T>;`, `Sampler[n] =
// (S);`, `MinFilter[n] = Linear;` ... (`Texture = <T>` is stage 0). Each stage with the token of
// its first assignment; the assignments read are marked in `consumed` (already sized).
struct PassSamplerStage {
    AsmTextureStage stage;
    size_t token = 0;
};
std::map<int, PassSamplerStage> collectPassSamplerStages(const FxPass& pass, const RewrittenEffect& rewritten, StateContext& context,
                                                         std::vector<bool>& consumed);

}  // namespace fxport::xlate
