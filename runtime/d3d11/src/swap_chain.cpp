// The headless swap chain (dxgi.h): a back buffer texture made through the device's own
// CreateTexture2D (so its checks and messages are D3D's), handed out by GetBuffer; Present
// flushes the context's work and counts the frame.
#include <atomic>

#include "d3d11_impl.h"
#include "fxport/d3d11/dxgi.h"

namespace fxport::d3d11 {

namespace {

class SwapChain final : public IDXGISwapChain {
public:
    SwapChain(ID3D11Device* device, const DXGI_SWAP_CHAIN_DESC& desc, ComPtr<ID3D11Texture2D> backBuffer)
        : device_(device), desc_(desc), backBuffer_(std::move(backBuffer)) {}
    ULONG AddRef() override { return ++references_; }
    ULONG Release() override {
        const ULONG left = --references_;
        if (left == 0) delete this;
        return left;
    }
    HRESULT Present(UINT, UINT) override {
        ComPtr<ID3D11DeviceContext> context;
        device_->GetImmediateContext(context.GetAddressOf());
        context->Flush();
        ++presented_;
        return succeed();
    }
    HRESULT GetBuffer(UINT Buffer, REFIID riid, void** ppSurface) override {
        if (!ppSurface) return fail(E_INVALIDARG, "IDXGISwapChain::GetBuffer: ppSurface is null");
        if (Buffer != 0)
            return fail(E_INVALIDARG, "IDXGISwapChain::GetBuffer: Buffer = " + std::to_string(Buffer) + " (a DISCARD swap chain gives buffer 0 only)");
        if (!(riid == IID_ID3D11Texture2D) && !(riid == IID_ID3D10Texture2D))
            return fail(E_INVALIDARG, "IDXGISwapChain::GetBuffer: riid is not IID_ID3D11Texture2D or IID_ID3D10Texture2D");
        backBuffer_->AddRef();
        *ppSurface = backBuffer_.Get();
        return succeed();
    }
    HRESULT SetFullscreenState(BOOL Fullscreen, void*) override {
        if (Fullscreen) {
            note("IDXGISwapChain::SetFullscreenState: the swap chain is headless; it stays windowed");
            return S_FALSE;
        }
        return succeed();
    }
    HRESULT GetDesc(DXGI_SWAP_CHAIN_DESC* pDesc) override {
        if (!pDesc) return fail(E_INVALIDARG, "IDXGISwapChain::GetDesc: pDesc is null");
        *pDesc = desc_;
        return succeed();
    }
    UINT PresentCount() override { return presented_; }

private:
    ComPtr<ID3D11Device> device_;
    DXGI_SWAP_CHAIN_DESC desc_;
    ComPtr<ID3D11Texture2D> backBuffer_;
    std::atomic<ULONG> references_{1};
    UINT presented_ = 0;
};

}  // namespace

HRESULT CreateHeadlessSwapChain(ID3D11Device* device, const DXGI_SWAP_CHAIN_DESC* desc, IDXGISwapChain** ppSwapChain) {
    if (!device) return fail(E_INVALIDARG, "CreateSwapChain: no device");
    if (!desc) return fail(E_INVALIDARG, "CreateSwapChain: pSwapChainDesc is null");
    const std::string at = "CreateSwapChain: DXGI_SWAP_CHAIN_DESC.";
    if (desc->BufferDesc.Width == 0 || desc->BufferDesc.Height == 0)
        return fail(E_INVALIDARG, at + "BufferDesc.Width x Height = " + std::to_string(desc->BufferDesc.Width) + " x " +
                                      std::to_string(desc->BufferDesc.Height) + " (a headless swap chain needs its size)");
    if (desc->BufferCount == 0) return fail(E_INVALIDARG, at + "BufferCount = 0");
    D3D11_TEXTURE2D_DESC t;
    t.Width = desc->BufferDesc.Width;
    t.Height = desc->BufferDesc.Height;
    t.MipLevels = 1;
    t.ArraySize = 1;
    t.Format = desc->BufferDesc.Format;
    t.BindFlags = D3D11_BIND_RENDER_TARGET | D3D11_BIND_SHADER_RESOURCE;
    t.SampleDesc = desc->SampleDesc;  // a multisampled back buffer is a multisampled target (CreateTexture2D checks the count)
    ComPtr<ID3D11Texture2D> backBuffer;
    if (HRESULT hr = device->CreateTexture2D(&t, nullptr, backBuffer.GetAddressOf()); FAILED(hr)) return hr;
    if (ppSwapChain) *ppSwapChain = new SwapChain(device, *desc, backBuffer);
    return succeed();
}

HRESULT D3D11CreateDeviceAndSwapChain(void* pAdapter, D3D_DRIVER_TYPE DriverType, void* Software, UINT Flags,
                                      const D3D_FEATURE_LEVEL* pFeatureLevels, UINT FeatureLevels, UINT SDKVersion,
                                      const DXGI_SWAP_CHAIN_DESC* pSwapChainDesc, IDXGISwapChain** ppSwapChain, ID3D11Device** ppDevice,
                                      D3D_FEATURE_LEVEL* pFeatureLevel, ID3D11DeviceContext** ppImmediateContext) {
    ComPtr<ID3D11Device> device;
    ComPtr<ID3D11DeviceContext> context;
    HRESULT hr = D3D11CreateDevice(pAdapter, DriverType, Software, Flags, pFeatureLevels, FeatureLevels, SDKVersion, device.GetAddressOf(),
                                   pFeatureLevel, context.GetAddressOf());
    if (FAILED(hr)) return hr;
    ComPtr<IDXGISwapChain> swapChain;
    if (ppSwapChain) {
        hr = CreateHeadlessSwapChain(device.Get(), pSwapChainDesc, swapChain.GetAddressOf());
        if (FAILED(hr)) return hr;
        *ppSwapChain = swapChain.Detach();
    }
    if (ppDevice) *ppDevice = device.Detach();
    if (ppImmediateContext) *ppImmediateContext = context.Detach();
    return succeed();
}

}  // namespace fxport::d3d11
