// The immediate context. Set* calls only record bindings (with a reference, as D3D holds them); a
// draw copies them into the device core -- targets, shaders, each cbuffer slot to the GL binding
// of the block it feeds, each t#/s# pair to the texture unit the translation samples it on, the
// decoded state objects into the device's state -- and draws; the device core compares with what
// GL has and calls GL only for what differs. D3D ignores invalid draws; so does this, noting why
// (GetLastErrorMessage).
#include "context.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "guarded.h"

namespace fxport::d3d11 {

namespace {

template <class T, class I>
T* own(I* object, Device* device) {
    auto* t = dynamic_cast<T*>(object);
    return t && &t->device() == device ? t : nullptr;
}

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

}  // namespace

Context::Context(Device* device) : device_(device) { ClearState(); }

void Context::ClearState() {
    layout_ = nullptr;
    for (VertexSlot& v : vertexSlots_) v = VertexSlot{};
    indexBuffer_ = nullptr;
    indexFormat_ = DXGI_FORMAT_UNKNOWN;
    indexOffset_ = 0;
    topology_ = D3D11_PRIMITIVE_TOPOLOGY_UNDEFINED;
    vertexShader_ = nullptr;
    pixelShader_ = nullptr;
    geometryShader_ = nullptr;
    hullShader_ = nullptr;
    domainShader_ = nullptr;
    computeShader_ = nullptr;
    for (Stage* stage : {&vs_, &ps_, &gs_, &hs_, &ds_, &cs_}) *stage = Stage{};
    for (auto& u : csUavs_) u = nullptr;
    viewport_ = D3D11_VIEWPORT{};
    viewportSet_ = false;
    scissor_ = D3D11_RECT{};
    rasterizer_ = nullptr;
    blend_ = nullptr;
    std::fill(std::begin(blendFactor_), std::end(blendFactor_), 1.0f);
    sampleMask_ = 0xffffffffu;
    depthStencil_ = nullptr;
    stencilRef_ = 0;
    for (auto& t : targets_) t = nullptr;
    depthView_ = nullptr;
    effectPass_ = nullptr;
    effectOwner_ = nullptr;
    decodeBlend(D3D11_BLEND_DESC{}, defaultBlend_);
    decodeRasterizer(D3D11_RASTERIZER_DESC{}, defaultRasterizer_);
    decodeDepthStencil(D3D11_DEPTH_STENCIL_DESC{}, defaultDepthStencil_);
    decodeSampler(D3D11_SAMPLER_DESC{}, defaultSampler_);
    succeed();
}

// --- input assembler

void Context::IASetInputLayout(ID3D11InputLayout* p) { layout_ = own<InputLayout>(p, device_); }

void Context::IASetVertexBuffers(UINT StartSlot, UINT NumBuffers, ID3D11Buffer* const* pp, const UINT* pStrides, const UINT* pOffsets) {
    for (UINT i = 0; i < NumBuffers; ++i) {
        const UINT slot = StartSlot + i;
        if (slot >= vertexSlots_.size())
            return note("IASetVertexBuffers: slot " + std::to_string(slot) + " is beyond D3D11's " + std::to_string(vertexSlots_.size()));
        VertexSlot& v = vertexSlots_[slot];
        v.buffer = pp ? own<Buffer>(pp[i], device_) : nullptr;
        v.stride = pStrides ? pStrides[i] : 0;
        v.offset = pOffsets ? pOffsets[i] : 0;
    }
}

void Context::IASetIndexBuffer(ID3D11Buffer* p, DXGI_FORMAT Format, UINT Offset) {
    indexBuffer_ = own<Buffer>(p, device_);
    indexFormat_ = Format;
    indexOffset_ = Offset;
}

void Context::IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY Topology) { topology_ = Topology; }

// --- shader stages

