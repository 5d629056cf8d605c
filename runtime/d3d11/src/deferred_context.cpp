// Deferred contexts and command lists. A deferred context records each call as a closure over
// copies of its arguments (holding a reference to every object named), to be run on the immediate
// context by ExecuteCommandList; state-setting calls are also kept apart, so that
// FinishCommandList(RestoreDeferredContextState = TRUE) can start the next list from the state the
// context had. Map on a deferred context is WRITE_DISCARD of a DYNAMIC buffer: the bytes written
// are kept and written by a Map/Unmap of the immediate context when the list runs.
#include <algorithm>
#include <cstring>
#include <functional>
#include <optional>

#include "context.h"
#include "guarded.h"

namespace fxport::d3d11 {

namespace {

using Command = std::function<void(ID3D11DeviceContext&)>;

class CommandList final : public Object<ID3D11CommandList> {
public:
    CommandList(Device* device, std::vector<Command> recorded) : Object(device), commands(std::move(recorded)) {}
    UINT GetContextFlags() override { return 0; }
    std::vector<Command> commands;
};

// The objects of an array argument, each held; raw() gives the array back at replay.
template <class T>
std::vector<ComPtr<T>> hold(T* const* objects, UINT count) {
    std::vector<ComPtr<T>> out;
    for (UINT i = 0; objects && i < count; ++i) out.emplace_back(objects[i]);
    return out;
}
template <class T>
std::vector<T*> raw(const std::vector<ComPtr<T>>& held) {
    std::vector<T*> out;
    for (const auto& p : held) out.push_back(p.Get());
    return out;
}
template <class T>
std::vector<T> copyOf(const T* values, UINT count) {
    return values ? std::vector<T>(values, values + count) : std::vector<T>();
}
template <class T>
const T* orNull(const std::vector<T>& v) { return v.empty() ? nullptr : v.data(); }

class DeferredContext final : public Object<ID3D11DeviceContext> {
public:
    explicit DeferredContext(Device* device) : Object(device) {}

