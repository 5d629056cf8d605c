// Typed pass-state values: each state's alternative and default, and the two numeric forms a value
// arrives in (fxport's enum order from the parser, D3D9's codes from a parameter at Apply()).
#include "fx/state_values.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace fxport::xlate {

namespace {

// Integers the way D3D9 keeps DWORD states: 0xFFFFFFFF is the mask with every bit set (-1 as int).
int dwordOf(double number) {
    if (!std::isfinite(number)) return 0;
    double clamped = std::fmax(-2147483648.0, std::fmin(4294967295.0, number));
    return static_cast<int>(static_cast<std::uint32_t>(static_cast<std::int64_t>(clamped)));
}

template <class E>
E enumAt(double index, E count, E fallback) {
    int i = dwordOf(index);
    return i >= 0 && i < static_cast<int>(count) ? static_cast<E>(i) : fallback;
}

}  // namespace

StateValue defaultStateValue(RenderState state) {
    switch (state) {
    case RenderState::AlphaBlendEnable: case RenderState::SeparateAlphaBlendEnable: case RenderState::StencilEnable:
    case RenderState::TwoSidedStencilMode: case RenderState::ScissorTestEnable: case RenderState::AlphaTestEnable:
    case RenderState::SrgbWriteEnable: case RenderState::FogEnable: case RenderState::PointSpriteEnable:
        return false;
    case RenderState::FogColor: case RenderState::FogTableMode: case RenderState::FogVertexMode: case RenderState::ClipPlaneEnable:
        return 0;
    case RenderState::ShadeMode: return 2;  // D3DSHADE_GOURAUD
    case RenderState::FogStart: return 0.0f;
    case RenderState::FogEnd: case RenderState::FogDensity: case RenderState::PointSize: case RenderState::PointSizeMin: return 1.0f;
    case RenderState::PointSizeMax: return 64.0f;
    case RenderState::ClipPlane: return std::array<float, 4>{0, 0, 0, 0};
    case RenderState::ZEnable: case RenderState::ZWriteEnable: case RenderState::MultiSampleAntiAlias:
    case RenderState::DepthClipEnable:
        return true;
    case RenderState::SrcBlend: case RenderState::SrcBlendAlpha: return Blend::One;
    case RenderState::DestBlend: case RenderState::DestBlendAlpha: return Blend::Zero;
    case RenderState::BlendOp: case RenderState::BlendOpAlpha: return BlendFunction::Add;
    case RenderState::BlendFactor: return std::array<float, 4>{1, 1, 1, 1};
    case RenderState::ColorWriteEnable: return 15;
    case RenderState::MultiSampleMask: case RenderState::StencilMask: case RenderState::StencilWriteMask: return -1;
    case RenderState::StencilRef: case RenderState::AlphaRef: return 0;
    case RenderState::ZFunc: return CompareFunction::LessEqual;
    case RenderState::StencilFunc: case RenderState::CcwStencilFunc: case RenderState::AlphaFunc: return CompareFunction::Always;
    case RenderState::StencilPass: case RenderState::StencilFail: case RenderState::StencilZFail:
    case RenderState::CcwStencilPass: case RenderState::CcwStencilFail: case RenderState::CcwStencilZFail:
        return StencilOperation::Keep;
    case RenderState::CullMode: return CullMode::CullCounterClockwiseFace;
    case RenderState::FillMode: return FillMode::Solid;
    case RenderState::DepthBias: case RenderState::SlopeScaleDepthBias: return 0.0f;
    }
    return false;
}

