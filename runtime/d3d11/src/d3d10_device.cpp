// D3D10's device as a thin adapter (fxport/d3d10/d3d10_interfaces.h): every call goes to the D3D11
// device or its immediate context, converting the two descriptions D3D10 spells differently
// (D3D10_VIEWPORT, D3D10_BLEND_DESC). Resources, views, shaders and states are the D3D11 objects.
#include <array>
#include <atomic>

#include "d3d10_queries.h"
#include "d3d11_impl.h"
#include "fxport/d3d10.h"

namespace fxport::d3d10 {

namespace {

// D3D10's blend description as D3D11's: the one blend for every target, enabled and masked per target.
// A target whose write mask is 0 takes target 0's enable: nothing of it is written either way,
// and fxport blends every target alike (one blend, per-target masks).
D3D11_BLEND_DESC blendDesc11(const D3D10_BLEND_DESC& d) {
    D3D11_BLEND_DESC out;
    out.AlphaToCoverageEnable = d.AlphaToCoverageEnable;
    out.IndependentBlendEnable = TRUE;
    for (int i = 0; i < 8; ++i) {
        D3D11_RENDER_TARGET_BLEND_DESC& t = out.RenderTarget[i];
        t.BlendEnable = d.RenderTargetWriteMask[i] == 0 ? d.BlendEnable[0] : d.BlendEnable[i];
        t.SrcBlend = d.SrcBlend;
        t.DestBlend = d.DestBlend;
        t.BlendOp = d.BlendOp;
        t.SrcBlendAlpha = d.SrcBlendAlpha;
        t.DestBlendAlpha = d.DestBlendAlpha;
        t.BlendOpAlpha = d.BlendOpAlpha;
        t.RenderTargetWriteMask = d.RenderTargetWriteMask[i];
        if (i >= 4 && d.RenderTargetWriteMask[i] == 0) t.RenderTargetWriteMask = D3D11_COLOR_WRITE_ENABLE_ALL;  // fxport binds 4 targets at most
    }
    return out;
}

class BlendState10 final : public ID3D10BlendState {
public:
    BlendState10(ComPtr<ID3D11BlendState> state, const D3D10_BLEND_DESC& desc) : state_(std::move(state)), desc_(desc) {}
    ULONG AddRef() override { return ++references_; }
    ULONG Release() override {
        const ULONG left = --references_;
        if (left == 0) delete this;
        return left;
    }
    void GetDevice(ID3D11Device** ppDevice) override { state_->GetDevice(ppDevice); }
    void GetDesc(D3D10_BLEND_DESC* pDesc) override {
        if (pDesc) *pDesc = desc_;
    }
    ID3D11BlendState* state() const { return state_.Get(); }

private:
    ComPtr<ID3D11BlendState> state_;
    D3D10_BLEND_DESC desc_;
    std::atomic<ULONG> references_{1};
};

class Device10 final : public ID3D10Device {
public:
    explicit Device10(ComPtr<ID3D11Device> device) : device_(std::move(device)) { device_->GetImmediateContext(context_.GetAddressOf()); }
    ULONG AddRef() override { return ++references_; }
    ULONG Release() override {
        const ULONG left = --references_;
        if (left == 0) delete this;
        return left;
    }
    ID3D11Device* GetD3D11Device() override { return device_.Get(); }
    ID3D11DeviceContext* GetD3D11Context() override { return context_.Get(); }