    // --- state: recorded, and kept for FinishCommandList(TRUE)
    void IASetInputLayout(ID3D11InputLayout* l) override { state([held = ComPtr<ID3D11InputLayout>(l)](auto& c) { c.IASetInputLayout(held.Get()); }); }
    void IASetVertexBuffers(UINT start, UINT n, ID3D11Buffer* const* b, const UINT* strides, const UINT* offsets) override {
        state([start, n, held = hold(b, n), s = copyOf(strides, n), o = copyOf(offsets, n)](auto& c) {
            c.IASetVertexBuffers(start, n, orNull(raw(held)), orNull(s), orNull(o));
        });
    }
    void IASetIndexBuffer(ID3D11Buffer* b, DXGI_FORMAT f, UINT offset) override {
        state([held = ComPtr<ID3D11Buffer>(b), f, offset](auto& c) { c.IASetIndexBuffer(held.Get(), f, offset); });
    }
    void IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY t) override { state([t](auto& c) { c.IASetPrimitiveTopology(t); }); }
#define FXPORT_SET_SHADER(Method, Type) \
    void Method(Type* s, ID3D11ClassInstance* const*, UINT) override { state([held = ComPtr<Type>(s)](auto& c) { c.Method(held.Get(), nullptr, 0); }); }
    FXPORT_SET_SHADER(VSSetShader, ID3D11VertexShader)
    FXPORT_SET_SHADER(PSSetShader, ID3D11PixelShader)
    FXPORT_SET_SHADER(GSSetShader, ID3D11GeometryShader)
    FXPORT_SET_SHADER(HSSetShader, ID3D11HullShader)
    FXPORT_SET_SHADER(DSSetShader, ID3D11DomainShader)
    FXPORT_SET_SHADER(CSSetShader, ID3D11ComputeShader)
#undef FXPORT_SET_SHADER
#define FXPORT_SET_SLOTS(Method, Type) \
    void Method(UINT start, UINT n, Type* const* p) override { state([start, n, h = hold(p, n)](auto& c) { c.Method(start, n, orNull(raw(h))); }); }
    FXPORT_SET_SLOTS(VSSetConstantBuffers, ID3D11Buffer)
    FXPORT_SET_SLOTS(PSSetConstantBuffers, ID3D11Buffer)
    FXPORT_SET_SLOTS(GSSetConstantBuffers, ID3D11Buffer)
    FXPORT_SET_SLOTS(HSSetConstantBuffers, ID3D11Buffer)
    FXPORT_SET_SLOTS(DSSetConstantBuffers, ID3D11Buffer)
    FXPORT_SET_SLOTS(CSSetConstantBuffers, ID3D11Buffer)
    FXPORT_SET_SLOTS(VSSetShaderResources, ID3D11ShaderResourceView)
    FXPORT_SET_SLOTS(PSSetShaderResources, ID3D11ShaderResourceView)
    FXPORT_SET_SLOTS(GSSetShaderResources, ID3D11ShaderResourceView)
    FXPORT_SET_SLOTS(HSSetShaderResources, ID3D11ShaderResourceView)
    FXPORT_SET_SLOTS(DSSetShaderResources, ID3D11ShaderResourceView)
    FXPORT_SET_SLOTS(CSSetShaderResources, ID3D11ShaderResourceView)
    FXPORT_SET_SLOTS(VSSetSamplers, ID3D11SamplerState)
    FXPORT_SET_SLOTS(PSSetSamplers, ID3D11SamplerState)
    FXPORT_SET_SLOTS(GSSetSamplers, ID3D11SamplerState)
    FXPORT_SET_SLOTS(HSSetSamplers, ID3D11SamplerState)
    FXPORT_SET_SLOTS(DSSetSamplers, ID3D11SamplerState)
    FXPORT_SET_SLOTS(CSSetSamplers, ID3D11SamplerState)
#undef FXPORT_SET_SLOTS
    void CSSetUnorderedAccessViews(UINT start, UINT n, ID3D11UnorderedAccessView* const* u, const UINT* counts) override {
        state([start, n, held = hold(u, n), k = copyOf(counts, n)](auto& c) { c.CSSetUnorderedAccessViews(start, n, orNull(raw(held)), orNull(k)); });
    }
    void RSSetViewports(UINT n, const D3D11_VIEWPORT* v) override { state([n, held = copyOf(v, n)](auto& c) { c.RSSetViewports(n, orNull(held)); }); }
    void RSSetScissorRects(UINT n, const D3D11_RECT* r) override { state([n, held = copyOf(r, n)](auto& c) { c.RSSetScissorRects(n, orNull(held)); }); }
    void RSSetState(ID3D11RasterizerState* r) override { state([held = ComPtr<ID3D11RasterizerState>(r)](auto& c) { c.RSSetState(held.Get()); }); }
    void OMSetRenderTargets(UINT n, ID3D11RenderTargetView* const* t, ID3D11DepthStencilView* d) override {
        state([n, views = hold(t, n), depth = ComPtr<ID3D11DepthStencilView>(d)](auto& c) { c.OMSetRenderTargets(n, orNull(raw(views)), depth.Get()); });
    }
    void OMSetRenderTargetsAndUnorderedAccessViews(UINT nr, ID3D11RenderTargetView* const* t, ID3D11DepthStencilView* d, UINT start, UINT nu,
                                                   ID3D11UnorderedAccessView* const* u, const UINT* counts) override {
        // The D3D11_KEEP_* counts name no array: nothing to copy.
        const UINT rtvs = nr == D3D11_KEEP_RENDER_TARGETS_AND_DEPTH_STENCIL ? 0 : nr, uavs = nu == D3D11_KEEP_UNORDERED_ACCESS_VIEWS ? 0 : nu;
        state([nr, views = hold(t, rtvs), depth = ComPtr<ID3D11DepthStencilView>(d), start, nu, unordered = hold(u, uavs), k = copyOf(counts, uavs)](auto& c) {
            c.OMSetRenderTargetsAndUnorderedAccessViews(nr, orNull(raw(views)), depth.Get(), start, nu, orNull(raw(unordered)), orNull(k));
        });
    }
    void OMSetBlendState(ID3D11BlendState* b, const FLOAT factor[4], UINT mask) override {
        std::vector<FLOAT> f = copyOf(factor, factor ? 4 : 0);
        state([held = ComPtr<ID3D11BlendState>(b), f, mask](auto& c) { c.OMSetBlendState(held.Get(), orNull(f), mask); });
    }
    void OMSetDepthStencilState(ID3D11DepthStencilState* d, UINT ref) override {
        state([held = ComPtr<ID3D11DepthStencilState>(d), ref](auto& c) { c.OMSetDepthStencilState(held.Get(), ref); });
    }
    void ClearState() override {
        stateCommands_.clear();  // everything before is undone
        predicate_ = nullptr;
        predicateValue_ = FALSE;
        state([](auto& c) { c.ClearState(); });
    }

