// The DXGI factory: one adapter (the GL driver's GPU), the window association it records, and
// swap chains made on a D3D11 device through it.
#include "dxgi_impl.h"
#include "guarded.h"

namespace fxport::d3d11 {

namespace {

class Factory final : public Counted<IDXGIFactory1> {
public:
    HRESULT QueryInterface(REFIID riid, void** ppv) override {
        return answerQuery<IUnknown, IDXGIObject, IDXGIFactory, IDXGIFactory1>(this, "IDXGIFactory", riid, ppv);
    }
    // A factory made by CreateDXGIFactory has no parent (DXGI answers E_NOINTERFACE too).
    HRESULT GetParent(REFIID riid, void** ppParent) override {
        if (ppParent) *ppParent = nullptr;
        return fail(E_NOINTERFACE, "IDXGIFactory::GetParent: a factory has no parent (asked for " + guidText(riid) + ")");
    }
    HRESULT EnumAdapters(UINT Adapter, IDXGIAdapter** ppAdapter) override {
        IDXGIAdapter1* adapter = nullptr;
        HRESULT hr = EnumAdapters1(Adapter, ppAdapter ? &adapter : nullptr);
        if (ppAdapter) *ppAdapter = adapter;
        return hr;
    }
    HRESULT EnumAdapters1(UINT Adapter, IDXGIAdapter1** ppAdapter) override {
        if (!ppAdapter) return fail(DXGI_ERROR_INVALID_CALL, "IDXGIFactory::EnumAdapters: ppAdapter is null");
        *ppAdapter = nullptr;
        if (Adapter != 0)
            return fail(DXGI_ERROR_NOT_FOUND, "IDXGIFactory::EnumAdapters: Adapter = " + std::to_string(Adapter) +
                                                  " (there is one adapter, 0: the GL driver's GPU)");
        // Asking the driver may make a GL context (before any device), which can fail.
        return guarded("IDXGIFactory::EnumAdapters", [&] {
            *ppAdapter = makeAdapter(this, currentAdapterIdentity());
            return succeed();
        });
    }
    BOOL IsCurrent() override { return TRUE; }
    HRESULT MakeWindowAssociation(HWND WindowHandle, UINT Flags) override {
        const UINT known = DXGI_MWA_NO_WINDOW_CHANGES | DXGI_MWA_NO_ALT_ENTER | DXGI_MWA_NO_PRINT_SCREEN;
        if (Flags & ~known)
            return fail(DXGI_ERROR_INVALID_CALL, "IDXGIFactory::MakeWindowAssociation: Flags = " + std::to_string(Flags) +
                                                     " (DXGI_MWA_NO_WINDOW_CHANGES 1 | NO_ALT_ENTER 2 | NO_PRINT_SCREEN 4)");
        window_ = WindowHandle;
        return succeed();
    }
    HRESULT GetWindowAssociation(HWND* pWindowHandle) override {
        if (!pWindowHandle) return fail(DXGI_ERROR_INVALID_CALL, "IDXGIFactory::GetWindowAssociation: pWindowHandle is null");
        *pWindowHandle = window_;
        return succeed();
    }
    HRESULT CreateSwapChain(IUnknown* pDevice, DXGI_SWAP_CHAIN_DESC* pDesc, IDXGISwapChain** ppSwapChain) override {
        if (!pDevice) return fail(DXGI_ERROR_INVALID_CALL, "IDXGIFactory::CreateSwapChain: pDevice is null");
        if (!ppSwapChain) return fail(DXGI_ERROR_INVALID_CALL, "IDXGIFactory::CreateSwapChain: ppSwapChain is null");
        *ppSwapChain = nullptr;
        ComPtr<ID3D11Device> device;
        if (FAILED(pDevice->QueryInterface(IID_ID3D11Device, reinterpret_cast<void**>(device.GetAddressOf()))))
            return fail(E_INVALIDARG, "IDXGIFactory::CreateSwapChain: pDevice is not a D3D11 device (its QueryInterface gives no ID3D11Device)");
        return makeSwapChain(device.Get(), pDesc, this, ppSwapChain);
    }

private:
    HWND window_ = nullptr;
};

HRESULT createFactory(const char* call, REFIID riid, void** ppFactory) {
    if (!ppFactory) return fail(E_INVALIDARG, std::string(call) + ": ppFactory is null");
    *ppFactory = nullptr;
    if (!(riid == IID_IDXGIFactory) && !(riid == IID_IDXGIFactory1))
        return fail(E_NOINTERFACE, std::string(call) + ": riid " + guidText(riid) + " is not IID_IDXGIFactory or IID_IDXGIFactory1");
    ComPtr<IDXGIFactory1> factory;
    factory.Attach(makeFactory());
    return factory->QueryInterface(riid, ppFactory);
}

}  // namespace

IDXGIFactory1* makeFactory() { return new Factory(); }

HRESULT CreateDXGIFactory(REFIID riid, void** ppFactory) { return createFactory("CreateDXGIFactory", riid, ppFactory); }
HRESULT CreateDXGIFactory1(REFIID riid, void** ppFactory) { return createFactory("CreateDXGIFactory1", riid, ppFactory); }

}  // namespace fxport::d3d11