void Context::VSSetShader(ID3D11VertexShader* p, ID3D11ClassInstance* const*, UINT) {
    vertexShader_ = own<VertexShader>(p, device_);
    effectPass_ = nullptr;  // the shader replaces an applied effect pass's
}
void Context::PSSetShader(ID3D11PixelShader* p, ID3D11ClassInstance* const*, UINT) {
    pixelShader_ = own<PixelShader>(p, device_);
    effectPass_ = nullptr;
}
void Context::GSSetShader(ID3D11GeometryShader* p, ID3D11ClassInstance* const*, UINT) {
    geometryShader_ = own<GeometryShader>(p, device_);
    effectPass_ = nullptr;
}
void Context::HSSetShader(ID3D11HullShader* p, ID3D11ClassInstance* const*, UINT) {
    hullShader_ = own<HullShader>(p, device_);
    effectPass_ = nullptr;
}
void Context::DSSetShader(ID3D11DomainShader* p, ID3D11ClassInstance* const*, UINT) {
    domainShader_ = own<DomainShader>(p, device_);
    effectPass_ = nullptr;
}
void Context::CSSetShader(ID3D11ComputeShader* p, ID3D11ClassInstance* const*, UINT) { computeShader_ = own<ComputeShader>(p, device_); }

template <class Array, class I, class T>
void setSlots(Array& slots, UINT start, UINT count, I* const* objects, Device* device, const char* call) {
    for (UINT i = 0; i < count; ++i) {
        if (start + i >= slots.size()) {
            note(std::string(call) + ": slot " + std::to_string(start + i) + " is beyond the " + std::to_string(slots.size()) + " fxport has");
            return;
        }
        slots[start + i] = objects ? own<T>(objects[i], device) : nullptr;
    }
}

// Each stage's Set{ConstantBuffers,ShaderResources,Samplers}: the same three calls per stage.
#define FXPORT_STAGE_SLOTS(PREFIX, STAGE)                                                                                               \
    void Context::PREFIX##SetConstantBuffers(UINT s, UINT n, ID3D11Buffer* const* p) {                                                   \
        setSlots<decltype(STAGE.constantBuffers), ID3D11Buffer, Buffer>(STAGE.constantBuffers, s, n, p, device_,                        \
                                                                        #PREFIX "SetConstantBuffers");                                   \
    }                                                                                                                                    \
    void Context::PREFIX##SetShaderResources(UINT s, UINT n, ID3D11ShaderResourceView* const* p) {                                       \
        setSlots<decltype(STAGE.views), ID3D11ShaderResourceView, ShaderResourceView>(STAGE.views, s, n, p, device_,                    \
                                                                                      #PREFIX "SetShaderResources");                     \
    }                                                                                                                                    \
    void Context::PREFIX##SetSamplers(UINT s, UINT n, ID3D11SamplerState* const* p) {                                                    \
        setSlots<decltype(STAGE.samplers), ID3D11SamplerState, SamplerState>(STAGE.samplers, s, n, p, device_, #PREFIX "SetSamplers"); \
    }
FXPORT_STAGE_SLOTS(VS, vs_)
FXPORT_STAGE_SLOTS(PS, ps_)
FXPORT_STAGE_SLOTS(GS, gs_)
FXPORT_STAGE_SLOTS(HS, hs_)
FXPORT_STAGE_SLOTS(DS, ds_)
FXPORT_STAGE_SLOTS(CS, cs_)
#undef FXPORT_STAGE_SLOTS

void Context::CSSetUnorderedAccessViews(UINT s, UINT n, ID3D11UnorderedAccessView* const* p, const UINT*) {
    setSlots<UavSlots, ID3D11UnorderedAccessView, UnorderedAccessView>(csUavs_, s, n, p, device_, "CSSetUnorderedAccessViews");
}

// --- rasterizer and output merger

void Context::RSSetViewports(UINT n, const D3D11_VIEWPORT* p) {
    viewportSet_ = n > 0 && p;
    if (viewportSet_) viewport_ = p[0];
    if (n > 1) note("RSSetViewports: " + std::to_string(n) + " viewports; fxport uses the first");
}
void Context::RSSetScissorRects(UINT n, const D3D11_RECT* p) {
    if (n > 0 && p) scissor_ = p[0];
}
void Context::RSSetState(ID3D11RasterizerState* p) { rasterizer_ = own<RasterizerState>(p, device_); }