    // --- actions: recorded only
    void Draw(UINT n, UINT first) override { act([=](auto& c) { c.Draw(n, first); }); }
    void DrawIndexed(UINT n, UINT first, INT base) override { act([=](auto& c) { c.DrawIndexed(n, first, base); }); }
    void DrawInstanced(UINT n, UINT instances, UINT first, UINT firstInstance) override {
        act([=](auto& c) { c.DrawInstanced(n, instances, first, firstInstance); });
    }
    void DrawIndexedInstanced(UINT n, UINT instances, UINT first, INT base, UINT firstInstance) override {
        act([=](auto& c) { c.DrawIndexedInstanced(n, instances, first, base, firstInstance); });
    }
    void Dispatch(UINT x, UINT y, UINT z) override { act([=](auto& c) { c.Dispatch(x, y, z); }); }
    void DrawAuto() override { act([](auto& c) { c.DrawAuto(); }); }
    void SOSetTargets(UINT n, ID3D11Buffer* const* b, const UINT* offsets) override {
        state([n, held = hold(b, n), o = copyOf(offsets, n)](auto& c) { c.SOSetTargets(n, orNull(raw(held)), orNull(o)); });
    }
    void SOGetTargets(UINT n, ID3D11Buffer** b) override {  // a deferred context answers what it was given: nothing here
        for (UINT i = 0; b && i < n; ++i) b[i] = nullptr;
    }
    void UpdateSubresource(ID3D11Resource* dst, UINT sub, const D3D11_BOX* box, const void* data, UINT rowPitch, UINT depthPitch) override;
    void CopyResource(ID3D11Resource* dst, ID3D11Resource* src) override {
        act([to = ComPtr<ID3D11Resource>(dst), from = ComPtr<ID3D11Resource>(src)](auto& c) { c.CopyResource(to.Get(), from.Get()); });
    }
    void CopySubresourceRegion(ID3D11Resource* dst, UINT dstSub, UINT x, UINT y, UINT z, ID3D11Resource* src, UINT srcSub, const D3D11_BOX* box) override {
        act([to = ComPtr<ID3D11Resource>(dst), dstSub, x, y, z, from = ComPtr<ID3D11Resource>(src), srcSub, area = copyOf(box, box ? 1 : 0)](auto& c) {
            c.CopySubresourceRegion(to.Get(), dstSub, x, y, z, from.Get(), srcSub, orNull(area));
        });
    }
    void ClearRenderTargetView(ID3D11RenderTargetView* v, const FLOAT rgba[4]) override {
        act([held = ComPtr<ID3D11RenderTargetView>(v), f = copyOf(rgba, rgba ? 4 : 0)](auto& c) { c.ClearRenderTargetView(held.Get(), orNull(f)); });
    }
    void ClearDepthStencilView(ID3D11DepthStencilView* v, UINT flags, FLOAT depth, UINT8 stencil) override {
        act([held = ComPtr<ID3D11DepthStencilView>(v), flags, depth, stencil](auto& c) { c.ClearDepthStencilView(held.Get(), flags, depth, stencil); });
    }
    void GenerateMips(ID3D11ShaderResourceView* v) override {
        act([held = ComPtr<ID3D11ShaderResourceView>(v)](auto& c) { c.GenerateMips(held.Get()); });
    }
    void ResolveSubresource(ID3D11Resource* dst, UINT dstSub, ID3D11Resource* src, UINT srcSub, DXGI_FORMAT format) override {
        act([to = ComPtr<ID3D11Resource>(dst), dstSub, from = ComPtr<ID3D11Resource>(src), srcSub, format](auto& c) {
            c.ResolveSubresource(to.Get(), dstSub, from.Get(), srcSub, format);
        });
    }
    void Begin(ID3D11Asynchronous* q) override { act([held = ComPtr<ID3D11Asynchronous>(q)](auto& c) { c.Begin(held.Get()); }); }
    void End(ID3D11Asynchronous* q) override { act([held = ComPtr<ID3D11Asynchronous>(q)](auto& c) { c.End(held.Get()); }); }
    HRESULT GetData(ID3D11Asynchronous*, void*, UINT, UINT) override {
        return fail(DXGI_ERROR_INVALID_CALL, "GetData: a deferred context has no results; ask the immediate context");
    }
    void Flush() override {}  // nothing runs until ExecuteCommandList
    void SetPredication(ID3D11Predicate* p, BOOL value) override {
        predicate_ = p;
        predicateValue_ = value;
        state([held = ComPtr<ID3D11Predicate>(p), value](auto& c) { c.SetPredication(held.Get(), value); });
    }
    void GetPredication(ID3D11Predicate** pp, BOOL* value) override {
        if (pp) {
            *pp = predicate_.Get();
            if (*pp) (*pp)->AddRef();
        }
        if (value) *value = predicateValue_;
    }
    HRESULT Map(ID3D11Resource* r, UINT sub, D3D11_MAP type, UINT flags, D3D11_MAPPED_SUBRESOURCE* mapped) override;
    void Unmap(ID3D11Resource* r, UINT sub) override;

