// Pass and sampler states decoded once (at technique compile) and applied by EffectPass::Apply().
#include "effect/pass_states.h"

#include <variant>

#include "device/pass_emulation.h"
#include "effect/effect_impl.h"
#include "fxport/graphics/graphics_device.h"
#include "device/sampler_filter.h"

namespace fxport {

namespace {

using xlate::RenderState;

Blend toBlend(xlate::Blend v) {
    switch (v) {
    case xlate::Blend::Zero: return Blend::Zero;
    case xlate::Blend::One: return Blend::One;
    case xlate::Blend::SourceColor: return Blend::SourceColor;
    case xlate::Blend::InverseSourceColor: return Blend::InverseSourceColor;
    case xlate::Blend::SourceAlpha: return Blend::SourceAlpha;
    case xlate::Blend::InverseSourceAlpha: return Blend::InverseSourceAlpha;
    case xlate::Blend::DestinationAlpha: return Blend::DestinationAlpha;
    case xlate::Blend::InverseDestinationAlpha: return Blend::InverseDestinationAlpha;
    case xlate::Blend::DestinationColor: return Blend::DestinationColor;
    case xlate::Blend::InverseDestinationColor: return Blend::InverseDestinationColor;
    case xlate::Blend::SourceAlphaSaturation: return Blend::SourceAlphaSaturation;
    case xlate::Blend::BlendFactor: return Blend::BlendFactor;
    case xlate::Blend::InverseBlendFactor: return Blend::InverseBlendFactor;
    }
    return Blend::One;
}

BlendFunction toBlendFunction(xlate::BlendFunction v) {
    switch (v) {
    case xlate::BlendFunction::Add: return BlendFunction::Add;
    case xlate::BlendFunction::Subtract: return BlendFunction::Subtract;
    case xlate::BlendFunction::ReverseSubtract: return BlendFunction::ReverseSubtract;
    case xlate::BlendFunction::Min: return BlendFunction::Min;
    case xlate::BlendFunction::Max: return BlendFunction::Max;
    }
    return BlendFunction::Add;
}

CompareFunction toCompare(xlate::CompareFunction v) {
    switch (v) {
    case xlate::CompareFunction::Never: return CompareFunction::Never;
    case xlate::CompareFunction::Less: return CompareFunction::Less;
    case xlate::CompareFunction::Equal: return CompareFunction::Equal;
    case xlate::CompareFunction::LessEqual: return CompareFunction::LessEqual;
    case xlate::CompareFunction::Greater: return CompareFunction::Greater;
    case xlate::CompareFunction::NotEqual: return CompareFunction::NotEqual;
    case xlate::CompareFunction::GreaterEqual: return CompareFunction::GreaterEqual;
    case xlate::CompareFunction::Always: return CompareFunction::Always;
    }
    return CompareFunction::Always;
}

StencilOperation toStencil(xlate::StencilOperation v) {
    switch (v) {
    case xlate::StencilOperation::Keep: return StencilOperation::Keep;
    case xlate::StencilOperation::Zero: return StencilOperation::Zero;
    case xlate::StencilOperation::Replace: return StencilOperation::Replace;
    case xlate::StencilOperation::IncrementSaturation: return StencilOperation::IncrementSaturation;
    case xlate::StencilOperation::DecrementSaturation: return StencilOperation::DecrementSaturation;
    case xlate::StencilOperation::Invert: return StencilOperation::Invert;
    case xlate::StencilOperation::Increment: return StencilOperation::Increment;
    case xlate::StencilOperation::Decrement: return StencilOperation::Decrement;
    }
    return StencilOperation::Keep;
}

CullMode toCull(xlate::CullMode v) {
    switch (v) {
    case xlate::CullMode::None: return CullMode::None;
    case xlate::CullMode::CullClockwiseFace: return CullMode::CullClockwiseFace;
    case xlate::CullMode::CullCounterClockwiseFace: return CullMode::CullCounterClockwiseFace;
    }
    return CullMode::CullCounterClockwiseFace;
}

// XNA has no point fill: D3D9's POINT draws as wireframe (as it did before typed states).
FillMode toFill(xlate::FillMode v) { return v == xlate::FillMode::Solid ? FillMode::Solid : FillMode::WireFrame; }

TextureAddressMode toAddress(xlate::TextureAddress a) {
    switch (a) {
    case xlate::TextureAddress::Wrap: return TextureAddressMode::Wrap;
    case xlate::TextureAddress::Mirror: return TextureAddressMode::Mirror;
    case xlate::TextureAddress::Clamp: return TextureAddressMode::Clamp;
    case xlate::TextureAddress::Border: return TextureAddressMode::Border;
    case xlate::TextureAddress::MirrorOnce: return TextureAddressMode::Mirror;
    }
    return TextureAddressMode::Wrap;
}

bool isLinear(xlate::TextureFilter f) { return f == xlate::TextureFilter::Linear || f == xlate::TextureFilter::Anisotropic; }

}  // namespace

void setRowValue(PassStateRow& row, const xlate::StateValue& value) {
    struct Set {
        PassStateRow& r;
        void operator()(bool v) const { r.flag = v; }
        void operator()(int v) const { r.integer = v; }
        void operator()(float v) const { r.number = v; }
        void operator()(xlate::Blend v) const { r.blend = toBlend(v); }
        void operator()(xlate::BlendFunction v) const { r.function = toBlendFunction(v); }
        void operator()(xlate::CompareFunction v) const { r.compare = toCompare(v); }
        void operator()(xlate::StencilOperation v) const { r.stencil = toStencil(v); }
        void operator()(xlate::CullMode v) const { r.cull = toCull(v); }
        void operator()(xlate::FillMode v) const { r.fill = toFill(v); }
        void operator()(const std::array<float, 4>& v) const {
            r.vector = Vector4(v[0], v[1], v[2], v[3]);
            r.factor = Color(r.vector);
        }
    };
    std::visit(Set{row}, value);
}

PassStates decodePassStates(const xlate::Pass& pass) {
    PassStates out;
    for (const xlate::StateAssignment& s : pass.states) {
        PassStateRow row;
        row.state = s.state;
        row.index = s.index;
        row.parameter = s.parameter;
        row.where = &s.where;
        if (s.parameter >= 0) {
            out.hasParameterRows = true;
            row.fromParameter = s.element;  // leaves the element index on the stack (none: 0)
            row.fromParameter.push_back({xlate::SelectorOp::Kind::IndexParameter, s.parameter});
        }
        else setRowValue(row, s.value);
        out.rows.push_back(row);
    }
    return out;
}

namespace {

Vector4 d3dColor(int argb) {  // a D3DCOLOR, 0xAARRGGBB
    const auto c = std::uint32_t(argb);
    return Vector4(float((c >> 16) & 255) / 255.0f, float((c >> 8) & 255) / 255.0f, float(c & 255) / 255.0f, float(c >> 24) / 255.0f);
}

FogMode fogMode(int d3dFogMode) { return d3dFogMode >= 1 && d3dFogMode <= 3 ? FogMode(d3dFogMode) : FogMode::None; }

}  // namespace

void applyPassStates(const PassStates& states, const Effect::Impl& e, GraphicsDevice& device) {
    // sRGB write and the D3D9 fixed-function states (alpha test, fog, points, clip planes, shade
    // mode) belong to the pass: off unless it turns them on (XNA 4's device has none of them, so
    // nothing else would ever turn them off); a program sets device.FixedFunction after Apply().
    // Texture stages no shader of the pass samples: the device keeps them for later passes (D3D9).
    for (const SamplerSlot& slot : states.textureStages) {
        if (slot.textureParameter >= 0 && e.textures[std::size_t(slot.textureParameter)])
            device.Textures[slot.unit] = e.textures[std::size_t(slot.textureParameter)];
        device.SamplerStates[slot.unit] = samplerStateOver(slot, e, device.SamplerStates[slot.unit]);
    }
    PassEmulation emulation;
    device.FixedFunction = FixedFunctionState{};
    if (states.rows.empty()) {
        setPassEmulation(device, emulation);
        return;
    }
    FixedFunctionState& fixed = device.FixedFunction;
    BlendState blend = device.BlendState;
    DepthStencilState depth = device.DepthStencilState;
    RasterizerState raster = device.RasterizerState;
    bool blendEnable = blend.blendingEnabled();
    bool separateAlpha = blend.AlphaSourceBlend != blend.ColorSourceBlend ||
                         blend.AlphaDestinationBlend != blend.ColorDestinationBlend ||
                         blend.AlphaBlendFunction != blend.ColorBlendFunction;
    bool blendTouched = false;
    PassStateRow fromParameter;
    for (const PassStateRow& literal : states.rows) {
        const PassStateRow* row = &literal;
        if (literal.parameter >= 0) {
            // The effect framework's parameter-driven state: the parameter holds the D3D9 value.
            fromParameter = literal;
            setRowValue(fromParameter, xlate::stateValueFromD3D9(literal.state, e.evaluateSelector(literal.fromParameter)));
            row = &fromParameter;
        }
        const PassStateRow& s = *row;
        switch (s.state) {
        case RenderState::AlphaBlendEnable:
            // XNA's BlendState has one enable; D3D10's BlendEnable[n > 0] is warned about by xlate.
            if (s.index == 0) blendEnable = s.flag, blendTouched = true;
            break;
        case RenderState::SrcBlend: blend.ColorSourceBlend = s.blend; blendTouched = true; break;
        case RenderState::DestBlend: blend.ColorDestinationBlend = s.blend; blendTouched = true; break;
        case RenderState::BlendOp: blend.ColorBlendFunction = s.function; blendTouched = true; break;
        case RenderState::SeparateAlphaBlendEnable: separateAlpha = s.flag; blendTouched = true; break;
        case RenderState::SrcBlendAlpha: blend.AlphaSourceBlend = s.blend; blendTouched = true; break;
        case RenderState::DestBlendAlpha: blend.AlphaDestinationBlend = s.blend; blendTouched = true; break;
        case RenderState::BlendOpAlpha: blend.AlphaBlendFunction = s.function; blendTouched = true; break;
        case RenderState::BlendFactor: blend.BlendFactor = s.factor; break;
        case RenderState::ColorWriteEnable: {
            auto mask = fxport::ColorWriteChannels(s.integer & 15);
            if (s.index == 0) blend.ColorWriteChannels = mask;
            if (s.index == 1) blend.ColorWriteChannels1 = mask;
            if (s.index == 2) blend.ColorWriteChannels2 = mask;
            if (s.index == 3) blend.ColorWriteChannels3 = mask;
            break;
        }
        case RenderState::MultiSampleMask: blend.MultiSampleMask = s.integer; break;
        case RenderState::ZEnable: depth.DepthBufferEnable = s.flag; break;
        case RenderState::ZWriteEnable: depth.DepthBufferWriteEnable = s.flag; break;
        case RenderState::ZFunc: depth.DepthBufferFunction = s.compare; break;
        case RenderState::StencilEnable: depth.StencilEnable = s.flag; break;
        case RenderState::StencilFunc: depth.StencilFunction = s.compare; break;
        case RenderState::StencilPass: depth.StencilPass = s.stencil; break;
        case RenderState::StencilFail: depth.StencilFail = s.stencil; break;
        case RenderState::StencilZFail: depth.StencilDepthBufferFail = s.stencil; break;
        case RenderState::StencilRef: depth.ReferenceStencil = s.integer; break;
        case RenderState::StencilMask: depth.StencilMask = s.integer; break;
        case RenderState::StencilWriteMask: depth.StencilWriteMask = s.integer; break;
        case RenderState::TwoSidedStencilMode: depth.TwoSidedStencilMode = s.flag; break;
        case RenderState::CcwStencilFunc: depth.CounterClockwiseStencilFunction = s.compare; break;
        case RenderState::CcwStencilPass: depth.CounterClockwiseStencilPass = s.stencil; break;
        case RenderState::CcwStencilFail: depth.CounterClockwiseStencilFail = s.stencil; break;
        case RenderState::CcwStencilZFail: depth.CounterClockwiseStencilDepthBufferFail = s.stencil; break;
        case RenderState::CullMode: raster.CullMode = s.cull; break;
        case RenderState::FillMode: raster.FillMode = s.fill; break;
        case RenderState::ScissorTestEnable: raster.ScissorTestEnable = s.flag; break;
        case RenderState::MultiSampleAntiAlias: raster.MultiSampleAntiAlias = s.flag; break;
        case RenderState::DepthBias: raster.DepthBias = s.number; break;
        case RenderState::SlopeScaleDepthBias: raster.SlopeScaleDepthBias = s.number; break;
        case RenderState::AlphaTestEnable: fixed.AlphaTestEnable = s.flag; break;
        case RenderState::AlphaFunc: fixed.AlphaFunction = s.compare; break;
        case RenderState::AlphaRef: fixed.ReferenceAlpha = s.integer; break;
        case RenderState::FogEnable: fixed.FogEnable = s.flag; break;
        case RenderState::FogColor: fixed.FogColor = d3dColor(s.integer); break;
        case RenderState::FogTableMode: fixed.FogTableMode = fogMode(s.integer); break;
        case RenderState::FogVertexMode: fixed.FogVertexMode = fogMode(s.integer); break;
        case RenderState::FogStart: fixed.FogStart = s.number; break;
        case RenderState::FogEnd: fixed.FogEnd = s.number; break;
        case RenderState::FogDensity: fixed.FogDensity = s.number; break;
        case RenderState::PointSize: fixed.PointSize = s.number; break;
        case RenderState::PointSizeMin: fixed.PointSizeMin = s.number; break;
        case RenderState::PointSizeMax: fixed.PointSizeMax = s.number; break;
        case RenderState::PointSpriteEnable: fixed.PointSpriteEnable = s.flag; break;
        case RenderState::ClipPlaneEnable: fixed.ClipPlaneEnable = std::uint32_t(s.integer) & 0x3Fu; break;
        case RenderState::ClipPlane:
            if (s.index >= 0 && s.index < int(fixed.ClipPlanes.size())) fixed.ClipPlanes[std::size_t(s.index)] = s.vector;
            break;
        case RenderState::ShadeMode: fixed.ShadeMode = s.integer == 1 ? ShadeMode::Flat : ShadeMode::Gouraud; break;
        case RenderState::SrgbWriteEnable:
            emulation.srgbWrite = s.flag;
            emulation.srgbWriteAt = s.where;
            emulation.srgbWriteReported = &e.reportedUnencodedSrgbWrite;
            break;
        case RenderState::DepthClipEnable:
            // Not honoured (XNA's RasterizerState has no depth clamp); xlate warns where it is
            // set to false.
            break;
        }
    }
    setPassEmulation(device, emulation);
    if (blendTouched) {
        if (!separateAlpha) {
            blend.AlphaSourceBlend = blend.ColorSourceBlend;
            blend.AlphaDestinationBlend = blend.ColorDestinationBlend;
            blend.AlphaBlendFunction = blend.ColorBlendFunction;
        }
        if (!blendEnable) {
            blend.ColorSourceBlend = blend.AlphaSourceBlend = Blend::One;
            blend.ColorDestinationBlend = blend.AlphaDestinationBlend = Blend::Zero;
            blend.ColorBlendFunction = blend.AlphaBlendFunction = BlendFunction::Add;
        }
    }
    device.BlendState = blend;
    device.DepthStencilState = depth;
    device.RasterizerState = raster;
}

SamplerOverride decodeSamplerState(const xlate::SamplerStateDesc& e) {
    SamplerOverride o;
    if (e.addressU) o.addressU = toAddress(*e.addressU);
    if (e.addressV) o.addressV = toAddress(*e.addressV);
    if (e.addressW) o.addressW = toAddress(*e.addressW);
    if (e.minFilter) {
        o.minLinear = isLinear(*e.minFilter);
        o.minAnisotropic = *e.minFilter == xlate::TextureFilter::Anisotropic;
    }
    if (e.magFilter) o.magLinear = isLinear(*e.magFilter);
    if (e.mipFilter) {
        o.useMipMaps = *e.mipFilter != xlate::TextureFilter::None;
        o.mipLinear = isLinear(*e.mipFilter);
    }
    o.maxAnisotropy = e.maxAnisotropy;
    o.maxMipLevel = e.maxMipLevel;
    o.mipLodBias = e.mipLodBias;
    if (e.borderColor) o.borderColor = Vector4((*e.borderColor)[0], (*e.borderColor)[1], (*e.borderColor)[2], (*e.borderColor)[3]);
    if (e.comparison) o.comparison = toCompare(*e.comparison);
    o.empty = !(e.addressU || e.addressV || e.addressW || e.minFilter || e.magFilter || e.mipFilter || e.maxAnisotropy ||
                e.maxMipLevel || e.mipLodBias || e.borderColor);
    return o;
}

SamplerState samplerStateOver(const SamplerSlot& slot, const Effect::Impl& effect, const SamplerState& device) {
    if (slot.fromParameters.empty()) return slot.state.over(device);
    xlate::SamplerStateDesc desc = slot.literal;
    for (const SamplerStateFromParameter& p : slot.fromParameters) xlate::setSamplerStateFromD3D9(desc, p.field, effect.evaluateSelector(p.read));
    return decodeSamplerState(desc).over(device);
}

SamplerState SamplerOverride::over(SamplerState s) const {
    // A shader's sampler either compares (sampler2DShadow in the GLSL) or not; GL leaves the
    // other combinations undefined, so every slot says which.
    s.UseComparison = comparison.has_value();
    if (comparison) s.ComparisonFunction = *comparison;
    if (empty) return s;
    if (addressU) s.AddressU = *addressU;
    if (addressV) s.AddressV = *addressV;
    if (addressW) s.AddressW = *addressW;
    if (minLinear || magLinear || mipLinear) {
        FilterParts parts = splitFilter(s.Filter);
        if (minLinear) parts.minLinear = *minLinear, parts.anisotropic = minAnisotropic;
        if (magLinear) parts.magLinear = *magLinear;
        if (mipLinear) parts.mipLinear = *mipLinear;
        s.Filter = joinFilter(parts);
    }
    if (useMipMaps) s.UseMipMaps = *useMipMaps;
    if (maxAnisotropy) s.MaxAnisotropy = *maxAnisotropy;
    if (maxMipLevel) s.MaxMipLevel = *maxMipLevel;
    if (mipLodBias) s.MipMapLevelOfDetailBias = *mipLodBias;
    if (borderColor) s.BorderColor = *borderColor;
    return s;
}

}  // namespace fxport