StateValue stateValueFromCanonical(RenderState state, double number) {
    StateValue v = defaultStateValue(state);
    struct Convert {
        double n;
        StateValue operator()(bool) const { return n != 0; }
        StateValue operator()(int) const { return dwordOf(n); }
        StateValue operator()(float) const { return static_cast<float>(n); }
        StateValue operator()(Blend d) const { return enumAt(n, Blend(13), d); }
        StateValue operator()(BlendFunction d) const { return enumAt(n, BlendFunction(5), d); }
        StateValue operator()(CompareFunction d) const { return enumAt(n, CompareFunction(8), d); }
        StateValue operator()(StencilOperation d) const { return enumAt(n, StencilOperation(8), d); }
        StateValue operator()(CullMode d) const { return enumAt(n, CullMode(3), d); }
        StateValue operator()(FillMode d) const { return enumAt(n, FillMode(3), d); }
        StateValue operator()(std::array<float, 4>) const {
            float f = static_cast<float>(n);
            return std::array<float, 4>{f, f, f, f};
        }
    };
    return std::visit(Convert{number}, v);
}

StateValue stateValueFromD3D9(RenderState state, double number) {
    StateValue v = defaultStateValue(state);
    if (std::holds_alternative<Blend>(v)) {
        // D3DBLEND: ZERO=1 ... SRCALPHASAT=11, (BOTHSRCALPHA=12, BOTHINVSRCALPHA=13), BLENDFACTOR=14, INVBLENDFACTOR=15.
        int code = dwordOf(number);
        if (code >= 1 && code <= 11) return Blend(code - 1);
        if (code == 14) return Blend::BlendFactor;
        if (code == 15) return Blend::InverseBlendFactor;
        return v;
    }
    if (state == RenderState::ClipPlane) return stateValueFromCanonical(state, number);  // a float4 parameter's first value
    if (std::holds_alternative<std::array<float, 4>>(v)) {
        // A D3DCOLOR: 0xAARRGGBB.
        auto c = static_cast<std::uint32_t>(dwordOf(number));
        return std::array<float, 4>{((c >> 16) & 255) / 255.0f, ((c >> 8) & 255) / 255.0f, (c & 255) / 255.0f, ((c >> 24) & 255) / 255.0f};
    }
    bool enumerated = std::holds_alternative<BlendFunction>(v) || std::holds_alternative<CompareFunction>(v) ||
                      std::holds_alternative<StencilOperation>(v) || std::holds_alternative<CullMode>(v) ||
                      std::holds_alternative<FillMode>(v);
    // D3DBLENDOP, D3DCMPFUNC, D3DSTENCILOP, D3DCULL and D3DFILLMODE number their values from 1 in
    // the order of fxport's enums.
    if (enumerated) return dwordOf(number) >= 1 ? stateValueFromCanonical(state, dwordOf(number) - 1) : v;
    return stateValueFromCanonical(state, number);
}

void setSamplerStateFromD3D9(SamplerStateDesc& desc, SamplerStateField field, double number) {
    const int code = dwordOf(number);
    auto filter = [&](std::optional<TextureFilter>& f) {  // D3DTEXF_NONE 0, POINT 1, LINEAR 2, ANISOTROPIC 3 (and the quads: linear)
        if (code >= 0 && code <= 3) f = TextureFilter(code);
        else if (code >= 4 && code <= 7) f = TextureFilter::Linear;
    };
    auto address = [&](std::optional<TextureAddress>& a) {  // D3DTADDRESS_WRAP 1 ... MIRRORONCE 5
        if (code >= 1 && code <= 5) a = TextureAddress(code - 1);
    };
    switch (field) {
    case SamplerStateField::MinFilter: filter(desc.minFilter); break;
    case SamplerStateField::MagFilter: filter(desc.magFilter); break;
    case SamplerStateField::MipFilter: filter(desc.mipFilter); break;
    case SamplerStateField::AddressU: address(desc.addressU); break;
    case SamplerStateField::AddressV: address(desc.addressV); break;
    case SamplerStateField::AddressW: address(desc.addressW); break;
    case SamplerStateField::MaxAnisotropy: desc.maxAnisotropy = std::max(1, code); break;
    case SamplerStateField::MaxMipLevel: desc.maxMipLevel = std::max(0, code); break;
    case SamplerStateField::MipLodBias: desc.mipLodBias = static_cast<float>(number); break;
    }
}

}  // namespace fxport::xlate
