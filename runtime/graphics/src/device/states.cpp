// XNA's preset state objects, value for value.
#include "fxport/graphics/blend_state.h"
#include "fxport/graphics/depth_stencil_state.h"
#include "fxport/graphics/rasterizer_state.h"
#include "fxport/graphics/sampler_state.h"

namespace fxport {

namespace {

BlendState blend(Blend source, Blend destination) {
    BlendState s;
    s.ColorSourceBlend = s.AlphaSourceBlend = source;
    s.ColorDestinationBlend = s.AlphaDestinationBlend = destination;
    return s;
}

DepthStencilState depth(bool enable, bool write) {
    DepthStencilState s;
    s.DepthBufferEnable = enable;
    s.DepthBufferWriteEnable = write;
    return s;
}

RasterizerState cull(CullMode mode) {
    RasterizerState s;
    s.CullMode = mode;
    return s;
}

SamplerState sampler(TextureFilter filter, TextureAddressMode address) {
    SamplerState s;
    s.Filter = filter;
    s.AddressU = s.AddressV = s.AddressW = address;
    return s;
}

}  // namespace

bool BlendState::blendingEnabled() const {
    return !(ColorSourceBlend == Blend::One && ColorDestinationBlend == Blend::Zero &&
             ColorBlendFunction == BlendFunction::Add && AlphaSourceBlend == Blend::One &&
             AlphaDestinationBlend == Blend::Zero && AlphaBlendFunction == BlendFunction::Add);
}

const BlendState BlendState::Additive = blend(Blend::SourceAlpha, Blend::One);
const BlendState BlendState::AlphaBlend = blend(Blend::One, Blend::InverseSourceAlpha);
const BlendState BlendState::NonPremultiplied = blend(Blend::SourceAlpha, Blend::InverseSourceAlpha);
const BlendState BlendState::Opaque = blend(Blend::One, Blend::Zero);

const DepthStencilState DepthStencilState::Default = depth(true, true);
const DepthStencilState DepthStencilState::DepthRead = depth(true, false);
const DepthStencilState DepthStencilState::None = depth(false, false);

const RasterizerState RasterizerState::CullClockwise = cull(CullMode::CullClockwiseFace);
const RasterizerState RasterizerState::CullCounterClockwise = cull(CullMode::CullCounterClockwiseFace);
const RasterizerState RasterizerState::CullNone = cull(CullMode::None);

const SamplerState SamplerState::AnisotropicClamp = sampler(TextureFilter::Anisotropic, TextureAddressMode::Clamp);
const SamplerState SamplerState::AnisotropicWrap = sampler(TextureFilter::Anisotropic, TextureAddressMode::Wrap);
const SamplerState SamplerState::LinearClamp = sampler(TextureFilter::Linear, TextureAddressMode::Clamp);
const SamplerState SamplerState::LinearWrap = sampler(TextureFilter::Linear, TextureAddressMode::Wrap);
const SamplerState SamplerState::PointClamp = sampler(TextureFilter::Point, TextureAddressMode::Clamp);
const SamplerState SamplerState::PointWrap = sampler(TextureFilter::Point, TextureAddressMode::Wrap);

}  // namespace fxport