void Context::OMSetRenderTargets(UINT n, ID3D11RenderTargetView* const* pp, ID3D11DepthStencilView* dsv) {
    for (auto& t : targets_) t = nullptr;
    for (UINT i = 0; i < n && i < targets_.size(); ++i) targets_[i] = pp ? own<RenderTargetView>(pp[i], device_) : nullptr;
    depthView_ = own<DepthStencilView>(dsv, device_);
}
void Context::OMSetBlendState(ID3D11BlendState* p, const FLOAT BlendFactor[4], UINT SampleMask) {
    blend_ = own<BlendState>(p, device_);
    for (int i = 0; i < 4; ++i) blendFactor_[i] = BlendFactor ? BlendFactor[i] : 1.0f;
    sampleMask_ = SampleMask;
}
void Context::OMSetDepthStencilState(ID3D11DepthStencilState* p, UINT StencilRef) {
    depthStencil_ = own<DepthStencilState>(p, device_);
    stencilRef_ = StencilRef;
}

// --- draws

void Context::bindStage(int stage, const ShaderBindings& bindings, const Stage& s) {
    GraphicsDevice& core = device_->core();
    for (const CbufferBinding& c : bindings.cbuffers) {
        const Buffer* b = std::size_t(c.slot) < s.constantBuffers.size() ? s.constantBuffers[std::size_t(c.slot)].Get() : nullptr;
        if (b && b->desc.ByteWidth < UINT(c.size))
            throw InvalidOperation("cbuffer '" + c.name + "' (b" + std::to_string(c.slot) + ") needs " + std::to_string(c.size) +
                                   " bytes; the buffer bound there has " + std::to_string(b->desc.ByteWidth));
        if (b && !(b->desc.BindFlags & D3D11_BIND_CONSTANT_BUFFER))
            throw InvalidOperation("the buffer at b" + std::to_string(c.slot) + " was not made with D3D11_BIND_CONSTANT_BUFFER");
        core::setUniformBuffer(core, stage, c.glBinding, b ? b->gpu.get() : nullptr);
    }
    for (const SamplerUnit& u : bindings.units) {
        if (u.glUnit < 0 || u.glUnit >= kMaxTextureSlots) continue;
        const ShaderResourceView* v =
            u.textureSlot >= 0 && std::size_t(u.textureSlot) < s.views.size() ? s.views[std::size_t(u.textureSlot)].Get() : nullptr;
        if (v && !v->texture)
            throw InvalidOperation("t" + std::to_string(u.textureSlot) + " holds a view of a buffer where the shader samples a texture");
        core.Textures[u.glUnit] = v ? v->texture->colour.get() : nullptr;
        const SamplerState* st =
            u.samplerSlot >= 0 && std::size_t(u.samplerSlot) < s.samplers.size() ? s.samplers[std::size_t(u.samplerSlot)].Get() : nullptr;
        core.SamplerStates[u.glUnit] = st ? st->state : defaultSampler_;
    }
}

namespace {

// D3D's rule: a structured view's StructureByteStride is the size of the shader's element. The
// shader's is the size of fxport's GL (std430) layout of it, which differs from HLSL's where a
// float3 (or a float2 and a float) ends an element: such a buffer is refused, not misread.
void checkStride(const std::string& use, const xlate::StorageBinding& b, const Buffer& buffer) {
    if (!(buffer.desc.MiscFlags & D3D11_RESOURCE_MISC_BUFFER_STRUCTURED)) return;  // raw: 4-byte words
    if (b.stride <= 0 || UINT(b.stride) == buffer.desc.StructureByteStride) return;
    throw InvalidOperation(use + ": its elements are " + std::to_string(b.stride) + " bytes in fxport's GL layout, the buffer's StructureByteStride is " +
                           std::to_string(buffer.desc.StructureByteStride) +
                           " (GLSL's std430 pads a float3 ending an element to 16 bytes: end the struct on a float4 or add padding)");
}

}  // namespace

