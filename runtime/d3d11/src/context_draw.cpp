// The immediate context's draws and dispatches (context.cpp has the Set calls): the recorded
// bindings are copied into the device core -- targets, the decoded states, every stage's shader,
// each cbuffer slot to the GL binding of the block it feeds, each t#/s# pair to the texture unit the
// translation samples it on, buffer SRVs and UAVs to the core's storage slots, the input slots to
// vertex streams -- and the core draws (or dispatches), calling GL only for what differs.
#include <algorithm>
#include <cmath>

#include "context.h"
#include "device/pass_emulation.h"
#include "guarded.h"

namespace fxport::d3d11 {

namespace {

PrimitiveType primitiveOf(D3D11_PRIMITIVE_TOPOLOGY t, bool& ok) {
    ok = true;
    if (t >= D3D11_PRIMITIVE_TOPOLOGY_1_CONTROL_POINT_PATCHLIST && t <= D3D11_PRIMITIVE_TOPOLOGY_32_CONTROL_POINT_PATCHLIST)
        return PrimitiveType::PointList;  // a patch list: DrawArguments::controlPoints says so
    switch (t) {
    case D3D11_PRIMITIVE_TOPOLOGY_POINTLIST: return PrimitiveType::PointList;
    case D3D11_PRIMITIVE_TOPOLOGY_LINELIST: return PrimitiveType::LineList;
    case D3D11_PRIMITIVE_TOPOLOGY_LINESTRIP: return PrimitiveType::LineStrip;
    case D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST: return PrimitiveType::TriangleList;
    case D3D11_PRIMITIVE_TOPOLOGY_TRIANGLESTRIP: return PrimitiveType::TriangleStrip;
    default: ok = false; return PrimitiveType::TriangleList;
    }
}

Color colorOf(const FLOAT f[4]) {
    auto byte = [](float v) { return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
    return Color(byte(f[0]), byte(f[1]), byte(f[2]), byte(f[3]));
}

// Whether a texture of `kind` is what a shader's texture of `wanted` samples, and the words for
// either in a message (arrays as their elements: xlate's kinds do not mark arrays).
const char* dimensionOf(xlate::TextureKind kind) {
    switch (kind) {
    case xlate::TextureKind::Texture1D: return "1D";
    case xlate::TextureKind::Texture3D: return "3D";
    case xlate::TextureKind::TextureCube: return "cube";
    default: return "2D";
    }
}
const char* dimensionOf(fxport::Texture::Kind kind) {
    switch (kind) {
    case fxport::Texture::Kind::Texture1D:
    case fxport::Texture::Kind::Texture1DArray: return "1D";
    case fxport::Texture::Kind::Texture3D: return "3D";
    case fxport::Texture::Kind::TextureCube:
    case fxport::Texture::Kind::TextureCubeArray: return "cube";
    default: return "2D";
    }
}

// D3D's debug layer refuses a view of another dimension than the shader's texture (GL would read
// black): the t# register and both dimensions.
void checkViewDimension(const ShaderBindings& bindings, int slot, const fxport::Texture& viewed) {
    for (const ResourceBinding& t : bindings.textures)
        if (t.slot == slot && std::string(dimensionOf(t.kind)) != dimensionOf(viewed.kind()))
            throw InvalidOperation("t" + std::to_string(slot) + " holds a view of a " + dimensionOf(viewed.kind()) + " texture where the shader's '" +
                                   t.name + "' is a " + dimensionOf(t.kind) + " texture");
}

}  // namespace

void Context::bindStage(int stage, const ShaderBindings& bindings, const Stage& s) {
    GraphicsDevice& core = device_->core();
    for (const CbufferBinding& c : bindings.cbuffers) {
        const Buffer* b = std::size_t(c.slot) < s.constantBuffers.size() ? s.constantBuffers[std::size_t(c.slot)].Get() : nullptr;
        if (b && b->desc.ByteWidth < UINT(c.size))
            throw InvalidOperation("cbuffer '" + c.name + "' (b" + std::to_string(c.slot) + ") needs " + std::to_string(c.size) +
                                   " bytes; the buffer bound there has " + std::to_string(b->desc.ByteWidth));
        if (b && !(b->desc.BindFlags & D3D11_BIND_CONSTANT_BUFFER))
            throw InvalidOperation("the buffer at b" + std::to_string(c.slot) + " was not made with D3D11_BIND_CONSTANT_BUFFER");
        core::setUniformBuffer(core, stage, c.blockBinding, b ? b->gpu.get() : nullptr);
    }
    for (const SamplerUnit& u : bindings.units) {
        if (u.glUnit < 0 || u.glUnit >= kMaxTextureSlots) continue;
        const ShaderResourceView* v =
            u.textureSlot >= 0 && std::size_t(u.textureSlot) < s.views.size() ? s.views[std::size_t(u.textureSlot)].Get() : nullptr;
        if (v && !v->sampled())
            throw InvalidOperation("t" + std::to_string(u.textureSlot) + " holds a view of a buffer where the shader samples a texture");
        if (v) checkViewDimension(bindings, u.textureSlot, *v->sampled());
        core.Textures[u.glUnit] = v ? v->sampled() : nullptr;
        const SamplerState* st =
            u.samplerSlot >= 0 && std::size_t(u.samplerSlot) < s.samplers.size() ? s.samplers[std::size_t(u.samplerSlot)].Get() : nullptr;
        core.SamplerStates[u.glUnit] = st ? st->state : defaultSampler_;
    }
}

namespace {

// D3D's rule: a structured view's StructureByteStride is the size of the shader's element (D3D's
// own layout: structured buffers are tightly packed, and fxport's translation reads them so). A
// buffer of another stride is refused, not misread (D3D's debug layer rejects the same draw).
void checkStride(const std::string& use, const xlate::StorageBinding& b, const Buffer& buffer) {
    if (!(buffer.desc.MiscFlags & D3D11_RESOURCE_MISC_BUFFER_STRUCTURED)) return;  // raw: 4-byte words
    if (b.stride <= 0 || UINT(b.stride) == buffer.desc.StructureByteStride) return;
    throw InvalidOperation(use + ": its elements are " + std::to_string(b.stride) + " bytes, the buffer's StructureByteStride is " +
                           std::to_string(buffer.desc.StructureByteStride) + " (D3D11 requires the shader's element size)");
}

}  // namespace

void Context::bindStorage(const char* call, const core::ShaderCode& code, const Stage& s, const UavSlots* uavs) {
    GraphicsDevice& core = device_->core();
    for (const xlate::StorageBinding& b : code.shader().storage) {
        const std::string reg = std::string(1, b.registerClass) + std::to_string(b.slot);
        const std::string use = std::string(call) + ": " + code.shader().entryPoint + " uses '" + b.name + "' (" + reg + ")";
        const bool image = b.kind == xlate::StorageKind::Image;
        const bool typed = b.kind == xlate::StorageKind::TexelBuffer || b.kind == xlate::StorageKind::ImageBuffer;  // Buffer<T>, RWBuffer<T>
        if (b.registerClass == 't') {
            const ShaderResourceView* v = b.slot >= 0 && std::size_t(b.slot) < s.views.size() ? s.views[std::size_t(b.slot)].Get() : nullptr;
            if (!v || !v->buffer || typed != (v->typed != nullptr))
                throw InvalidOperation(use + ", but no shader-resource view of a " + (typed ? "buffer with a Format (a typed view)" : "structured or raw buffer") +
                                       " is set there");
            if (typed) {
                core::setTexelBuffer(core, false, b.slot, v->typed.get());
                continue;
            }
            checkStride(use, b, *v->buffer);
            core::setStorageBuffer(core, false, b.slot, v->buffer->gpu.get(), v->range.offset, v->range.bytes);
            continue;
        }
        const UnorderedAccessView* v = uavs && b.slot >= 0 && std::size_t(b.slot) < uavs->size() ? (*uavs)[std::size_t(b.slot)].Get() : nullptr;
        if (!v)
            throw InvalidOperation(use + ", but no unordered-access view is set there" +
                                   (uavs ? std::string(" (CSSetUnorderedAccessViews, or OMSetRenderTargetsAndUnorderedAccessViews for a pixel shader)")
                                        : std::string(" (fxport binds UAVs for pixel and compute shaders only)")));
        const bool ofTexture = v->texture || v->image;
        if (image != ofTexture)
            throw InvalidOperation(use + ", a " + (image ? "texture" : "buffer") + ", but the view there is of a " + (ofTexture ? "texture" : "buffer"));
        if (typed != (v->typed != nullptr))
            throw InvalidOperation(use + (typed ? ", a typed buffer (RWBuffer<T>), but the view there has no Format" : ", but the view there is a typed one (RWBuffer<T>)"));
        if (typed) {
            core::setTexelBuffer(core, true, b.slot, v->typed.get());
        } else if (image && v->image) {
            core.SetUnorderedAccess(b.slot, v->image.get());
        } else if (image) {
            core.SetUnorderedAccess(b.slot, v->formatView ? v->formatView.get() : v->texture->colour.get());
        } else {
            checkStride(use, b, *v->buffer);
            core::setStorageBuffer(core, true, b.slot, v->buffer->gpu.get(), v->range.offset, v->range.bytes);
        }
    }
}

bool Context::prepare(const char* call) {
    const std::string at = std::string(call) + ": ";
    if (!effectPass_ && !vertexShader_) {
        note(at + "no vertex shader set; nothing drawn");
        return false;
    }
    static const std::vector<xlate::VertexInput> none;
    const auto& inputs = effectPass_ ? none : vertexShader_->code->shader().inputs;
    const bool readsVertices = std::any_of(inputs.begin(), inputs.end(), [](const auto& in) { return in.semantic.rfind("SV_", 0) != 0; });
    if (!layout_ && readsVertices) {
        note(at + "no input layout set and the vertex shader has inputs; nothing drawn");
        return false;
    }
    std::vector<RenderTargetBinding> colour;
    for (const auto& t : targets_)
        if (t) colour.emplace_back(&t->target());
    GraphicsDevice& core = device_->core();
    core::DepthBuffer* depth = depthView_ ? &depthView_->buffer() : nullptr;
    const bool depthOnly = colour.empty();  // a shadow-map pass: depth-stencil view, no render target
    // Stream output draws with no target at all (ParticlesGS's advance pass): what the rasteriser
    // makes of it goes to a 1 x 1 scratch target that nothing reads.
    const bool streaming = std::any_of(soTargets_.begin(), soTargets_.end(), [](const ComPtr<Buffer>& b) { return bool(b); });
    if (depthOnly && !depth && !streaming) {
        note(at + "no render target or depth-stencil view bound; nothing drawn");
        return false;
    }
    if (depthOnly) colour.emplace_back(&scratchTarget(depth ? depth->width() : 1, depth ? depth->height() : 1));
    const RenderTarget2D& first = *static_cast<RenderTarget2D*>(colour[0].RenderTarget);
    if (depth && (depth->width() != first.Width() || depth->height() != first.Height())) {
        note(at + "the depth-stencil view is " + std::to_string(depth->width()) + "x" + std::to_string(depth->height()) +
             ", the render target " + std::to_string(first.Width()) + "x" + std::to_string(first.Height()) + "; nothing drawn");
        return false;
    }
    core::setTargets(core, colour, depth);

    core.BlendState = blend_ ? blend_->state : defaultBlend_;
    core.BlendState.BlendFactor = colorOf(blendFactor_);
    core.BlendState.MultiSampleMask = int(sampleMask_);
    if (depthOnly || (!effectPass_ && !pixelShader_)) {  // no colour is written (D3D: no target, or no pixel shader)
        core.BlendState.ColorWriteChannels = core.BlendState.ColorWriteChannels1 = ColorWriteChannels::None;
        core.BlendState.ColorWriteChannels2 = core.BlendState.ColorWriteChannels3 = ColorWriteChannels::None;
    }
    core.DepthStencilState = depthStencil_ ? depthStencil_->state : defaultDepthStencil_;
    core.DepthStencilState.ReferenceStencil = int(stencilRef_);
    core.RasterizerState = rasterizer_ ? rasterizer_->state : defaultRasterizer_;
    setViewports(core);

    if (effectPass_) {
        // The pass binds its shaders, constants and textures and sets the states it names over
        // the context's (Effects11's Apply does the same through the context's Set calls).
        effectPass_->Apply();
        // SetPixelShader(NULL): D3D runs no pixel shader (depth only; a stream-output pass).
        if (core::fillEmptyPixelStage(core, *emptyPixelShader().code)) {
            core.BlendState.ColorWriteChannels = core.BlendState.ColorWriteChannels1 = ColorWriteChannels::None;
            core.BlendState.ColorWriteChannels2 = core.BlendState.ColorWriteChannels3 = ColorWriteChannels::None;
        }
    } else {
        auto codeOf = [](const auto& shader) { return shader ? shader->code.get() : nullptr; };
        const PixelShader& pixel = pixelShader_ ? *pixelShader_.Get() : emptyPixelShader();  // D3D draws depth without one
        const core::ShaderCode* stages[5] = {vertexShader_->code.get(), pixel.code.get(), codeOf(geometryShader_),
                                             codeOf(hullShader_), codeOf(domainShader_)};
        // A geometry shader made with stream output from vertex-shader bytecode (D3D's "null" one)
        // is the vertex shader capturing its own outputs: it runs in the vertex stage.
        if (stages[2] && stages[2]->shader().profile.stage == xlate::ShaderStage::Vertex) {
            if (stages[2]->shader().glsl != stages[0]->shader().glsl) {
                note(std::string(call) + ": the geometry shader streams a vertex shader other than the bound one; nothing drawn");
                return false;
            }
            stages[0] = stages[2];
            stages[2] = nullptr;
        }
        core::setShaderStages(core, stages);
        const ShaderBindings* bindings[5] = {&vertexShader_->bindings, &pixel.bindings,
                                             geometryShader_ ? &geometryShader_->bindings : nullptr,
                                             hullShader_ ? &hullShader_->bindings : nullptr, domainShader_ ? &domainShader_->bindings : nullptr};
        const Stage* slots[5] = {&vs_, &ps_, &gs_, &hs_, &ds_};
        for (int stage = 0; stage < 5; ++stage) {
            if (!stages[stage]) continue;
            bindStage(stage, *bindings[stage], *slots[stage]);
            bindStorage(call, *stages[stage], *slots[stage], stage == 1 ? &psUavs_ : nullptr);  // stage 1: the pixel shader
        }
    }
    // D3D10+ encodes what a draw writes into an _SRGB render-target view (blending in linear):
    // GL's sRGB write, which changes sRGB attachments only, is on for every draw of this front end.
    PassEmulation srgbEncoded;
    srgbEncoded.srgbWrite = true;
    setPassEmulation(core, srgbEncoded);
    // A read-only depth-stencil view writes no depth (or stencil) whatever the state or the
    // effect pass says, so a shader may sample the texture while it is bound.
    if (depthView_ && (depthView_->desc.Flags & D3D11_DSV_READ_ONLY_DEPTH)) core.DepthStencilState.DepthBufferWriteEnable = false;
    if (depthView_ && (depthView_->desc.Flags & D3D11_DSV_READ_ONLY_STENCIL)) core.DepthStencilState.StencilWriteMask = 0;
    return true;
}

namespace {
template <class T>
std::vector<T> afterFirst(const std::vector<T>& all) {
    return all.size() > 1 ? std::vector<T>(all.begin() + 1, all.end()) : std::vector<T>{};
}
}  // namespace

// Viewport and scissor 0 are the device's (no viewport set: setTargets' whole target); the rest
// are the core's viewports 1.. .
void Context::setViewports(GraphicsDevice& core) const {
    if (!viewports_.empty()) core.Viewport = viewports_[0];
    core.ScissorRectangle = scissors_.empty() ? Rectangle(0, 0, 0, 0) : scissors_[0];
    core::setMoreViewports(core, afterFirst(viewports_), afterFirst(scissors_));
}

bool Context::streams(const char* call, std::vector<core::InstancedStream>& out) {
    out.clear();
    declarations_.clear();
    if (!layout_) return true;
    declarations_.reserve(layout_->slots.size());  // the streams point into it
    for (std::size_t slot = 0; slot < layout_->slots.size(); ++slot) {
        const InputLayout::Slot& elements = layout_->slots[slot];
        const VertexSlot& v = vertexSlots_[slot];
        if (!elements.elements.empty() && (!v.buffer || !v.buffer->gpu)) {
            note(std::string(call) + ": the input layout reads slot " + std::to_string(slot) + " and no vertex buffer is set there; nothing drawn");
            return false;
        }
        declarations_.push_back(core::StreamLayout{std::max(int(v.stride), 1), elements.elements});
        core::InstancedStream stream;
        stream.vertices = core::VertexStream{elements.elements.empty() ? nullptr : v.buffer->gpu.get(), v.offset, &declarations_.back()};
        stream.instanceStepRate = int(elements.instanceStepRate);
        out.push_back(stream);
    }
    return true;
}

void Context::draw(const char* call, core::DrawArguments a, bool indexed) {
    bool ok = false;
    a.type = primitiveOf(topology_, ok);
    if (!ok) return note(std::string(call) + ": primitive topology " + std::to_string(topology_) + " is not one fxport draws; nothing drawn");
    const bool patches = topology_ >= D3D11_PRIMITIVE_TOPOLOGY_1_CONTROL_POINT_PATCHLIST;
    if (patches) a.controlPoints = int(topology_) - int(D3D11_PRIMITIVE_TOPOLOGY_1_CONTROL_POINT_PATCHLIST) + 1;
    if (!effectPass_ && bool(hullShader_) != bool(domainShader_))
        return note(std::string(call) + ": a hull shader without a domain shader (or the reverse); nothing drawn");
    if (!effectPass_ && patches != bool(hullShader_))
        return note(std::string(call) + (patches ? ": a patch-list topology draws through a hull and a domain shader (HSSetShader, DSSetShader); nothing drawn"
                                                 : ": hull and domain shaders draw patch lists only (D3D11_PRIMITIVE_TOPOLOGY_n_CONTROL_POINT_PATCHLIST); nothing drawn"));
    if (indexed) {
        if (!indexBuffer_ || !indexBuffer_->gpu) return note(std::string(call) + ": no index buffer set; nothing drawn");
        if (indexFormat_ != DXGI_FORMAT_R16_UINT && indexFormat_ != DXGI_FORMAT_R32_UINT)
            return note(std::string(call) + ": index format " + formatName(indexFormat_) + " (must be R16_UINT or R32_UINT)");
        a.indexSize = indexFormat_ == DXGI_FORMAT_R32_UINT ? 4 : 2;
        if (indexOffset_ % UINT(a.indexSize) != 0)
            return note(std::string(call) + ": index buffer offset " + std::to_string(indexOffset_) + " is not a multiple of the index size");
        a.first += int(indexOffset_ / UINT(a.indexSize));
        const std::size_t end = (std::size_t(a.first) + std::size_t(a.count)) * std::size_t(a.indexSize);
        if (end > indexBuffer_->desc.ByteWidth)
            return note(std::string(call) + ": indices up to byte " + std::to_string(end) + " overrun the index buffer's " +
                        std::to_string(indexBuffer_->desc.ByteWidth));
        a.indices = indexBuffer_->gpu.get();
    }
    if (predicatedAway()) return;  // SetPredication
    std::vector<core::InstancedStream> vertexStreams;
    if (!streams(call, vertexStreams)) return;
    HRESULT hr = guarded(call, [&] {
        if (!prepare(call)) return S_FALSE;
        core::drawStreams(device_->core(), vertexStreams, a);
        return S_OK;
    });
    if (hr == S_OK) succeed();
}

void Context::Draw(UINT VertexCount, UINT StartVertexLocation) {
    draw("Draw", core::DrawArguments{PrimitiveType::TriangleList, int(VertexCount), int(StartVertexLocation)}, false);
}
void Context::DrawIndexed(UINT IndexCount, UINT StartIndexLocation, INT BaseVertexLocation) {
    draw("DrawIndexed", core::DrawArguments{PrimitiveType::TriangleList, int(IndexCount), int(StartIndexLocation), BaseVertexLocation}, true);
}
void Context::DrawInstanced(UINT VertexCountPerInstance, UINT InstanceCount, UINT StartVertexLocation, UINT StartInstanceLocation) {
    draw("DrawInstanced",
         core::DrawArguments{PrimitiveType::TriangleList, int(VertexCountPerInstance), int(StartVertexLocation), 0, int(InstanceCount),
                             int(StartInstanceLocation)},
         false);
}
void Context::DrawIndexedInstanced(UINT IndexCountPerInstance, UINT InstanceCount, UINT StartIndexLocation, INT BaseVertexLocation,
                                   UINT StartInstanceLocation) {
    draw("DrawIndexedInstanced",
         core::DrawArguments{PrimitiveType::TriangleList, int(IndexCountPerInstance), int(StartIndexLocation), BaseVertexLocation,
                             int(InstanceCount), int(StartInstanceLocation)},
         true);
}

void Context::Dispatch(UINT x, UINT y, UINT z) {
    if (!computeShader_) return note("Dispatch: no compute shader set (CSSetShader); nothing run");
    if (predicatedAway()) return;  // SetPredication
    const UINT most = D3D11_CS_DISPATCH_MAX_THREAD_GROUPS_PER_DIMENSION;
    if (x > most || y > most || z > most)
        return note("Dispatch(" + std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) + "): each count is at most " +
                    std::to_string(most) + "; nothing run");
    HRESULT hr = guarded("Dispatch", [&] {
        GraphicsDevice& core = device_->core();
        core::setComputeShader(core, computeShader_->code.get());
        bindStage(5, computeShader_->bindings, cs_);
        bindStorage("Dispatch", *computeShader_->code, cs_, &csUavs_);
        core.DispatchCompute(int(x), int(y), int(z));
        return S_OK;
    });
    if (hr == S_OK) succeed();
}

}  // namespace fxport::d3d11
