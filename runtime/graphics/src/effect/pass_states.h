// INTERNAL: a pass's render states and a shader's sampler states, decoded once when the technique
// is compiled (xlate's typed rows -> the runtime's own enums, texture parameters -> indices), so
// that EffectPass::Apply() only copies values: no name look-up, no number -> enum conversion
// (except for parameter-driven states, whose value is only known at Apply()).
#pragma once

#include <optional>
#include <vector>

#include "fxport/graphics/blend_state.h"
#include "fxport/graphics/depth_stencil_state.h"
#include "fxport/graphics/effect.h"
#include "fxport/graphics/rasterizer_state.h"
#include "fxport/graphics/sampler_state.h"
#include "fxport/xlate/compiled_effect.h"

namespace fxport {

class GraphicsDevice;

// One state assignment in runtime types. Only the field that `state` uses is meaningful.
struct PassStateRow {
    xlate::RenderState state = xlate::RenderState::AlphaBlendEnable;
    int index = 0;       // render target of ColorWriteEnable[n]
    int parameter = -1;  // >= 0: the value is this parameter's, read at Apply()
    // The parameter's element as a selector program ending in parameter[index]; empty without one.
    std::vector<xlate::SelectorOp> fromParameter;
    const xlate::SourceLocation* where = nullptr;  // the assignment in the compiled effect (for warnings)
    bool flag = false;
    int integer = 0;
    float number = 0;
    Blend blend = Blend::One;
    BlendFunction function = BlendFunction::Add;
    CompareFunction compare = CompareFunction::Always;
    StencilOperation stencil = StencilOperation::Keep;
    CullMode cull = CullMode::CullCounterClockwiseFace;
    FillMode fill = FillMode::Solid;
    Color factor;
    Vector4 vector;  // the float4 of BlendFactor / ClipPlane[n], unquantised
};

// Fills the typed field of `row` from xlate's value for the row's state.
void setRowValue(PassStateRow& row, const xlate::StateValue& value);

// The effect's sampler_state over the device's SamplerStates[unit]: what the effect specified.
struct SamplerOverride {
    std::optional<TextureAddressMode> addressU, addressV, addressW;
    std::optional<bool> minLinear, magLinear, mipLinear;
    bool minAnisotropic = false;      // MinFilter = Anisotropic (only meaningful when minLinear is set)
    std::optional<bool> useMipMaps;   // MipFilter = None -> false
    std::optional<int> maxAnisotropy, maxMipLevel;
    std::optional<float> mipLodBias;
    std::optional<Vector4> borderColor;
    std::optional<CompareFunction> comparison;  // a comparison sampler; none turns comparison off
    bool empty = true;                          // nothing but (no) comparison

    SamplerState over(SamplerState device) const;
};

// A sampler state read from a parameter at Apply(): the field and the program that reads the
// parameter's (element's) D3D9 number (Effect::Impl::evaluateSelector).
struct SamplerStateFromParameter {
    xlate::SamplerStateField field = xlate::SamplerStateField::MinFilter;
    std::vector<xlate::SelectorOp> read;
};

// One texture unit a shader samples, ready for Apply().
struct SamplerSlot {
    int unit = 0;
    int vertexRegister = -1;    // an SM 1-3 vertex shader's sampler: its s#, the GraphicsDevice::VertexTextures slot
    int textureParameter = -1;  // index into the effect's parameters; -1: Textures[unit] as set by the host
    SamplerOverride state;      // decoded once, when no state reads a parameter
    xlate::SamplerStateDesc literal;                       // the states given as values
    std::vector<SamplerStateFromParameter> fromParameters; // the others, over `literal` at each Apply()
};

SamplerOverride decodeSamplerState(const xlate::SamplerStateDesc& desc);

// The slot's sampler state over `device`: `state`, decoded once, or, where states are read from
// the effect's parameters, decoded from them now (only such slots pay for it at Apply()).
SamplerState samplerStateOver(const SamplerSlot& slot, const Effect::Impl& effect, const SamplerState& device);

struct PassStates {
    std::vector<PassStateRow> rows;  // in source order: later rows win
    bool hasParameterRows = false;
    // D3D9 texture stages the pass sets and its shaders do not sample (xlate::Pass::textureStages),
    // set on the device at Apply() for later passes.
    std::vector<SamplerSlot> textureStages;
};

PassStates decodePassStates(const xlate::Pass& pass);

// Sets the rows over the device's BlendState/DepthStencilState/RasterizerState (D3D9 keeps
// AlphaBlendEnable, SrcBlend ... as separate states; XNA's objects are folded back). Parameter-
// driven rows read `effect`'s current parameter values.
void applyPassStates(const PassStates& states, const Effect::Impl& effect, GraphicsDevice& device);

}  // namespace fxport