void Context::bindStorage(const char* call, const core::ShaderCode& code, const Stage& s, const UavSlots* uavs) {
    GraphicsDevice& core = device_->core();
    for (const xlate::StorageBinding& b : code.shader().storage) {
        const std::string reg = std::string(1, b.registerClass) + std::to_string(b.slot);
        const std::string use = std::string(call) + ": " + code.shader().entryPoint + " uses '" + b.name + "' (" + reg + ")";
        const bool image = b.kind == xlate::StorageKind::Image;
        if (b.registerClass == 't') {
            const ShaderResourceView* v = b.slot >= 0 && std::size_t(b.slot) < s.views.size() ? s.views[std::size_t(b.slot)].Get() : nullptr;
            if (!v || !v->buffer)
                throw InvalidOperation(use + ", but no shader-resource view of a structured or raw buffer is set there");
            checkStride(use, b, *v->buffer);
            core::setStorageBuffer(core, false, b.slot, v->buffer->gpu.get());
            continue;
        }
        const UnorderedAccessView* v = uavs && b.slot >= 0 && std::size_t(b.slot) < uavs->size() ? (*uavs)[std::size_t(b.slot)].Get() : nullptr;
        if (!v)
            throw InvalidOperation(use + ", but no unordered-access view is set there" +
                                   (uavs ? std::string(" (CSSetUnorderedAccessViews)") : std::string(" (fxport binds UAVs for compute shaders only)")));
        if (image != (v->texture != nullptr))
            throw InvalidOperation(use + ", a " + (image ? "texture" : "buffer") + ", but the view there is of a " + (v->texture ? "texture" : "buffer"));
        if (image) {
            core.SetUnorderedAccess(b.slot, v->texture->colour.get());
        } else {
            checkStride(use, b, *v->buffer);
            core::setStorageBuffer(core, true, b.slot, v->buffer->gpu.get());
        }
    }
}

