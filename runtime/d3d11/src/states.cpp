// D3D11 state descriptions decoded once, at Create*State, into the device core's state structs
// (DXVK's d3d11_blend.cpp does the same into Vulkan's). Every field is checked: a value D3D
// rejects is E_INVALIDARG, one D3D takes but fxport cannot honour is E_NOTIMPL; both name the
// description, the field and the value.
#include <cmath>
#include <string>

#include "d3d11_impl.h"

namespace fxport::d3d11 {

namespace {

std::string field(const char* desc, const std::string& name, long long value) {
    return std::string(desc) + "." + name + " = " + std::to_string(value);
}

HRESULT invalid(const char* call, const std::string& what, const std::string& why) {
    return fail(E_INVALIDARG, std::string(call) + ": " + what + " " + why);
}
HRESULT unsupported(const char* call, const std::string& what, const std::string& why) {
    return fail(E_NOTIMPL, std::string(call) + ": " + what + " is not supported by fxport (" + why + ")");
}

bool compareFunction(D3D11_COMPARISON_FUNC f, fxport::CompareFunction& out) {
    switch (f) {
    case D3D11_COMPARISON_NEVER: out = fxport::CompareFunction::Never; return true;
    case D3D11_COMPARISON_LESS: out = fxport::CompareFunction::Less; return true;
    case D3D11_COMPARISON_EQUAL: out = fxport::CompareFunction::Equal; return true;
    case D3D11_COMPARISON_LESS_EQUAL: out = fxport::CompareFunction::LessEqual; return true;
    case D3D11_COMPARISON_GREATER: out = fxport::CompareFunction::Greater; return true;
    case D3D11_COMPARISON_NOT_EQUAL: out = fxport::CompareFunction::NotEqual; return true;
    case D3D11_COMPARISON_GREATER_EQUAL: out = fxport::CompareFunction::GreaterEqual; return true;
    case D3D11_COMPARISON_ALWAYS: out = fxport::CompareFunction::Always; return true;
    }
    return false;
}

bool stencilOp(D3D11_STENCIL_OP op, fxport::StencilOperation& out) {
    switch (op) {
    case D3D11_STENCIL_OP_KEEP: out = fxport::StencilOperation::Keep; return true;
    case D3D11_STENCIL_OP_ZERO: out = fxport::StencilOperation::Zero; return true;
    case D3D11_STENCIL_OP_REPLACE: out = fxport::StencilOperation::Replace; return true;
    case D3D11_STENCIL_OP_INCR_SAT: out = fxport::StencilOperation::IncrementSaturation; return true;
    case D3D11_STENCIL_OP_DECR_SAT: out = fxport::StencilOperation::DecrementSaturation; return true;
    case D3D11_STENCIL_OP_INVERT: out = fxport::StencilOperation::Invert; return true;
    case D3D11_STENCIL_OP_INCR: out = fxport::StencilOperation::Increment; return true;
    case D3D11_STENCIL_OP_DECR: out = fxport::StencilOperation::Decrement; return true;
    }
    return false;
}

// 0: ok, 1: not a D3D11_BLEND value, 2: a dual-source factor (SRC1_*).
int blendFactor(D3D11_BLEND b, fxport::Blend& out) {
    switch (b) {
    case D3D11_BLEND_ZERO: out = fxport::Blend::Zero; return 0;
    case D3D11_BLEND_ONE: out = fxport::Blend::One; return 0;
    case D3D11_BLEND_SRC_COLOR: out = fxport::Blend::SourceColor; return 0;
    case D3D11_BLEND_INV_SRC_COLOR: out = fxport::Blend::InverseSourceColor; return 0;
    case D3D11_BLEND_SRC_ALPHA: out = fxport::Blend::SourceAlpha; return 0;
    case D3D11_BLEND_INV_SRC_ALPHA: out = fxport::Blend::InverseSourceAlpha; return 0;
    case D3D11_BLEND_DEST_ALPHA: out = fxport::Blend::DestinationAlpha; return 0;
    case D3D11_BLEND_INV_DEST_ALPHA: out = fxport::Blend::InverseDestinationAlpha; return 0;
    case D3D11_BLEND_DEST_COLOR: out = fxport::Blend::DestinationColor; return 0;
    case D3D11_BLEND_INV_DEST_COLOR: out = fxport::Blend::InverseDestinationColor; return 0;
    case D3D11_BLEND_SRC_ALPHA_SAT: out = fxport::Blend::SourceAlphaSaturation; return 0;
    case D3D11_BLEND_BLEND_FACTOR: out = fxport::Blend::BlendFactor; return 0;
    case D3D11_BLEND_INV_BLEND_FACTOR: out = fxport::Blend::InverseBlendFactor; return 0;
    case D3D11_BLEND_SRC1_COLOR: case D3D11_BLEND_INV_SRC1_COLOR: case D3D11_BLEND_SRC1_ALPHA: case D3D11_BLEND_INV_SRC1_ALPHA: return 2;
    }
    return 1;
}

bool blendOp(D3D11_BLEND_OP op, fxport::BlendFunction& out) {
    switch (op) {
    case D3D11_BLEND_OP_ADD: out = fxport::BlendFunction::Add; return true;
    case D3D11_BLEND_OP_SUBTRACT: out = fxport::BlendFunction::Subtract; return true;
    case D3D11_BLEND_OP_REV_SUBTRACT: out = fxport::BlendFunction::ReverseSubtract; return true;
    case D3D11_BLEND_OP_MIN: out = fxport::BlendFunction::Min; return true;
    case D3D11_BLEND_OP_MAX: out = fxport::BlendFunction::Max; return true;
    }
    return false;
}

bool isColorFactor(D3D11_BLEND b) {
    return b == D3D11_BLEND_SRC_COLOR || b == D3D11_BLEND_INV_SRC_COLOR || b == D3D11_BLEND_DEST_COLOR ||
           b == D3D11_BLEND_INV_DEST_COLOR || b == D3D11_BLEND_SRC1_COLOR || b == D3D11_BLEND_INV_SRC1_COLOR;
}

// One render target's blend, checked; `which` is "RenderTarget[i]".
HRESULT decodeTargetBlend(const D3D11_RENDER_TARGET_BLEND_DESC& t, const std::string& which, fxport::BlendState& out) {
    const char* call = "CreateBlendState";
    const std::string at = "D3D11_BLEND_DESC." + which;
    struct Factor {
        const char* name;
        D3D11_BLEND value;
        fxport::Blend* into;
        bool alpha;
    } factors[] = {{"SrcBlend", t.SrcBlend, &out.ColorSourceBlend, false},
                   {"DestBlend", t.DestBlend, &out.ColorDestinationBlend, false},
                   {"SrcBlendAlpha", t.SrcBlendAlpha, &out.AlphaSourceBlend, true},
                   {"DestBlendAlpha", t.DestBlendAlpha, &out.AlphaDestinationBlend, true}};
    for (const Factor& f : factors) {
        const std::string what = at + "." + f.name + " = " + std::to_string(f.value);
        fxport::Blend b;
        const int r = blendFactor(f.value, b);
        if (r == 1) return invalid(call, what, "is not a D3D11_BLEND value (1-11, 14-19)");
        if (r == 2) return unsupported(call, what, "dual-source blending");
        if (f.alpha && isColorFactor(f.value)) return invalid(call, what, "is a colour factor; alpha blend factors may not be");
        if (t.BlendEnable) *f.into = b;
    }
    struct Op {
        const char* name;
        D3D11_BLEND_OP value;
        fxport::BlendFunction* into;
    } ops[] = {{"BlendOp", t.BlendOp, &out.ColorBlendFunction}, {"BlendOpAlpha", t.BlendOpAlpha, &out.AlphaBlendFunction}};
    for (const Op& o : ops) {
        fxport::BlendFunction f;
        if (!blendOp(o.value, f))
            return invalid(call, at + "." + o.name + " = " + std::to_string(o.value), "is not a D3D11_BLEND_OP value (1-5)");
        if (t.BlendEnable) *o.into = f;
    }
    if (t.RenderTargetWriteMask > 15)
        return invalid(call, at + ".RenderTargetWriteMask = " + std::to_string(t.RenderTargetWriteMask), "has bits beyond D3D11_COLOR_WRITE_ENABLE_ALL");
    return S_OK;
}

bool sameBlend(const D3D11_RENDER_TARGET_BLEND_DESC& a, const D3D11_RENDER_TARGET_BLEND_DESC& b) {
    if (a.BlendEnable != b.BlendEnable) return false;
    if (!a.BlendEnable) return true;
    return a.SrcBlend == b.SrcBlend && a.DestBlend == b.DestBlend && a.BlendOp == b.BlendOp && a.SrcBlendAlpha == b.SrcBlendAlpha &&
           a.DestBlendAlpha == b.DestBlendAlpha && a.BlendOpAlpha == b.BlendOpAlpha;
}

}  // namespace

D3D11_SAMPLER_DESC defaultSamplerDesc() { return D3D11_SAMPLER_DESC{}; }

HRESULT decodeSampler(const D3D11_SAMPLER_DESC& d, fxport::SamplerState& out) {
    const char* call = "CreateSamplerState";
    out = fxport::SamplerState{};
    using TF = fxport::TextureFilter;
    switch (d.Filter & ~0x80u) {
    case D3D11_FILTER_MIN_MAG_MIP_POINT: out.Filter = TF::Point; break;
    case D3D11_FILTER_MIN_MAG_POINT_MIP_LINEAR: out.Filter = TF::PointMipLinear; break;
    case D3D11_FILTER_MIN_POINT_MAG_LINEAR_MIP_POINT: out.Filter = TF::MinPointMagLinearMipPoint; break;
    case D3D11_FILTER_MIN_POINT_MAG_MIP_LINEAR: out.Filter = TF::MinPointMagLinearMipLinear; break;
    case D3D11_FILTER_MIN_LINEAR_MAG_MIP_POINT: out.Filter = TF::MinLinearMagPointMipPoint; break;
    case D3D11_FILTER_MIN_LINEAR_MAG_POINT_MIP_LINEAR: out.Filter = TF::MinLinearMagPointMipLinear; break;
    case D3D11_FILTER_MIN_MAG_LINEAR_MIP_POINT: out.Filter = TF::LinearMipPoint; break;
    case D3D11_FILTER_MIN_MAG_MIP_LINEAR: out.Filter = TF::Linear; break;
    case D3D11_FILTER_ANISOTROPIC: out.Filter = TF::Anisotropic; break;
    default: return invalid(call, field("D3D11_SAMPLER_DESC", "Filter", d.Filter), "is not a D3D11_FILTER value fxport knows");
    }
    out.UseComparison = (d.Filter & 0x80u) != 0;
    if (out.UseComparison && !compareFunction(d.ComparisonFunc, out.ComparisonFunction))
        return invalid(call, field("D3D11_SAMPLER_DESC", "ComparisonFunc", d.ComparisonFunc), "is not a D3D11_COMPARISON_FUNC value (1-8)");
    const D3D11_TEXTURE_ADDRESS_MODE modes[3] = {d.AddressU, d.AddressV, d.AddressW};
    fxport::TextureAddressMode* into[3] = {&out.AddressU, &out.AddressV, &out.AddressW};
    const char* names[3] = {"AddressU", "AddressV", "AddressW"};
    for (int i = 0; i < 3; ++i) {
        switch (modes[i]) {
        case D3D11_TEXTURE_ADDRESS_WRAP: *into[i] = fxport::TextureAddressMode::Wrap; break;
        case D3D11_TEXTURE_ADDRESS_MIRROR: *into[i] = fxport::TextureAddressMode::Mirror; break;
        case D3D11_TEXTURE_ADDRESS_CLAMP: *into[i] = fxport::TextureAddressMode::Clamp; break;
        case D3D11_TEXTURE_ADDRESS_BORDER: *into[i] = fxport::TextureAddressMode::Border; break;
        case D3D11_TEXTURE_ADDRESS_MIRROR_ONCE:
            return unsupported(call, field("D3D11_SAMPLER_DESC", names[i], modes[i]), "MIRROR_ONCE has no device-core mode yet");
        default: return invalid(call, field("D3D11_SAMPLER_DESC", names[i], modes[i]), "is not a D3D11_TEXTURE_ADDRESS_MODE value (1-5)");
        }
    }
    if (d.MaxAnisotropy > 16) return invalid(call, field("D3D11_SAMPLER_DESC", "MaxAnisotropy", d.MaxAnisotropy), "is above 16");
    if (!(d.MipLODBias >= -16.0f && d.MipLODBias <= 15.99f))
        return invalid(call, "D3D11_SAMPLER_DESC.MipLODBias = " + std::to_string(d.MipLODBias), "is outside [-16, 15.99]");
    if (std::isnan(d.MinLOD) || std::isnan(d.MaxLOD) || d.MinLOD > d.MaxLOD)
        return invalid(call, "D3D11_SAMPLER_DESC.MinLOD = " + std::to_string(d.MinLOD) + ", MaxLOD = " + std::to_string(d.MaxLOD),
                       "is not a range (MinLOD must not exceed MaxLOD)");
    out.MaxAnisotropy = int(std::max(1u, d.MaxAnisotropy));
    out.MipMapLevelOfDetailBias = d.MipLODBias;
    out.BorderColor = Vector4(d.BorderColor[0], d.BorderColor[1], d.BorderColor[2], d.BorderColor[3]);
    // LOD clamps: the most detailed level from MinLOD; MaxLOD below 1 samples that level only.
    out.MaxMipLevel = d.MinLOD > 0 ? int(d.MinLOD) : 0;
    out.UseMipMaps = d.MaxLOD >= 1.0f;
    return S_OK;
}

HRESULT decodeBlend(const D3D11_BLEND_DESC& d, fxport::BlendState& out) {
    const char* call = "CreateBlendState";
    out = fxport::BlendState::Opaque;
    if (d.AlphaToCoverageEnable) return unsupported(call, "D3D11_BLEND_DESC.AlphaToCoverageEnable = TRUE", "no multisampling");
    const int targets = d.IndependentBlendEnable ? 8 : 1;
    fxport::ColorWriteChannels* masks[4] = {&out.ColorWriteChannels, &out.ColorWriteChannels1, &out.ColorWriteChannels2,
                                            &out.ColorWriteChannels3};
    // Every field is checked first (E_INVALIDARG), then what fxport cannot honour (E_NOTIMPL).
    for (int i = 0; i < targets; ++i) {
        fxport::BlendState scratch = out;
        const std::string which = "RenderTarget[" + std::to_string(i) + "]";
        if (HRESULT hr = decodeTargetBlend(d.RenderTarget[i], which, i == 0 ? out : scratch); FAILED(hr)) return hr;
    }
    for (int i = 1; i < targets; ++i) {
        const std::string which = "RenderTarget[" + std::to_string(i) + "]";
        if (!sameBlend(d.RenderTarget[i], d.RenderTarget[0]))
            return unsupported(call, "D3D11_BLEND_DESC." + which + " blending unlike RenderTarget[0]",
                               "one blend for every target; only the write masks differ per target");
        if (i >= 4 && d.RenderTarget[i].RenderTargetWriteMask != D3D11_COLOR_WRITE_ENABLE_ALL)
            return unsupported(call, "D3D11_BLEND_DESC." + which + ".RenderTargetWriteMask", "at most 4 render targets");
    }
    for (int i = 0; i < 4; ++i)
        *masks[i] = fxport::ColorWriteChannels(d.RenderTarget[d.IndependentBlendEnable ? i : 0].RenderTargetWriteMask);
    return S_OK;
}

HRESULT decodeRasterizer(const D3D11_RASTERIZER_DESC& d, fxport::RasterizerState& out) {
    const char* call = "CreateRasterizerState";
    out = fxport::RasterizerState{};
    if (d.FillMode == D3D11_FILL_SOLID) out.FillMode = fxport::FillMode::Solid;
    else if (d.FillMode == D3D11_FILL_WIREFRAME) out.FillMode = fxport::FillMode::WireFrame;
    else return invalid(call, field("D3D11_RASTERIZER_DESC", "FillMode", d.FillMode), "is not a D3D11_FILL_MODE value (2, 3)");
    // Front faces are clockwise on screen unless FrontCounterClockwise; the core names the winding it culls.
    const bool ccwFront = d.FrontCounterClockwise != FALSE;
    switch (d.CullMode) {
    case D3D11_CULL_NONE: out.CullMode = fxport::CullMode::None; break;
    case D3D11_CULL_BACK:
        out.CullMode = ccwFront ? fxport::CullMode::CullClockwiseFace : fxport::CullMode::CullCounterClockwiseFace;
        break;
    case D3D11_CULL_FRONT:
        out.CullMode = ccwFront ? fxport::CullMode::CullCounterClockwiseFace : fxport::CullMode::CullClockwiseFace;
        break;
    default: return invalid(call, field("D3D11_RASTERIZER_DESC", "CullMode", d.CullMode), "is not a D3D11_CULL_MODE value (1-3)");
    }
    if (d.DepthBiasClamp != 0)
        return unsupported(call, "D3D11_RASTERIZER_DESC.DepthBiasClamp = " + std::to_string(d.DepthBiasClamp), "GL 4.5 core has no bias clamp");
    if (!d.DepthClipEnable) return unsupported(call, "D3D11_RASTERIZER_DESC.DepthClipEnable = FALSE", "depth clamping is not wired yet");
    // D3D's integer bias is in units of the depth buffer's resolution: 2^-24 for the 24-bit buffers.
    out.DepthBias = float(d.DepthBias) / 16777216.0f;
    out.SlopeScaleDepthBias = d.SlopeScaledDepthBias;
    out.ScissorTestEnable = d.ScissorEnable != FALSE;
    // D3D10.1+ rasterises triangles on a multisampled target per sample whatever MultisampleEnable
    // says (it picks a line algorithm only); GL does so only with GL_MULTISAMPLE on.
    out.MultiSampleAntiAlias = true;
    out.FrontCounterClockwise = ccwFront;  // SV_IsFrontFace and the FrontFace stencil ops follow it
    return S_OK;
}

HRESULT decodeDepthStencil(const D3D11_DEPTH_STENCIL_DESC& d, fxport::DepthStencilState& out) {
    const char* call = "CreateDepthStencilState";
    out = fxport::DepthStencilState{};
    out.DepthBufferEnable = d.DepthEnable != FALSE;
    if (d.DepthWriteMask != D3D11_DEPTH_WRITE_MASK_ZERO && d.DepthWriteMask != D3D11_DEPTH_WRITE_MASK_ALL)
        return invalid(call, field("D3D11_DEPTH_STENCIL_DESC", "DepthWriteMask", d.DepthWriteMask), "is not a D3D11_DEPTH_WRITE_MASK value (0, 1)");
    out.DepthBufferWriteEnable = d.DepthWriteMask == D3D11_DEPTH_WRITE_MASK_ALL;
    if (!compareFunction(d.DepthFunc, out.DepthBufferFunction))
        return invalid(call, field("D3D11_DEPTH_STENCIL_DESC", "DepthFunc", d.DepthFunc), "is not a D3D11_COMPARISON_FUNC value (1-8)");
    out.StencilEnable = d.StencilEnable != FALSE;
    out.StencilMask = d.StencilReadMask;
    out.StencilWriteMask = d.StencilWriteMask;
    struct Face {
        const char* name;
        const D3D11_DEPTH_STENCILOP_DESC& desc;
        fxport::CompareFunction* func;
        fxport::StencilOperation *pass, *fail, *depthFail;
    } faces[] = {{"FrontFace", d.FrontFace, &out.StencilFunction, &out.StencilPass, &out.StencilFail, &out.StencilDepthBufferFail},
                 {"BackFace", d.BackFace, &out.CounterClockwiseStencilFunction, &out.CounterClockwiseStencilPass,
                  &out.CounterClockwiseStencilFail, &out.CounterClockwiseStencilDepthBufferFail}};
    for (const Face& f : faces) {
        const std::string at = std::string(f.name) + ".";
        if (!compareFunction(f.desc.StencilFunc, *f.func))
            return invalid(call, field("D3D11_DEPTH_STENCIL_DESC", at + "StencilFunc", f.desc.StencilFunc), "is not a D3D11_COMPARISON_FUNC value (1-8)");
        const std::pair<const char*, D3D11_STENCIL_OP> ops[] = {
            {"StencilPassOp", f.desc.StencilPassOp}, {"StencilFailOp", f.desc.StencilFailOp}, {"StencilDepthFailOp", f.desc.StencilDepthFailOp}};
        fxport::StencilOperation* into[] = {f.pass, f.fail, f.depthFail};
        for (int i = 0; i < 3; ++i)
            if (!stencilOp(ops[i].second, *into[i]))
                return invalid(call, field("D3D11_DEPTH_STENCIL_DESC", at + ops[i].first, ops[i].second), "is not a D3D11_STENCIL_OP value (1-8)");
    }
    // The main stencil ops are the front faces' (clockwise ones, or counter-clockwise ones under a
    // rasterizer state with FrontCounterClockwise); the CounterClockwise set the back faces'.
    out.TwoSidedStencilMode = true;
    return S_OK;
}

}  // namespace fxport::d3d11