    HRESULT CreateBuffer(const D3D10_BUFFER_DESC* d, const D3D10_SUBRESOURCE_DATA* i, ID3D10Buffer** pp) override {
        return device_->CreateBuffer(d, i, pp);
    }
    HRESULT CreateTexture1D(const D3D10_TEXTURE1D_DESC* d, const D3D10_SUBRESOURCE_DATA* i, ID3D10Texture1D** pp) override {
        return device_->CreateTexture1D(d, i, pp);
    }
    HRESULT CreateTexture2D(const D3D10_TEXTURE2D_DESC* d, const D3D10_SUBRESOURCE_DATA* i, ID3D10Texture2D** pp) override {
        return device_->CreateTexture2D(d, i, pp);
    }
    HRESULT CreateShaderResourceView(ID3D10Resource* r, const D3D10_SHADER_RESOURCE_VIEW_DESC* d, ID3D10ShaderResourceView** pp) override {
        return device_->CreateShaderResourceView(r, d, pp);
    }
    HRESULT CreateRenderTargetView(ID3D10Resource* r, const D3D10_RENDER_TARGET_VIEW_DESC* d, ID3D10RenderTargetView** pp) override {
        return device_->CreateRenderTargetView(r, d, pp);
    }
    HRESULT CreateDepthStencilView(ID3D10Resource* r, const D3D10_DEPTH_STENCIL_VIEW_DESC* d, ID3D10DepthStencilView** pp) override {
        return device_->CreateDepthStencilView(r, d, pp);
    }
    HRESULT CreateInputLayout(const D3D10_INPUT_ELEMENT_DESC* e, UINT n, const void* b, SIZE_T l, ID3D10InputLayout** pp) override {
        return device_->CreateInputLayout(e, n, b, l, pp);
    }
    HRESULT CreateVertexShader(const void* b, SIZE_T l, ID3D10VertexShader** pp) override { return device_->CreateVertexShader(b, l, nullptr, pp); }
    HRESULT CreatePixelShader(const void* b, SIZE_T l, ID3D10PixelShader** pp) override { return device_->CreatePixelShader(b, l, nullptr, pp); }
    HRESULT CreateGeometryShaderWithStreamOutput(const void* b, SIZE_T l, const D3D10_SO_DECLARATION_ENTRY* entries, UINT count, UINT stride,
                                                 ID3D10GeometryShader** pp) override {
        // D3D10's entries are D3D11's on stream 0; one stride, of slot 0 (D3D10 writes several slots
        // only with one entry each, whose strides are their sizes).
        std::vector<D3D11_SO_DECLARATION_ENTRY> d3d11(count);
        for (UINT i = 0; i < count && entries; ++i)
            d3d11[i] = {0, entries[i].SemanticName, entries[i].SemanticIndex, entries[i].StartComponent, entries[i].ComponentCount, entries[i].OutputSlot};
        const UINT strides[1] = {stride};
        return device_->CreateGeometryShaderWithStreamOutput(b, l, entries ? d3d11.data() : nullptr, count, strides, 1, 0, nullptr, pp);
    }
    HRESULT CreateGeometryShader(const void* b, SIZE_T l, ID3D10GeometryShader** pp) override {
        return device_->CreateGeometryShader(b, l, nullptr, pp);
    }
    HRESULT CreateBlendState(const D3D10_BLEND_DESC* d, ID3D10BlendState** pp) override {
        if (!d) return d3d11::fail(E_INVALIDARG, "CreateBlendState: the description is null");
        for (int i = 1; i < 8; ++i)
            if (d->RenderTargetWriteMask[i] != 0 && (d->BlendEnable[i] != 0) != (d->BlendEnable[0] != 0))
                return d3d11::fail(E_NOTIMPL, "CreateBlendState: D3D10_BLEND_DESC.BlendEnable[" + std::to_string(i) + "] = " +
                                                  (d->BlendEnable[i] ? "TRUE" : "FALSE") + " unlike BlendEnable[0] with RenderTargetWriteMask[" +
                                                  std::to_string(i) + "] = " + std::to_string(d->RenderTargetWriteMask[i]) +
                                                  ": fxport blends every target alike (a target not written may differ: mask 0)");
        const D3D11_BLEND_DESC desc = blendDesc11(*d);
        ComPtr<ID3D11BlendState> state;
        // D3D11's messages name RenderTarget[i]'s fields, which D3D10_BLEND_DESC holds once (or per target).
        if (HRESULT hr = device_->CreateBlendState(&desc, pp ? state.GetAddressOf() : nullptr); FAILED(hr)) return hr;
        if (pp) *pp = new BlendState10(state, *d);
        return S_OK;
    }
    HRESULT CreateDepthStencilState(const D3D10_DEPTH_STENCIL_DESC* d, ID3D10DepthStencilState** pp) override {
        return device_->CreateDepthStencilState(d, pp);
    }
    HRESULT CreateRasterizerState(const D3D10_RASTERIZER_DESC* d, ID3D10RasterizerState** pp) override {
        return device_->CreateRasterizerState(d, pp);
    }
    HRESULT CreateSamplerState(const D3D10_SAMPLER_DESC* d, ID3D10SamplerState** pp) override { return device_->CreateSamplerState(d, pp); }

