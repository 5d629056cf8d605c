// EffectPass::Apply: what the D3D effect framework does at BeginPass/CommitChanges.
#include <algorithm>
#include <cstring>
#include <iostream>

#include "effect_impl.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/graphics_device.h"
#include "fxport/graphics/texture.h"

namespace fxport {

namespace {

using xlate::RenderState;

Blend toBlend(double v) {
    switch (xlate::Blend(int(v))) {
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

BlendFunction toBlendFunction(double v) {
    switch (xlate::BlendFunction(int(v))) {
    case xlate::BlendFunction::Add: return BlendFunction::Add;
    case xlate::BlendFunction::Subtract: return BlendFunction::Subtract;
    case xlate::BlendFunction::ReverseSubtract: return BlendFunction::ReverseSubtract;
    case xlate::BlendFunction::Min: return BlendFunction::Min;
    case xlate::BlendFunction::Max: return BlendFunction::Max;
    }
    return BlendFunction::Add;
}

CompareFunction toCompare(double v) {
    switch (xlate::CompareFunction(int(v))) {
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

StencilOperation toStencil(double v) {
    switch (xlate::StencilOperation(int(v))) {
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

CullMode toCull(double v) {
    switch (xlate::CullMode(int(v))) {
    case xlate::CullMode::None: return CullMode::None;
    case xlate::CullMode::CullClockwiseFace: return CullMode::CullClockwiseFace;
    case xlate::CullMode::CullCounterClockwiseFace: return CullMode::CullCounterClockwiseFace;
    }
    return CullMode::CullCounterClockwiseFace;
}

// The first number a parameter holds (for `AlphaRef = <AlphaReference>;` style states and shader
// selectors).
double parameterNumber(const Effect::Impl& e, int index, int element) {
    const xlate::Parameter& p = e.outline.parameters[std::size_t(index)];
    if (p.offset < 0) return p.defaultValue.empty() ? 0.0 : p.defaultValue[0];
    const std::vector<std::uint8_t>& shadow = e.blocks[std::size_t(p.block)].shadow;
    int at = Effect::Impl::byteOffset(p, element, 0, 0);
    if (at < 0 || std::size_t(at) + 4 > shadow.size()) return 0;
    if (p.type == xlate::ParameterType::Float) {
        float f;
        std::memcpy(&f, &shadow[std::size_t(at)], 4);
        return f;
    }
    std::int32_t n;
    std::memcpy(&n, &shadow[std::size_t(at)], 4);
    return n;
}

double stateValue(const Effect::Impl& e, const xlate::StateAssignment& s, int component = 0) {
    if (s.parameter.empty()) return s.value[std::size_t(component)];
    auto it = e.parameterIndex.find(s.parameter);
    return it == e.parameterIndex.end() ? 0.0 : parameterNumber(e, it->second, 0);
}

// D3D9 keeps AlphaBlendEnable, SrcBlend, DestBlend ... as separate states; XNA's BlendState has
// no "enable". Rebuild the D3D9 view from the device's state, apply the pass's rows, fold back.
void applyStates(const Effect::Impl& e, const std::vector<xlate::StateAssignment>& rows, GraphicsDevice& device) {
    if (rows.empty()) return;
    BlendState blend = device.BlendState;
    DepthStencilState depth = device.DepthStencilState;
    RasterizerState raster = device.RasterizerState;
    bool blendEnable = blend.blendingEnabled();
    bool separateAlpha = blend.AlphaSourceBlend != blend.ColorSourceBlend ||
                         blend.AlphaDestinationBlend != blend.ColorDestinationBlend ||
                         blend.AlphaBlendFunction != blend.ColorBlendFunction;
    bool blendTouched = false;
    for (const xlate::StateAssignment& s : rows) {
        double v = stateValue(e, s);
        switch (s.state) {
        case RenderState::AlphaBlendEnable: blendEnable = v != 0; blendTouched = true; break;
        case RenderState::SrcBlend: blend.ColorSourceBlend = toBlend(v); blendTouched = true; break;
        case RenderState::DestBlend: blend.ColorDestinationBlend = toBlend(v); blendTouched = true; break;
        case RenderState::BlendOp: blend.ColorBlendFunction = toBlendFunction(v); blendTouched = true; break;
        case RenderState::SeparateAlphaBlendEnable: separateAlpha = v != 0; blendTouched = true; break;
        case RenderState::SrcBlendAlpha: blend.AlphaSourceBlend = toBlend(v); blendTouched = true; break;
        case RenderState::DestBlendAlpha: blend.AlphaDestinationBlend = toBlend(v); blendTouched = true; break;
        case RenderState::BlendOpAlpha: blend.AlphaBlendFunction = toBlendFunction(v); blendTouched = true; break;
        case RenderState::BlendFactor:
            blend.BlendFactor = Color(Vector4(float(s.value[0]), float(s.value[1]), float(s.value[2]), float(s.value[3])));
            break;
        case RenderState::ColorWriteEnable: {
            auto mask = fxport::ColorWriteChannels(int(v) & 15);
            if (s.index == 0) blend.ColorWriteChannels = mask;
            if (s.index == 1) blend.ColorWriteChannels1 = mask;
            if (s.index == 2) blend.ColorWriteChannels2 = mask;
            if (s.index == 3) blend.ColorWriteChannels3 = mask;
            break;
        }
        case RenderState::MultiSampleMask: blend.MultiSampleMask = int(v); break;
        case RenderState::ZEnable: depth.DepthBufferEnable = v != 0; break;
        case RenderState::ZWriteEnable: depth.DepthBufferWriteEnable = v != 0; break;
        case RenderState::ZFunc: depth.DepthBufferFunction = toCompare(v); break;
        case RenderState::StencilEnable: depth.StencilEnable = v != 0; break;
        case RenderState::StencilFunc: depth.StencilFunction = toCompare(v); break;
        case RenderState::StencilPass: depth.StencilPass = toStencil(v); break;
        case RenderState::StencilFail: depth.StencilFail = toStencil(v); break;
        case RenderState::StencilZFail: depth.StencilDepthBufferFail = toStencil(v); break;
        case RenderState::StencilRef: depth.ReferenceStencil = int(v); break;
        case RenderState::StencilMask: depth.StencilMask = int(v); break;
        case RenderState::StencilWriteMask: depth.StencilWriteMask = int(v); break;
        case RenderState::TwoSidedStencilMode: depth.TwoSidedStencilMode = v != 0; break;
        case RenderState::CcwStencilFunc: depth.CounterClockwiseStencilFunction = toCompare(v); break;
        case RenderState::CcwStencilPass: depth.CounterClockwiseStencilPass = toStencil(v); break;
        case RenderState::CcwStencilFail: depth.CounterClockwiseStencilFail = toStencil(v); break;
        case RenderState::CcwStencilZFail: depth.CounterClockwiseStencilDepthBufferFail = toStencil(v); break;
        case RenderState::CullMode: raster.CullMode = toCull(v); break;
        case RenderState::FillMode:
            raster.FillMode = xlate::FillMode(int(v)) == xlate::FillMode::Solid ? FillMode::Solid : FillMode::WireFrame;
            break;
        case RenderState::ScissorTestEnable: raster.ScissorTestEnable = v != 0; break;
        case RenderState::MultiSampleAntiAlias: raster.MultiSampleAntiAlias = v != 0; break;
        case RenderState::DepthBias: raster.DepthBias = float(v); break;
        case RenderState::SlopeScaleDepthBias: raster.SlopeScaleDepthBias = float(v); break;
        case RenderState::DepthClipEnable:
        case RenderState::AlphaTestEnable:
        case RenderState::AlphaFunc:
        case RenderState::AlphaRef:
        case RenderState::SrgbWriteEnable:
            // No GL core equivalent that the shader does not have to do itself; xlate warned when
            // it compiled the effect (these are listed in CompiledEffect::diagnostics).
            break;
        }
    }
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

// The effect's sampler_state over the device's: only what the effect specified changes.
SamplerState mergeSampler(SamplerState s, const xlate::SamplerStateDesc& e) {
    auto address = [](xlate::TextureAddress a) {
        switch (a) {
        case xlate::TextureAddress::Wrap: return TextureAddressMode::Wrap;
        case xlate::TextureAddress::Mirror: return TextureAddressMode::Mirror;
        case xlate::TextureAddress::Clamp: return TextureAddressMode::Clamp;
        case xlate::TextureAddress::Border: return TextureAddressMode::Border;
        case xlate::TextureAddress::MirrorOnce: return TextureAddressMode::Mirror;
        }
        return TextureAddressMode::Wrap;
    };
    if (e.addressU) s.AddressU = address(*e.addressU);
    if (e.addressV) s.AddressV = address(*e.addressV);
    if (e.addressW) s.AddressW = address(*e.addressW);
    if (e.minFilter || e.magFilter || e.mipFilter) {
        bool anisotropic = s.Filter == TextureFilter::Anisotropic;
        bool minL = true, magL = true, mipL = true;
        switch (s.Filter) {
        case TextureFilter::Linear: case TextureFilter::Anisotropic: break;
        case TextureFilter::Point: minL = magL = mipL = false; break;
        case TextureFilter::LinearMipPoint: mipL = false; break;
        case TextureFilter::PointMipLinear: minL = magL = false; break;
        case TextureFilter::MinLinearMagPointMipLinear: magL = false; break;
        case TextureFilter::MinLinearMagPointMipPoint: magL = mipL = false; break;
        case TextureFilter::MinPointMagLinearMipLinear: minL = false; break;
        case TextureFilter::MinPointMagLinearMipPoint: minL = mipL = false; break;
        }
        auto linear = [](xlate::TextureFilter f) { return f == xlate::TextureFilter::Linear || f == xlate::TextureFilter::Anisotropic; };
        if (e.minFilter) minL = linear(*e.minFilter), anisotropic = *e.minFilter == xlate::TextureFilter::Anisotropic;
        if (e.magFilter) magL = linear(*e.magFilter);
        if (e.mipFilter) {
            s.UseMipMaps = *e.mipFilter != xlate::TextureFilter::None;
            mipL = linear(*e.mipFilter);
        }
        if (anisotropic) s.Filter = TextureFilter::Anisotropic;
        else if (minL && magL) s.Filter = mipL ? TextureFilter::Linear : TextureFilter::LinearMipPoint;
        else if (!minL && !magL) s.Filter = mipL ? TextureFilter::PointMipLinear : TextureFilter::Point;
        else if (minL) s.Filter = mipL ? TextureFilter::MinLinearMagPointMipLinear : TextureFilter::MinLinearMagPointMipPoint;
        else s.Filter = mipL ? TextureFilter::MinPointMagLinearMipLinear : TextureFilter::MinPointMagLinearMipPoint;
    }
    if (e.maxAnisotropy) s.MaxAnisotropy = *e.maxAnisotropy;
    if (e.maxMipLevel) s.MaxMipLevel = *e.maxMipLevel;
    if (e.mipLodBias) s.MipMapLevelOfDetailBias = *e.mipLodBias;
    if (e.borderColor) s.BorderColor = Vector4((*e.borderColor)[0], (*e.borderColor)[1], (*e.borderColor)[2], (*e.borderColor)[3]);
    return s;
}

// Evaluates `VertexShader = (VSArray[VSIndices[ShaderIndex]])` style selectors.
int chooseShader(const Effect::Impl& e, const xlate::ShaderChoice& choice, const std::string& technique, const std::string& pass) {
    if (choice.selector.empty()) return choice.shaders[0];
    std::vector<int> stack;
    for (const xlate::SelectorOp& op : choice.selector) {
        switch (op.kind) {
        case xlate::SelectorOp::Kind::PushConstant: stack.push_back(op.value); break;
        case xlate::SelectorOp::Kind::PushParameter: stack.push_back(int(parameterNumber(e, op.value, 0))); break;
        case xlate::SelectorOp::Kind::IndexParameter: {
            int index = stack.empty() ? 0 : stack.back();
            if (!stack.empty()) stack.pop_back();
            stack.push_back(int(parameterNumber(e, op.value, index)));
            break;
        }
        }
    }
    int pick = stack.empty() ? 0 : stack.back();
    if (pick < 0 || pick >= int(choice.shaders.size()))
        throw InvalidOperation(e.displayName + " technique '" + technique + "' pass '" + pass + "': the shader-array index evaluates to " + std::to_string(pick) +
                               ", outside 0.." + std::to_string(choice.shaders.size() - 1));
    return choice.shaders[std::size_t(pick)];
}

}  // namespace

void Effect::Impl::uploadRead(const std::vector<BlockReads>& reads) {
    for (const BlockReads& r : reads) {
        Block& b = blocks[std::size_t(r.block)];
        if (b.dirtyEnd <= b.dirtyBegin || !b.buffer) continue;
        // Walk the dirty range: send what a read range covers, remember the hull of the rest.
        int leftBegin = INT_MAX, leftEnd = 0, cursor = b.dirtyBegin;
        for (const auto& [begin, end] : r.ranges) {
            int lo = std::max(begin, cursor), hi = std::min(end, b.dirtyEnd);
            if (lo >= hi) continue;
            if (lo > cursor) leftBegin = std::min(leftBegin, cursor), leftEnd = lo;
            glNamedBufferSubData(b.buffer, lo, hi - lo, b.shadow.data() + lo);
            constantBytesUploaded += std::uint64_t(hi - lo);
            ++constantUploads;
            cursor = hi;
        }
        if (cursor < b.dirtyEnd) leftBegin = std::min(leftBegin, cursor), leftEnd = b.dirtyEnd;
        b.dirtyBegin = leftBegin;
        b.dirtyEnd = leftEnd;
    }
}

void EffectPass::Apply() {
    if (effect_->IsDisposed()) throw InvalidOperation("EffectPass '" + name_ + "'.Apply(): the effect was disposed");
    // A derived effect (BasicEffect ...) may redirect to the pass of the permutation it needs.
    effect_->OnApply(*this).applyThis();
}

void EffectPass::applyThis() {
    if (effect_->IsDisposed()) throw InvalidOperation("EffectPass '" + name_ + "'.Apply(): the effect was disposed");
    Effect::Impl& e = effect_->impl();
    GraphicsDevice& device = effect_->device();
    GraphicsDevice::Impl& d = device.impl();
    // The first Apply of a technique compiles it (xlate, cached) and links its programs.
    const Effect::Impl::TechniqueCode& code = e.ensureCompiled(technique_, d);
    const xlate::CompiledEffect& compiled = *code.code->effect;
    const xlate::Technique& technique = compiled.techniques[std::size_t(code.index)];
    const xlate::Pass& pass = technique.passes[std::size_t(pass_)];
    if (!pass.valid) {
        std::string where = e.displayName + " technique '" + technique.name + "' pass '" + pass.name + "'";
        std::string why;
        for (const xlate::Diagnostic& diag : compiled.diagnostics) why += "\n  " + diag.format();
        throw InvalidOperation(where + " cannot run: the compiler rejected it" + why);
    }

    const xlate::ShaderChoice* choices[kStageCount] = {&pass.vertexShader, &pass.pixelShader, &pass.geometryShader};
    for (int stage = 0; stage < kStageCount; ++stage) {
        const xlate::ShaderChoice& choice = *choices[stage];
        if (choice.shaders.empty()) {
            // D3D: a stage the pass does not assign keeps its shader -- except the geometry stage,
            // which a pass with a vertex shader and none of its own runs without.
            if (stage == 2 && !pass.vertexShader.shaders.empty()) d.shaders[2] = nullptr;
            continue;
        }
        std::size_t shader = std::size_t(chooseShader(e, choice, technique.name, pass.name));
        const ShaderProgram& program = code.code->programs[shader];
        d.shaders[std::size_t(stage)] = &program;
        // Only the blocks this shader reads, and of those only the bytes it reads; changes to
        // other constants stay dirty until a shader that reads them is applied.
        const std::vector<Effect::Impl::BlockReads>& reads = code.code->reads[shader];
        e.uploadRead(reads);
        for (const Effect::Impl::BlockReads& r : reads) {
            const Effect::Impl::Block& block = e.blocks[std::size_t(r.block)];
            if (block.buffer) d.wantedUniformBuffers[std::size_t(uniformBindingFor(stage, block.binding))] = block.buffer;
        }
        for (const xlate::SamplerBinding& sampler : program.shader->samplers) {
            if (sampler.unit < 0 || sampler.unit >= kMaxTextureSlots) continue;
            if (!sampler.textureParameter.empty()) {
                auto it = e.parameterIndex.find(sampler.textureParameter);
                // A texture parameter left unset does not clear the slot: hosts that feed
                // Textures[n] directly (as the tutorials do) keep working.
                if (it != e.parameterIndex.end() && e.textures[std::size_t(it->second)])
                    device.Textures[sampler.unit] = e.textures[std::size_t(it->second)];
            }
            device.SamplerStates[sampler.unit] = mergeSampler(device.SamplerStates[sampler.unit], sampler.state);
        }
    }
    // A stage the pass leaves alone keeps its shader (D3D9). When that is one of this effect's (an
    // earlier pass's vertex shader under a pixel-shader-only pass), it reads this effect's
    // constants too: send what changed of those.
    for (int stage = 0; stage < kStageCount; ++stage)
        if (choices[stage]->shaders.empty() && d.shaders[std::size_t(stage)])
            if (const auto* reads = e.readsOf(d.shaders[std::size_t(stage)])) e.uploadRead(*reads);
    applyStates(e, pass.states, device);
    d.passApplied = true;
}

}  // namespace fxport
