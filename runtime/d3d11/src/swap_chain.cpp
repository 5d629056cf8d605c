// The headless swap chain (dxgi.h): a back buffer texture made through the device's own
// CreateTexture2D (so its checks and messages are D3D's), handed out by GetBuffer and made again
// by ResizeBuffers; Present flushes the context's work and counts the frame.
#include "dxgi_impl.h"

namespace fxport::d3d11 {

namespace {

// The back buffer `desc` describes (a render target and shader resource), through `device`.
HRESULT makeBackBuffer(ID3D11Device* device, const DXGI_SWAP_CHAIN_DESC& desc, ComPtr<ID3D11Texture2D>& out) {
    D3D11_TEXTURE2D_DESC t;
    t.Width = desc.BufferDesc.Width;
    t.Height = desc.BufferDesc.Height;
    t.MipLevels = 1;
    t.ArraySize = 1;
    t.Format = desc.BufferDesc.Format;
    t.BindFlags = D3D11_BIND_RENDER_TARGET | D3D11_BIND_SHADER_RESOURCE;
    t.SampleDesc = desc.SampleDesc;  // a multisampled back buffer is a multisampled target (CreateTexture2D checks the count)
    return device->CreateTexture2D(&t, nullptr, out.GetAddressOf());
}

// How many references `object` has besides the one its caller holds.
template <class T>
ULONG otherReferences(T* object) {
    object->AddRef();
    return object->Release() - 1;
}

class SwapChain final : public Counted<IDXGISwapChain> {
public:
    SwapChain(ID3D11Device* device, const DXGI_SWAP_CHAIN_DESC& desc, ComPtr<ID3D11Texture2D> backBuffer, IDXGIFactory* factory)
        : device_(device), desc_(desc), backBuffer_(std::move(backBuffer)), factory_(factory) {}
    HRESULT QueryInterface(REFIID riid, void** ppv) override {
        return answerQuery<IUnknown, IDXGIObject, IDXGIDeviceSubObject, IDXGISwapChain>(this, "IDXGISwapChain", riid, ppv);
    }
    // The factory that made it; for one D3D11CreateDeviceAndSwapChain made, the device's adapter's.
    HRESULT GetParent(REFIID riid, void** ppParent) override {
        if (!ppParent) return fail(DXGI_ERROR_INVALID_CALL, "IDXGISwapChain::GetParent: ppParent is null");
        if (factory_) return factory_->QueryInterface(riid, ppParent);
        ComPtr<IDXGIDevice> dxgi;
        if (HRESULT hr = device_->QueryInterface(IID_IDXGIDevice, reinterpret_cast<void**>(dxgi.GetAddressOf())); FAILED(hr)) return hr;
        ComPtr<IDXGIAdapter> adapter;
        if (HRESULT hr = dxgi->GetAdapter(adapter.GetAddressOf()); FAILED(hr)) return hr;
        return adapter->GetParent(riid, ppParent);
    }
    HRESULT GetDevice(REFIID riid, void** ppDevice) override {
        if (!ppDevice) return fail(DXGI_ERROR_INVALID_CALL, "IDXGISwapChain::GetDevice: ppDevice is null");
        return device_->QueryInterface(riid, ppDevice);
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
    HRESULT SetFullscreenState(BOOL Fullscreen, IDXGIOutput*) override {
        if (Fullscreen) {
            note("IDXGISwapChain::SetFullscreenState: the swap chain is headless; it stays windowed");
            return S_FALSE;
        }
        return succeed();
    }
    HRESULT GetFullscreenState(BOOL* pFullscreen, IDXGIOutput** ppTarget) override {
        if (pFullscreen) *pFullscreen = FALSE;
        if (ppTarget) *ppTarget = nullptr;
        return succeed();
    }
    HRESULT GetDesc(DXGI_SWAP_CHAIN_DESC* pDesc) override {
        if (!pDesc) return fail(E_INVALIDARG, "IDXGISwapChain::GetDesc: pDesc is null");
        *pDesc = desc_;
        return succeed();
    }
    HRESULT ResizeBuffers(UINT BufferCount, UINT Width, UINT Height, DXGI_FORMAT NewFormat, UINT SwapChainFlags) override;
    HRESULT ResizeTarget(const DXGI_MODE_DESC* pNewTargetParameters) override {
        if (!pNewTargetParameters) return fail(DXGI_ERROR_INVALID_CALL, "IDXGISwapChain::ResizeTarget: pNewTargetParameters is null");
        note("IDXGISwapChain::ResizeTarget: the swap chain is headless (no window to resize); ResizeBuffers sets the back buffer's size");
        return S_OK;
    }
    HRESULT GetContainingOutput(IDXGIOutput** ppOutput) override {
        if (!ppOutput) return fail(DXGI_ERROR_INVALID_CALL, "IDXGISwapChain::GetContainingOutput: ppOutput is null");
        *ppOutput = nullptr;
        ComPtr<IDXGIAdapter> adapter;
        if (HRESULT hr = GetParentAdapter(adapter); FAILED(hr)) return hr;
        *ppOutput = makeOutput(adapter.Get(), desc_.BufferDesc.Width, desc_.BufferDesc.Height);
        return succeed();
    }
    UINT PresentCount() override { return presented_; }

private:
    HRESULT GetParentAdapter(ComPtr<IDXGIAdapter>& adapter) {
        ComPtr<IDXGIFactory> factory;
        if (HRESULT hr = GetParent(IID_IDXGIFactory, reinterpret_cast<void**>(factory.GetAddressOf())); FAILED(hr)) return hr;
        return factory->EnumAdapters(0, adapter.GetAddressOf());
    }

    ComPtr<ID3D11Device> device_;
    DXGI_SWAP_CHAIN_DESC desc_;
    ComPtr<ID3D11Texture2D> backBuffer_;
    ComPtr<IDXGIFactory> factory_;  // null: the device's adapter's factory
    UINT presented_ = 0;
};

HRESULT SwapChain::ResizeBuffers(UINT BufferCount, UINT Width, UINT Height, DXGI_FORMAT NewFormat, UINT SwapChainFlags) {
    const std::string call = "IDXGISwapChain::ResizeBuffers: ";
    // D3D's rule: the old buffer must be free of the application's references, direct and through views.
    if (ULONG held = otherReferences(backBuffer_.Get()); held > 0)
        return fail(DXGI_ERROR_INVALID_CALL, call + "the back buffer still has " + std::to_string(held) +
                                                 " reference(s) besides the swap chain's (GetBuffer's, views of it, views bound to the "
                                                 "context): release them and unbind (ClearState or OMSetRenderTargets(0, ...)) first");
    if (BufferCount > 16) return fail(DXGI_ERROR_INVALID_CALL, call + "BufferCount = " + std::to_string(BufferCount) + " (0..16)");
    DXGI_SWAP_CHAIN_DESC next = desc_;
    if (BufferCount != 0) next.BufferCount = BufferCount;
    if (Width != 0) next.BufferDesc.Width = Width;  // 0: DXGI takes the window's; headless, the buffer keeps its own
    if (Height != 0) next.BufferDesc.Height = Height;
    if (NewFormat != DXGI_FORMAT_UNKNOWN) next.BufferDesc.Format = NewFormat;
    next.Flags = SwapChainFlags;
    ComPtr<ID3D11Texture2D> buffer;
    if (HRESULT hr = makeBackBuffer(device_.Get(), next, buffer); FAILED(hr)) return hr;
    backBuffer_ = buffer;
    desc_ = next;
    return succeed();
}

}  // namespace

HRESULT makeSwapChain(ID3D11Device* device, const DXGI_SWAP_CHAIN_DESC* desc, IDXGIFactory* factory, IDXGISwapChain** ppSwapChain) {
    if (!device) return fail(E_INVALIDARG, "CreateSwapChain: no device");
    if (!desc) return fail(E_INVALIDARG, "CreateSwapChain: pSwapChainDesc is null");
    const std::string at = "CreateSwapChain: DXGI_SWAP_CHAIN_DESC.";
    if (desc->BufferDesc.Width == 0 || desc->BufferDesc.Height == 0)
        return fail(E_INVALIDARG, at + "BufferDesc.Width x Height = " + std::to_string(desc->BufferDesc.Width) + " x " +
                                      std::to_string(desc->BufferDesc.Height) + " (a headless swap chain needs its size)");
    if (desc->BufferCount == 0) return fail(E_INVALIDARG, at + "BufferCount = 0");
    ComPtr<ID3D11Texture2D> backBuffer;
    if (HRESULT hr = makeBackBuffer(device, *desc, backBuffer); FAILED(hr)) return hr;
    if (ppSwapChain) *ppSwapChain = new SwapChain(device, *desc, backBuffer, factory);
    return succeed();
}

HRESULT CreateHeadlessSwapChain(ID3D11Device* device, const DXGI_SWAP_CHAIN_DESC* desc, IDXGISwapChain** ppSwapChain) {
    return makeSwapChain(device, desc, nullptr, ppSwapChain);
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