    D3D11_DEVICE_CONTEXT_TYPE GetType() override { return D3D11_DEVICE_CONTEXT_DEFERRED; }
    void ExecuteCommandList(ID3D11CommandList*, BOOL) override {
        note("ExecuteCommandList: a deferred context cannot run command lists (D3D's nested lists are not there)");
    }
    HRESULT FinishCommandList(BOOL restore, ID3D11CommandList** pp) override {
        if (!pp) return fail(E_INVALIDARG, "FinishCommandList: ppCommandList is null");
        if (mapped_) return fail(DXGI_ERROR_INVALID_CALL, "FinishCommandList: a buffer is still mapped on the deferred context");
        *pp = new CommandList(device_, std::move(commands_));
        commands_.clear();
        if (restore) commands_ = stateCommands_;  // the next list starts from the state this one ended in
        else stateCommands_.clear(), predicate_ = nullptr, predicateValue_ = FALSE;
        return succeed();
    }

private:
    ComPtr<ID3D11Predicate> predicate_;  // what GetPredication answers
    BOOL predicateValue_ = FALSE;
    void state(Command c) {
        stateCommands_.push_back(c);
        commands_.push_back(std::move(c));
    }
    void act(Command c) { commands_.push_back(std::move(c)); }

    std::vector<Command> commands_;
    std::vector<Command> stateCommands_;
    ComPtr<ID3D11Resource> mapped_;  // the buffer between Map and Unmap
    std::vector<std::uint8_t> mapBytes_;
};

void DeferredContext::UpdateSubresource(ID3D11Resource* dst, UINT sub, const D3D11_BOX* box, const void* data, UINT rowPitch, UINT depthPitch) {
    // The bytes the call reads: a buffer's box or whole width; a texture's rows (its level's, or the box's).
    std::size_t bytes = 0;
    if (auto* b = own<Buffer>(dst, device_)) {
        bytes = box ? std::size_t(box->right - box->left) : b->desc.ByteWidth;
    } else if (auto* t = own<Texture>(dst, device_)) {
        const int level = int(sub % UINT(std::max(1, t->levels)));
        const std::size_t texel = t->levelBytes(level) / (std::size_t(t->levelWidth(level)) * std::size_t(t->levelHeight(level)));
        const std::size_t width = box ? std::size_t(box->right - box->left) : std::size_t(t->levelWidth(level));
        const std::size_t rows = box ? std::size_t(box->bottom - box->top) : std::size_t(t->levelHeight(level));
        bytes = rows == 0 ? 0 : (rows - 1) * rowPitch + width * texel;
    } else {
        return note("UpdateSubresource: pDstResource is null or not a resource of this device");
    }
    std::vector<std::uint8_t> source(bytes);
    if (data && bytes) std::memcpy(source.data(), data, bytes);
    act([held = ComPtr<ID3D11Resource>(dst), sub, area = copyOf(box, box ? 1 : 0), written = std::move(source), rowPitch, depthPitch](auto& c) {
        c.UpdateSubresource(held.Get(), sub, orNull(area), written.data(), rowPitch, depthPitch);
    });
}

HRESULT DeferredContext::Map(ID3D11Resource* r, UINT sub, D3D11_MAP type, UINT, D3D11_MAPPED_SUBRESOURCE* mapped) {
    Buffer* b = own<Buffer>(r, device_);
    if (!b || type != D3D11_MAP_WRITE_DISCARD || b->desc.Usage != D3D11_USAGE_DYNAMIC || sub != 0)
        return fail(E_INVALIDARG, "Map: a deferred context maps DYNAMIC buffers with D3D11_MAP_WRITE_DISCARD only (MapType = " +
                                      std::to_string(type) + ", Subresource = " + std::to_string(sub) + ")");
    if (!mapped) return fail(E_INVALIDARG, "Map: pMappedResource is null");
    if (mapped_) return fail(E_INVALIDARG, "Map: another buffer is mapped on this deferred context; Unmap it first");
    mapped_ = r;
    mapBytes_.assign(b->desc.ByteWidth, 0);
    mapped->pData = mapBytes_.data();
    mapped->RowPitch = mapped->DepthPitch = b->desc.ByteWidth;
    return succeed();
}

void DeferredContext::Unmap(ID3D11Resource* r, UINT) {
    if (!mapped_ || mapped_.Get() != r) return note("Unmap: the resource is not mapped on this deferred context");
    act([b = mapped_, bytes = std::move(mapBytes_)](auto& c) {
        D3D11_MAPPED_SUBRESOURCE m;
        if (FAILED(c.Map(b.Get(), 0, D3D11_MAP_WRITE_DISCARD, 0, &m))) return;
        std::memcpy(m.pData, bytes.data(), bytes.size());
        c.Unmap(b.Get(), 0);
    });
    mapped_ = nullptr;
    mapBytes_.clear();
}

}  // namespace