bool Context::prepare(const char* call) {
    const std::string at = std::string(call) + ": ";
    if (!effectPass_ && (!vertexShader_ || !pixelShader_)) {
        note(at + "no " + std::string(!vertexShader_ ? "vertex" : "pixel") + " shader set; nothing drawn (fxport needs both)");
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
    if (colour.empty()) {
        note(at + "no render target view bound; nothing drawn (fxport draws into at least one)");
        return false;
    }
    GraphicsDevice& core = device_->core();
    core::DepthBuffer* depth = depthView_ ? depthView_->texture->depth.get() : nullptr;
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
    core.DepthStencilState = depthStencil_ ? depthStencil_->state : defaultDepthStencil_;
    core.DepthStencilState.ReferenceStencil = int(stencilRef_);
    core.RasterizerState = rasterizer_ ? rasterizer_->state : defaultRasterizer_;
    if (viewportSet_) {
        Viewport v(int(std::lround(viewport_.TopLeftX)), int(std::lround(viewport_.TopLeftY)), int(std::lround(viewport_.Width)),
                   int(std::lround(viewport_.Height)));
        v.MinDepth = viewport_.MinDepth;
        v.MaxDepth = viewport_.MaxDepth;
        core.Viewport = v;
    }
    core.ScissorRectangle = Rectangle(scissor_.left, scissor_.top, scissor_.right - scissor_.left, scissor_.bottom - scissor_.top);

    if (effectPass_) {
        // The pass binds its shaders, constants and textures and sets the states it names over
        // the context's (Effects11's Apply does the same through the context's Set calls).
        effectPass_->Apply();
    } else {
        auto codeOf = [](const auto& shader) { return shader ? shader->code.get() : nullptr; };
        const core::ShaderCode* stages[5] = {vertexShader_->code.get(), pixelShader_->code.get(), codeOf(geometryShader_),
                                             codeOf(hullShader_), codeOf(domainShader_)};
        core::setShaderStages(core, stages);
        const ShaderBindings* bindings[5] = {&vertexShader_->bindings, &pixelShader_->bindings,
                                             geometryShader_ ? &geometryShader_->bindings : nullptr,
                                             hullShader_ ? &hullShader_->bindings : nullptr, domainShader_ ? &domainShader_->bindings : nullptr};
        const Stage* slots[5] = {&vs_, &ps_, &gs_, &hs_, &ds_};
        for (int stage = 0; stage < 5; ++stage) {
            if (!stages[stage]) continue;
            bindStage(stage, *bindings[stage], *slots[stage]);
            bindStorage(call, *stages[stage], *slots[stage], nullptr);
        }
    }
    return true;
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
        declarations_.emplace_back(std::max(int(v.stride), 1), elements.elements);
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

// --- resources

HRESULT Context::Map(ID3D11Resource* pResource, UINT Subresource, D3D11_MAP MapType, UINT, D3D11_MAPPED_SUBRESOURCE* out) {
    if (!out) return fail(E_INVALIDARG, "Map: pMappedResource is null");
    const bool reads = MapType == D3D11_MAP_READ || MapType == D3D11_MAP_READ_WRITE;
    const bool writes = MapType != D3D11_MAP_READ;
    if (MapType < D3D11_MAP_READ || MapType > D3D11_MAP_WRITE_NO_OVERWRITE)
        return fail(E_INVALIDARG, "Map: MapType = " + std::to_string(MapType) + " is not a D3D11_MAP value (1-5)");
    auto checkAccess = [&](D3D11_USAGE usage, UINT cpu) -> HRESULT {
        if (usage == D3D11_USAGE_DYNAMIC && MapType != D3D11_MAP_WRITE_DISCARD && MapType != D3D11_MAP_WRITE_NO_OVERWRITE)
            return fail(E_INVALIDARG, "Map: MapType = " + std::to_string(MapType) + " on a USAGE_DYNAMIC resource (WRITE_DISCARD or WRITE_NO_OVERWRITE)");
        if (usage != D3D11_USAGE_DYNAMIC && usage != D3D11_USAGE_STAGING)
            return fail(E_INVALIDARG, "Map: the resource's Usage = " + std::to_string(usage) + " (only DYNAMIC and STAGING resources map)");
        if ((reads && !(cpu & D3D11_CPU_ACCESS_READ)) || (writes && !(cpu & D3D11_CPU_ACCESS_WRITE)))
            return fail(E_INVALIDARG, "Map: MapType = " + std::to_string(MapType) + " needs CPU access the resource's CPUAccessFlags = " +
                                          std::to_string(cpu) + " do not give");
        return S_OK;
    };
    if (auto* b = own<Buffer>(pResource, device_)) {
        if (Subresource != 0) return fail(E_INVALIDARG, "Map: Subresource = " + std::to_string(Subresource) + " of a buffer");
        if (b->mapped) return fail(E_INVALIDARG, "Map: the buffer is already mapped");
        if (HRESULT hr = checkAccess(b->desc.Usage, b->desc.CPUAccessFlags); FAILED(hr)) return hr;
        if (b->cpu.empty()) b->cpu.assign(b->desc.ByteWidth, 0);  // a dynamic buffer's CPU copy, kept for NO_OVERWRITE
        b->mapped = true;
        *out = D3D11_MAPPED_SUBRESOURCE{b->cpu.data(), b->desc.ByteWidth, b->desc.ByteWidth};
        return succeed();
    }
    if (auto* t = own<Texture>(pResource, device_)) {
        if (Subresource >= UINT(t->levels)) return fail(E_INVALIDARG, "Map: Subresource = " + std::to_string(Subresource) + " of " + std::to_string(t->levels));
        if (t->mappedLevel >= 0) return fail(E_INVALIDARG, "Map: the texture is already mapped");
        if (HRESULT hr = checkAccess(t->desc.Usage, t->desc.CPUAccessFlags); FAILED(hr)) return hr;
        if (t->staging.empty())
            for (int level = 0; level < t->levels; ++level) t->staging.emplace_back(t->levelBytes(level), 0);
        t->mappedLevel = int(Subresource);
        const UINT row = UINT(t->levelWidth(int(Subresource)) * bytesPerPixel(t->format));
        *out = D3D11_MAPPED_SUBRESOURCE{t->staging[Subresource].data(), row, UINT(t->levelBytes(int(Subresource)))};
        return succeed();
    }
    return fail(E_INVALIDARG, "Map: pResource is not a buffer or texture of this device");
}

void Context::Unmap(ID3D11Resource* pResource, UINT Subresource) {
    guarded("Unmap", [&] {
        if (auto* b = own<Buffer>(pResource, device_)) {
            if (!b->mapped) return fail(E_INVALIDARG, "Unmap: the buffer is not mapped");
            b->mapped = false;
            if (b->gpu) b->gpu->write(0, b->cpu.size(), b->cpu.data());
            return succeed();
        }
        if (auto* t = own<Texture>(pResource, device_)) {
            if (t->mappedLevel != int(Subresource)) return fail(E_INVALIDARG, "Unmap: subresource " + std::to_string(Subresource) + " is not mapped");
            t->mappedLevel = -1;
            if (t->colour) t->colour->setData(int(Subresource), nullptr, t->staging[Subresource].data(), t->staging[Subresource].size());
            return succeed();
        }
        return fail(E_INVALIDARG, "Unmap: pResource is not a buffer or texture of this device");
    });
}

void Context::UpdateSubresource(ID3D11Resource* pDst, UINT DstSubresource, const D3D11_BOX* box, const void* pSrcData, UINT SrcRowPitch, UINT) {
    guarded("UpdateSubresource", [&] {
        if (!pSrcData) return fail(E_INVALIDARG, "UpdateSubresource: pSrcData is null");
        if (auto* b = own<Buffer>(pDst, device_)) {
            if (b->desc.Usage != D3D11_USAGE_DEFAULT)
                return fail(E_INVALIDARG, "UpdateSubresource: the buffer's Usage = " + std::to_string(b->desc.Usage) + " (only USAGE_DEFAULT)");
            if (box && (b->desc.BindFlags & D3D11_BIND_CONSTANT_BUFFER))
                return fail(E_INVALIDARG, "UpdateSubresource: a constant buffer is updated whole (pDstBox must be null)");
            const UINT left = box ? box->left : 0, right = box ? box->right : b->desc.ByteWidth;
            if (right <= left || right > b->desc.ByteWidth)
                return fail(E_INVALIDARG, "UpdateSubresource: box [" + std::to_string(left) + ", " + std::to_string(right) + ") of a " +
                                              std::to_string(b->desc.ByteWidth) + "-byte buffer");
            b->gpu->write(left, right - left, pSrcData);
            return succeed();
        }
        auto* t = own<Texture>(pDst, device_);
        if (!t) return fail(E_INVALIDARG, "UpdateSubresource: pDstResource is not a buffer or texture of this device");
        if (t->desc.Usage != D3D11_USAGE_DEFAULT || !t->colour)
            return fail(E_INVALIDARG, "UpdateSubresource: the texture is not a USAGE_DEFAULT colour texture");
        const int level = int(DstSubresource);
        if (level >= t->levels) return fail(E_INVALIDARG, "UpdateSubresource: DstSubresource = " + std::to_string(DstSubresource));
        Rectangle r(0, 0, t->levelWidth(level), t->levelHeight(level));
        if (box) r = Rectangle(int(box->left), int(box->top), int(box->right) - int(box->left), int(box->bottom) - int(box->top));
        const std::size_t row = std::size_t(r.Width) * std::size_t(bytesPerPixel(t->format));
        if (SrcRowPitch < row) return fail(E_INVALIDARG, "UpdateSubresource: SrcRowPitch = " + std::to_string(SrcRowPitch) + " < " + std::to_string(row));
        std::vector<std::uint8_t> packed(row * std::size_t(std::max(r.Height, 0)));
        for (int y = 0; y < r.Height; ++y)
            std::memcpy(&packed[std::size_t(y) * row], static_cast<const std::uint8_t*>(pSrcData) + std::size_t(y) * SrcRowPitch, row);
        t->colour->setData(level, &r, packed.data(), packed.size());
        return succeed();
    });
}

void Context::CopyResource(ID3D11Resource* pDst, ID3D11Resource* pSrc) {
    guarded("CopyResource", [&] {
        auto *bd = own<Buffer>(pDst, device_), *bs = own<Buffer>(pSrc, device_);
        if (bd && bs) {
            if (bd->desc.ByteWidth != bs->desc.ByteWidth) return fail(E_INVALIDARG, "CopyResource: the buffers differ in ByteWidth");
            if (bd->gpu && bs->gpu) bd->gpu->copyFrom(*bs->gpu);
            else if (bd->gpu) bd->gpu->write(0, bs->cpu.size(), bs->cpu.data());
            else if (bs->gpu) bs->gpu->read(0, bd->cpu.size(), bd->cpu.data());
            else bd->cpu = bs->cpu;
            return succeed();
        }
        auto *td = own<Texture>(pDst, device_), *ts = own<Texture>(pSrc, device_);
        if (!td || !ts) return fail(E_INVALIDARG, "CopyResource: the resources are not two buffers or two textures of this device");
        if (td->desc.Width != ts->desc.Width || td->desc.Height != ts->desc.Height || td->desc.Format != ts->desc.Format ||
            td->levels != ts->levels)
            return fail(E_INVALIDARG, "CopyResource: the textures differ in size, format or mip levels");
        if (td->depth || ts->depth) return fail(E_NOTIMPL, "CopyResource: depth-stencil textures cannot be copied in fxport yet");
        for (int level = 0; level < ts->levels; ++level) {
            if (td->colour && ts->colour) {
                core::copyTexture(*td->colour, *ts->colour);
                break;
            }
            auto& cpu = td->colour ? ts->staging[std::size_t(level)] : td->staging[std::size_t(level)];
            if (td->colour) td->colour->setData(level, nullptr, cpu.data(), cpu.size());
            else if (ts->colour) ts->colour->getData(level, cpu.data(), cpu.size());
            else td->staging = ts->staging;
        }
        return succeed();
    });
}

namespace {

// Rows of `width` texels between two tightly packed levels (staging textures' memory).
void copyRows(const std::vector<std::uint8_t>& from, int fromWidth, int fx, int fy, std::vector<std::uint8_t>& to, int toWidth, int tx, int ty,
              int width, int height, int texel) {
    for (int row = 0; row < height; ++row)
        std::memcpy(&to[(std::size_t(ty + row) * std::size_t(toWidth) + std::size_t(tx)) * std::size_t(texel)],
                    &from[(std::size_t(fy + row) * std::size_t(fromWidth) + std::size_t(fx)) * std::size_t(texel)],
                    std::size_t(width) * std::size_t(texel));
}

}  // namespace

void Context::CopySubresourceRegion(ID3D11Resource* pDst, UINT DstSubresource, UINT DstX, UINT DstY, UINT DstZ, ID3D11Resource* pSrc,
                                    UINT SrcSubresource, const D3D11_BOX* box) {
    const char* call = "CopySubresourceRegion";
    guarded(call, [&] {
        const std::string at = std::string(call) + ": ";
        if (box && (box->front != 0 || box->back != 1))
            return fail(E_INVALIDARG, at + "pSrcBox front/back = " + std::to_string(box->front) + "/" + std::to_string(box->back) + " (2D: 0/1)");
        if (DstZ != 0) return fail(E_INVALIDARG, at + "DstZ = " + std::to_string(DstZ) + " (2D resources: 0)");
        auto *bd = own<Buffer>(pDst, device_), *bs = own<Buffer>(pSrc, device_);
        if (bd && bs) {
            if (DstSubresource != 0 || SrcSubresource != 0) return fail(E_INVALIDARG, at + "a buffer has one subresource (0)");
            const UINT left = box ? box->left : 0, right = box ? box->right : bs->desc.ByteWidth;
            if (right <= left || right > bs->desc.ByteWidth || DstX > bd->desc.ByteWidth || right - left > bd->desc.ByteWidth - DstX)
                return fail(E_INVALIDARG, at + "bytes [" + std::to_string(left) + ", " + std::to_string(right) + ") of a " + std::to_string(bs->desc.ByteWidth) +
                                              "-byte buffer to byte " + std::to_string(DstX) + " of a " + std::to_string(bd->desc.ByteWidth) + "-byte one");
            const UINT bytes = right - left;
            if (bd->gpu && bs->gpu) bd->gpu->copyFrom(*bs->gpu, left, DstX, bytes);
            else if (bd->gpu) bd->gpu->write(DstX, bytes, bs->cpu.data() + left);
            else if (bs->gpu) bs->gpu->read(left, bytes, bd->cpu.data() + DstX);
            else std::memmove(bd->cpu.data() + DstX, bs->cpu.data() + left, bytes);
            return succeed();
        }
        auto *td = own<Texture>(pDst, device_), *ts = own<Texture>(pSrc, device_);
        if (!td || !ts) return fail(E_INVALIDARG, at + "the resources are not two buffers or two textures of this device");
        if (td->desc.Format != ts->desc.Format)
            return fail(E_INVALIDARG, at + "the textures' formats differ (" + std::string(formatName(td->desc.Format)) + ", " + formatName(ts->desc.Format) + ")");
        if (td->depth || ts->depth) return fail(E_NOTIMPL, at + "depth-stencil textures cannot be copied in fxport yet");
        if (DstSubresource >= UINT(td->levels) || SrcSubresource >= UINT(ts->levels))
            return fail(E_INVALIDARG, at + "DstSubresource = " + std::to_string(DstSubresource) + ", SrcSubresource = " + std::to_string(SrcSubresource) +
                                          " (the textures have " + std::to_string(td->levels) + " and " + std::to_string(ts->levels) + " levels)");
        const int sl = int(SrcSubresource), dl = int(DstSubresource);
        Rectangle area(0, 0, ts->levelWidth(sl), ts->levelHeight(sl));
        if (box) area = Rectangle(int(box->left), int(box->top), int(box->right) - int(box->left), int(box->bottom) - int(box->top));
        if (area.Width <= 0 || area.Height <= 0 || (box && (box->right > UINT(ts->levelWidth(sl)) || box->bottom > UINT(ts->levelHeight(sl)))))
            return fail(E_INVALIDARG, at + "pSrcBox {" + std::to_string(area.X) + ", " + std::to_string(area.Y) + ", " + std::to_string(area.X + area.Width) +
                                          ", " + std::to_string(area.Y + area.Height) + "} is empty or outside source level " + std::to_string(sl));
        if (DstX + UINT(area.Width) > UINT(td->levelWidth(dl)) || DstY + UINT(area.Height) > UINT(td->levelHeight(dl)))
            return fail(E_INVALIDARG, at + "the region at (" + std::to_string(DstX) + ", " + std::to_string(DstY) + ") overruns destination level " +
                                          std::to_string(dl));
        const int x = int(DstX), y = int(DstY);
        if (td->colour && ts->colour) {
            core::copyTextureRegion(*td->colour, dl, x, y, *ts->colour, sl, area);
            return succeed();
        }
        // Staging on one side or both: through the CPU (a GPU texture's whole level is read).
        const int texel = bytesPerPixel(ts->format);
        std::vector<std::uint8_t> source = ts->colour ? std::vector<std::uint8_t>(ts->levelBytes(sl)) : ts->staging[std::size_t(sl)];
        if (ts->colour) ts->colour->getData(sl, source.data(), source.size());
        if (td->colour) {
            std::vector<std::uint8_t> packed(std::size_t(area.Width) * std::size_t(area.Height) * std::size_t(texel));
            copyRows(source, ts->levelWidth(sl), area.X, area.Y, packed, area.Width, 0, 0, area.Width, area.Height, texel);
            const Rectangle target(x, y, area.Width, area.Height);
            td->colour->setData(dl, &target, packed.data(), packed.size());
        } else {
            copyRows(source, ts->levelWidth(sl), area.X, area.Y, td->staging[std::size_t(dl)], td->levelWidth(dl), x, y, area.Width, area.Height, texel);
        }
        return succeed();
    });
}

void Context::ClearRenderTargetView(ID3D11RenderTargetView* p, const FLOAT c[4]) {
    guarded("ClearRenderTargetView", [&] {
        auto* v = own<RenderTargetView>(p, device_);
        if (!v || !c) return fail(E_INVALIDARG, "ClearRenderTargetView: no view of this device, or no colour");
        core::clearTexture(*v->texture->colour, Vector4(c[0], c[1], c[2], c[3]));
        return succeed();
    });
}

void Context::ClearDepthStencilView(ID3D11DepthStencilView* p, UINT flags, FLOAT depth, UINT8 stencil) {
    guarded("ClearDepthStencilView", [&] {
        auto* v = own<DepthStencilView>(p, device_);
        if (!v) return fail(E_INVALIDARG, "ClearDepthStencilView: no view of this device");
        core::clearDepthBuffer(device_->core(), *v->texture->depth, (flags & D3D11_CLEAR_DEPTH) != 0, (flags & D3D11_CLEAR_STENCIL) != 0,
                               depth, int(stencil));
        return succeed();
    });
}

void Context::GenerateMips(ID3D11ShaderResourceView* p) {
    auto* v = own<ShaderResourceView>(p, device_);
    if (!v || !(v->texture->desc.MiscFlags & D3D11_RESOURCE_MISC_GENERATE_MIPS))
        return note("GenerateMips: the view's texture was not made with D3D11_RESOURCE_MISC_GENERATE_MIPS");
    guarded("GenerateMips", [&] {
        core::generateMips(*v->texture->colour);
        return succeed();
    });
}

void Context::Flush() { device_->core().finish(); }

}  // namespace fxport::d3d11
