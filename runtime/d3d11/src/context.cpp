// The immediate context. Set* calls only record bindings (with a reference, as D3D holds them); a
// draw copies them into the device core -- targets, shaders, each cbuffer slot to the GL binding
// of the block it feeds, each t#/s# pair to the texture unit the translation samples it on, the
// decoded state objects into the device's state -- and draws; the device core compares with what
// GL has and calls GL only for what differs. D3D ignores invalid draws; so does this, noting why
// (GetLastErrorMessage). This file: the Set calls; context_draw.cpp: draws and dispatches;
// context_resources.cpp: Map, updates, copies and clears.
#include "context.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "guarded.h"

namespace fxport::d3d11 {

Context::Context(Device* device) : device_(device) { ClearState(); }

void Context::ClearState() {
    layout_ = nullptr;
    for (VertexSlot& v : vertexSlots_) v = VertexSlot{};
    indexBuffer_ = nullptr;
    SOSetTargets(0, nullptr, nullptr);
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
    for (auto& u : psUavs_) u = nullptr;
    viewports_.clear();
    scissors_.clear();
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
    predicate_ = nullptr;
    predicateValue_ = FALSE;
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

// Each viewport and scissor rectangle (D3D11 has 16; SV_ViewportArrayIndex picks one), as the
// device core's: whole pixels, as for XNA.
void Context::RSSetViewports(UINT n, const D3D11_VIEWPORT* p) {
    if (n > D3D11_VIEWPORT_AND_SCISSORRECT_OBJECT_COUNT_PER_PIPELINE)
        return note("RSSetViewports: " + std::to_string(n) + " viewports; D3D11 has 16; nothing set");
    viewports_.clear();
    for (UINT i = 0; p && i < n; ++i) {
        const D3D11_VIEWPORT& d = p[i];
        Viewport v(int(std::lround(d.TopLeftX)), int(std::lround(d.TopLeftY)), int(std::lround(d.Width)), int(std::lround(d.Height)));
        v.MinDepth = d.MinDepth;
        v.MaxDepth = d.MaxDepth;
        viewports_.push_back(v);
    }
}
void Context::RSSetScissorRects(UINT n, const D3D11_RECT* p) {
    if (n > D3D11_VIEWPORT_AND_SCISSORRECT_OBJECT_COUNT_PER_PIPELINE)
        return note("RSSetScissorRects: " + std::to_string(n) + " rectangles; D3D11 has 16; nothing set");
    scissors_.clear();
    for (UINT i = 0; p && i < n; ++i) scissors_.emplace_back(p[i].left, p[i].top, p[i].right - p[i].left, p[i].bottom - p[i].top);
}
void Context::RSSetState(ID3D11RasterizerState* p) { rasterizer_ = own<RasterizerState>(p, device_); }

void Context::OMSetRenderTargets(UINT n, ID3D11RenderTargetView* const* pp, ID3D11DepthStencilView* dsv) {
    for (auto& t : targets_) t = nullptr;
    for (UINT i = 0; i < n && i < targets_.size(); ++i) targets_[i] = pp ? own<RenderTargetView>(pp[i], device_) : nullptr;
    depthView_ = own<DepthStencilView>(dsv, device_);
}
void Context::OMSetRenderTargetsAndUnorderedAccessViews(UINT numRtvs, ID3D11RenderTargetView* const* rtvs, ID3D11DepthStencilView* dsv,
                                                        UINT uavStart, UINT numUavs, ID3D11UnorderedAccessView* const* uavs, const UINT*) {
    const char* call = "OMSetRenderTargetsAndUnorderedAccessViews";
    const bool keepTargets = numRtvs == D3D11_KEEP_RENDER_TARGETS_AND_DEPTH_STENCIL;
    if (numUavs != D3D11_KEEP_UNORDERED_ACCESS_VIEWS && numUavs > 0) {
        const UINT lastTarget = keepTargets ? 0 : numRtvs;
        if (uavStart < lastTarget || uavStart >= psUavs_.size() || numUavs > psUavs_.size() - uavStart)
            return note(std::string(call) + ": UAVStartSlot " + std::to_string(uavStart) + ", NumUAVs " + std::to_string(numUavs) +
                        ": the UAVs must follow the " + std::to_string(lastTarget) + " render targets within u0..u" +
                        std::to_string(psUavs_.size() - 1) + "; nothing set");
    }
    if (!keepTargets) OMSetRenderTargets(numRtvs, rtvs, dsv);
    if (numUavs == D3D11_KEEP_UNORDERED_ACCESS_VIEWS) return;
    for (auto& u : psUavs_) u = nullptr;
    if (numUavs > 0) setSlots<UavSlots, ID3D11UnorderedAccessView, UnorderedAccessView>(psUavs_, uavStart, numUavs, uavs, device_, call);
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

}  // namespace fxport::d3d11