HRESULT Device::CreateDeferredContext(UINT flags, ID3D11DeviceContext** pp) {
    if (flags != 0) return fail(E_INVALIDARG, "CreateDeferredContext: ContextFlags = " + std::to_string(flags) + " (must be 0)");
    if (!pp) return fail(E_INVALIDARG, "CreateDeferredContext: ppDeferredContext is null");
    *pp = new DeferredContext(this);
    return succeed();
}

HRESULT Context::FinishCommandList(BOOL, ID3D11CommandList**) {
    return fail(DXGI_ERROR_INVALID_CALL, "FinishCommandList: the immediate context records nothing; call it on a deferred context");
}

struct Context::Bindings {
    ComPtr<InputLayout> layout;
    std::array<VertexSlot, D3D11_IA_VERTEX_INPUT_RESOURCE_SLOT_COUNT> vertexSlots;
    ComPtr<Buffer> indexBuffer;
    DXGI_FORMAT indexFormat;
    UINT indexOffset;
    D3D11_PRIMITIVE_TOPOLOGY topology;
    ComPtr<VertexShader> vs;
    ComPtr<PixelShader> ps;
    ComPtr<GeometryShader> gs;
    ComPtr<HullShader> hs;
    ComPtr<DomainShader> ds;
    ComPtr<ComputeShader> cs;
    std::array<Stage, 6> stages;
    UavSlots csUavs, psUavs;
    std::vector<Viewport> viewports;
    std::vector<Rectangle> scissors;
    ComPtr<RasterizerState> rasterizer;
    ComPtr<BlendState> blend;
    std::array<FLOAT, 4> blendFactor;
    UINT sampleMask;
    ComPtr<DepthStencilState> depthStencil;
    UINT stencilRef;
    std::array<ComPtr<RenderTargetView>, D3D11_SIMULTANEOUS_RENDER_TARGET_COUNT> targets;
    ComPtr<DepthStencilView> depthView;
    EffectPass* effectPass;
    const void* effectOwner;
    ComPtr<Query> predicate;
    BOOL predicateValue;
};