    void IASetInputLayout(ID3D10InputLayout* p) override { context_->IASetInputLayout(p); }
    void IASetVertexBuffers(UINT s, UINT n, ID3D10Buffer* const* pp, const UINT* strides, const UINT* offsets) override {
        context_->IASetVertexBuffers(s, n, pp, strides, offsets);
    }
    void IASetIndexBuffer(ID3D10Buffer* p, DXGI_FORMAT f, UINT o) override { context_->IASetIndexBuffer(p, f, o); }
    void IASetPrimitiveTopology(D3D10_PRIMITIVE_TOPOLOGY t) override { context_->IASetPrimitiveTopology(t); }
    void VSSetShader(ID3D10VertexShader* p) override { context_->VSSetShader(p, nullptr, 0); }
    void PSSetShader(ID3D10PixelShader* p) override { context_->PSSetShader(p, nullptr, 0); }
    void GSSetShader(ID3D10GeometryShader* p) override { context_->GSSetShader(p, nullptr, 0); }
    void VSSetConstantBuffers(UINT s, UINT n, ID3D10Buffer* const* pp) override { context_->VSSetConstantBuffers(s, n, pp); }
    void PSSetConstantBuffers(UINT s, UINT n, ID3D10Buffer* const* pp) override { context_->PSSetConstantBuffers(s, n, pp); }
    void GSSetConstantBuffers(UINT s, UINT n, ID3D10Buffer* const* pp) override { context_->GSSetConstantBuffers(s, n, pp); }
    void VSSetShaderResources(UINT s, UINT n, ID3D10ShaderResourceView* const* pp) override { context_->VSSetShaderResources(s, n, pp); }
    void PSSetShaderResources(UINT s, UINT n, ID3D10ShaderResourceView* const* pp) override { context_->PSSetShaderResources(s, n, pp); }
    void GSSetShaderResources(UINT s, UINT n, ID3D10ShaderResourceView* const* pp) override { context_->GSSetShaderResources(s, n, pp); }
    void VSSetSamplers(UINT s, UINT n, ID3D10SamplerState* const* pp) override { context_->VSSetSamplers(s, n, pp); }
    void PSSetSamplers(UINT s, UINT n, ID3D10SamplerState* const* pp) override { context_->PSSetSamplers(s, n, pp); }
    void GSSetSamplers(UINT s, UINT n, ID3D10SamplerState* const* pp) override { context_->GSSetSamplers(s, n, pp); }
    void RSSetViewports(UINT n, const D3D10_VIEWPORT* p) override {
        std::vector<D3D11_VIEWPORT> viewports(n);
        for (UINT i = 0; i < n && p; ++i)
            viewports[i] = D3D11_VIEWPORT{FLOAT(p[i].TopLeftX), FLOAT(p[i].TopLeftY), FLOAT(p[i].Width), FLOAT(p[i].Height), p[i].MinDepth, p[i].MaxDepth};
        context_->RSSetViewports(p ? n : 0, viewports.data());
    }
    void RSSetScissorRects(UINT n, const D3D10_RECT* p) override { context_->RSSetScissorRects(n, p); }
    void RSSetState(ID3D10RasterizerState* p) override { context_->RSSetState(p); }
    void OMSetRenderTargets(UINT n, ID3D10RenderTargetView* const* pp, ID3D10DepthStencilView* dsv) override {
        context_->OMSetRenderTargets(n, pp, dsv);
    }
    void OMSetBlendState(ID3D10BlendState* p, const FLOAT factor[4], UINT mask) override {
        auto* state = dynamic_cast<BlendState10*>(p);
        if (p && !state) return d3d11::note("OMSetBlendState: the blend state was not made by an fxport ID3D10Device");
        context_->OMSetBlendState(state ? state->state() : nullptr, factor, mask);
    }
    void OMSetDepthStencilState(ID3D10DepthStencilState* p, UINT ref) override { context_->OMSetDepthStencilState(p, ref); }
    void Draw(UINT c, UINT s) override { context_->Draw(c, s); }
    void DrawIndexed(UINT c, UINT s, INT b) override { context_->DrawIndexed(c, s, b); }
    void DrawInstanced(UINT c, UINT n, UINT s, UINT i) override { context_->DrawInstanced(c, n, s, i); }
    void DrawAuto() override { context_->DrawAuto(); }
    void SOSetTargets(UINT n, ID3D10Buffer* const* pp, const UINT* offsets) override {
        for (UINT i = 0; i < soOffsets_.size(); ++i) soOffsets_[i] = i < n && pp && pp[i] && offsets ? offsets[i] : 0;
        context_->SOSetTargets(n, pp, offsets);
    }
    // D3D10 answers the offsets too: the ones SOSetTargets was given (-1 for an append).
    void SOGetTargets(UINT n, ID3D10Buffer** pp, UINT* offsets) override {
        context_->SOGetTargets(n, pp);
        for (UINT i = 0; offsets && i < n; ++i) offsets[i] = i < soOffsets_.size() ? soOffsets_[i] : 0;
    }
    void DrawIndexedInstanced(UINT c, UINT n, UINT s, INT b, UINT i) override { context_->DrawIndexedInstanced(c, n, s, b, i); }
    void ClearRenderTargetView(ID3D10RenderTargetView* v, const FLOAT c[4]) override { context_->ClearRenderTargetView(v, c); }
    void ClearDepthStencilView(ID3D10DepthStencilView* v, UINT f, FLOAT d, UINT8 s) override { context_->ClearDepthStencilView(v, f, d, s); }
    void UpdateSubresource(ID3D10Resource* r, UINT sub, const D3D10_BOX* box, const void* data, UINT row, UINT depth) override {
        context_->UpdateSubresource(r, sub, box, data, row, depth);
    }
    void CopyResource(ID3D10Resource* d, ID3D10Resource* s) override { context_->CopyResource(d, s); }
    void CopySubresourceRegion(ID3D10Resource* d, UINT ds, UINT x, UINT y, UINT z, ID3D10Resource* s, UINT ss, const D3D10_BOX* box) override {
        context_->CopySubresourceRegion(d, ds, x, y, z, s, ss, box);
    }
    void GenerateMips(ID3D10ShaderResourceView* v) override { context_->GenerateMips(v); }
    void ClearState() override {
        context_->ClearState();
        predicate_ = nullptr;
        predicateValue_ = FALSE;
        soOffsets_ = {};
    }
    void Flush() override { context_->Flush(); }
    HRESULT CreateQuery(const D3D10_QUERY_DESC* d, ID3D10Query** pp) override {
        ID3D10Predicate* made = nullptr;
        const HRESULT hr = createQuery10(device_.Get(), context_.Get(), d, false, pp ? &made : nullptr);
        if (pp) *pp = made;
        return hr;
    }
    HRESULT CreatePredicate(const D3D10_QUERY_DESC* d, ID3D10Predicate** pp) override {
        return createQuery10(device_.Get(), context_.Get(), d, true, pp);
    }
    void SetPredication(ID3D10Predicate* p, BOOL value) override {
        context_->SetPredication(predicate11(p), value);
        predicate_ = p;
        predicateValue_ = value;
    }
    HRESULT CheckFormatSupport(DXGI_FORMAT format, UINT* support) override { return device_->CheckFormatSupport(format, support); }
    HRESULT CheckMultisampleQualityLevels(DXGI_FORMAT format, UINT samples, UINT* levels) override {
        return device_->CheckMultisampleQualityLevels(format, samples, levels);
    }
    UINT GetCreationFlags() override { return device_->GetCreationFlags(); }
    HRESULT GetDeviceRemovedReason() override { return S_OK; }
    void GetPredication(ID3D10Predicate** pp, BOOL* value) override {
        if (pp) {
            *pp = predicate_.Get();
            if (*pp) (*pp)->AddRef();
        }
        if (value) *value = predicateValue_;
    }

private:
    ComPtr<ID3D11Device> device_;
    ComPtr<ID3D11DeviceContext> context_;
    std::array<UINT, 4> soOffsets_{};  // what SOSetTargets was given, which SOGetTargets answers
    ComPtr<ID3D10Predicate> predicate_;  // the D3D10 object SetPredication was given (GetPredication's answer)
    BOOL predicateValue_ = FALSE;
    std::atomic<ULONG> references_{1};
};

D3D_DRIVER_TYPE driverType11(D3D10_DRIVER_TYPE t) {
    switch (t) {
    case D3D10_DRIVER_TYPE_HARDWARE: return D3D_DRIVER_TYPE_HARDWARE;
    case D3D10_DRIVER_TYPE_REFERENCE: return D3D_DRIVER_TYPE_REFERENCE;
    case D3D10_DRIVER_TYPE_WARP: return D3D_DRIVER_TYPE_WARP;
    default: return D3D_DRIVER_TYPE_NULL;  // refused below
    }
}

}  // namespace

HRESULT D3D10CreateDevice(void* pAdapter, D3D10_DRIVER_TYPE DriverType, void* Software, UINT Flags, UINT SDKVersion, ID3D10Device** ppDevice) {
    if (SDKVersion != D3D10_SDK_VERSION)
        return d3d11::fail(E_INVALIDARG, "D3D10CreateDevice: SDKVersion = " + std::to_string(SDKVersion) + " (D3D10_SDK_VERSION is 29)");
    if (driverType11(DriverType) == D3D_DRIVER_TYPE_NULL)
        return d3d11::fail(E_INVALIDARG, "D3D10CreateDevice: DriverType = " + std::to_string(DriverType) + " (HARDWARE, REFERENCE or WARP)");
    const D3D_FEATURE_LEVEL level = D3D_FEATURE_LEVEL_10_0;
    ComPtr<ID3D11Device> device;
    HRESULT hr = D3D11CreateDevice(pAdapter, driverType11(DriverType), Software, Flags, &level, 1, D3D11_SDK_VERSION, device.GetAddressOf(),
                                   nullptr, nullptr);
    if (FAILED(hr)) return hr;
    if (ppDevice) *ppDevice = new Device10(device);
    return d3d11::succeed();
}

HRESULT D3D10CreateDeviceAndSwapChain(void* pAdapter, D3D10_DRIVER_TYPE DriverType, void* Software, UINT Flags, UINT SDKVersion,
                                      const DXGI_SWAP_CHAIN_DESC* pSwapChainDesc, IDXGISwapChain** ppSwapChain, ID3D10Device** ppDevice) {
    ComPtr<ID3D10Device> device;
    HRESULT hr = D3D10CreateDevice(pAdapter, DriverType, Software, Flags, SDKVersion, device.GetAddressOf());
    if (FAILED(hr)) return hr;
    if (ppSwapChain) {
        hr = CreateHeadlessSwapChain(device->GetD3D11Device(), pSwapChainDesc, ppSwapChain);
        if (FAILED(hr)) return hr;
    }
    if (ppDevice) *ppDevice = device.Detach();
    return d3d11::succeed();
}

}  // namespace fxport::d3d10