Context::Bindings Context::bindings() const {
    return Bindings{layout_, vertexSlots_, indexBuffer_, indexFormat_, indexOffset_, topology_, vertexShader_, pixelShader_,
                    geometryShader_, hullShader_, domainShader_, computeShader_, {vs_, ps_, gs_, hs_, ds_, cs_}, csUavs_, psUavs_,
                    viewports_, scissors_, rasterizer_, blend_, {blendFactor_[0], blendFactor_[1], blendFactor_[2], blendFactor_[3]},
                    sampleMask_, depthStencil_, stencilRef_, targets_, depthView_, effectPass_, effectOwner_, predicate_, predicateValue_};
}

void Context::rebind(const Bindings& b) {
    layout_ = b.layout;
    vertexSlots_ = b.vertexSlots;
    indexBuffer_ = b.indexBuffer;
    indexFormat_ = b.indexFormat;
    indexOffset_ = b.indexOffset;
    topology_ = b.topology;
    vertexShader_ = b.vs;
    pixelShader_ = b.ps;
    geometryShader_ = b.gs;
    hullShader_ = b.hs;
    domainShader_ = b.ds;
    computeShader_ = b.cs;
    Stage* stages[6] = {&vs_, &ps_, &gs_, &hs_, &ds_, &cs_};
    for (std::size_t i = 0; i < 6; ++i) *stages[i] = b.stages[i];
    csUavs_ = b.csUavs;
    psUavs_ = b.psUavs;
    viewports_ = b.viewports;
    scissors_ = b.scissors;
    rasterizer_ = b.rasterizer;
    blend_ = b.blend;
    std::copy(b.blendFactor.begin(), b.blendFactor.end(), blendFactor_);
    sampleMask_ = b.sampleMask;
    depthStencil_ = b.depthStencil;
    stencilRef_ = b.stencilRef;
    targets_ = b.targets;
    depthView_ = b.depthView;
    effectPass_ = b.effectPass;
    effectOwner_ = b.effectOwner;
    predicate_ = b.predicate;
    predicateValue_ = b.predicateValue;
}

void Context::ExecuteCommandList(ID3D11CommandList* list, BOOL restore) {
    auto* commands = own<CommandList>(list, device_);
    if (!commands) return note("ExecuteCommandList: pCommandList is null or not a command list of this device");
    std::optional<Bindings> saved;
    if (restore) saved = bindings();
    ClearState();  // a command list runs from D3D's default state
    for (const Command& c : commands->commands) c(*this);
    ClearState();
    if (saved) rebind(*saved);
}

}  // namespace fxport::d3d11
