// The D3D11 device's IDXGIDevice: an interface of the device object itself (it counts references
// on the device and queries through it), whose adapter is made once, at the first GetAdapter, from
// what the device's driver says of its GPU.
#include "dxgi_impl.h"

namespace fxport::d3d11 {

HRESULT Device::QueryInterface(REFIID riid, void** ppvObject) {
    if (!ppvObject) return fail(E_POINTER, "ID3D11Device::QueryInterface: ppvObject is null");
    *ppvObject = nullptr;
    if (riid == IID_IUnknown || riid == IID_ID3D11Device) {
        *ppvObject = static_cast<ID3D11Device*>(this);
    } else if (riid == IID_IDXGIObject || riid == IID_IDXGIDevice || riid == IID_IDXGIDevice1) {
        *ppvObject = static_cast<IDXGIDevice1*>(&dxgi());
    } else {
        return fail(E_NOINTERFACE, "ID3D11Device::QueryInterface: no interface " + guidText(riid) +
                                       " (the device answers IUnknown, ID3D11Device, IDXGIDevice and IDXGIDevice1)");
    }
    AddRef();
    return succeed();
}

DxgiDevice& Device::dxgi() {
    if (!dxgi_) dxgi_ = std::make_unique<DxgiDevice>(*this);
    return *dxgi_;
}

ULONG DxgiDevice::AddRef() { return device_.AddRef(); }
ULONG DxgiDevice::Release() { return device_.Release(); }
HRESULT DxgiDevice::QueryInterface(REFIID riid, void** ppv) { return device_.QueryInterface(riid, ppv); }

HRESULT DxgiDevice::GetAdapter(IDXGIAdapter** pAdapter) {
    if (!pAdapter) return fail(E_INVALIDARG, "IDXGIDevice::GetAdapter: pAdapter is null");
    if (!adapter_) {
        ComPtr<IDXGIFactory1> factory;
        factory.Attach(makeFactory());
        adapter_.Attach(makeAdapter(factory.Get(), device_.core().adapterIdentity()));
    }
    adapter_->AddRef();
    *pAdapter = adapter_.Get();
    return succeed();
}

HRESULT DxgiDevice::GetParent(REFIID riid, void** ppParent) {
    if (!ppParent) return fail(E_INVALIDARG, "IDXGIDevice::GetParent: ppParent is null");
    ComPtr<IDXGIAdapter> adapter;
    if (HRESULT hr = GetAdapter(adapter.GetAddressOf()); FAILED(hr)) return hr;
    return adapter->QueryInterface(riid, ppParent);
}

HRESULT DxgiDevice::SetGPUThreadPriority(INT Priority) {
    if (Priority < -7 || Priority > 7)
        return fail(E_INVALIDARG, "IDXGIDevice::SetGPUThreadPriority: Priority = " + std::to_string(Priority) + " (-7..7)");
    priority_ = Priority;
    return succeed();
}

HRESULT DxgiDevice::GetGPUThreadPriority(INT* pPriority) {
    if (!pPriority) return fail(E_INVALIDARG, "IDXGIDevice::GetGPUThreadPriority: pPriority is null");
    *pPriority = priority_;
    return succeed();
}

HRESULT DxgiDevice::SetMaximumFrameLatency(UINT MaxLatency) {
    if (MaxLatency > 16)
        return fail(DXGI_ERROR_INVALID_CALL, "IDXGIDevice1::SetMaximumFrameLatency: MaxLatency = " + std::to_string(MaxLatency) + " (0..16)");
    maxLatency_ = MaxLatency == 0 ? 3 : MaxLatency;  // 0: DXGI's default
    return succeed();
}

HRESULT DxgiDevice::GetMaximumFrameLatency(UINT* pMaxLatency) {
    if (!pMaxLatency) return fail(DXGI_ERROR_INVALID_CALL, "IDXGIDevice1::GetMaximumFrameLatency: pMaxLatency is null");
    *pMaxLatency = maxLatency_;
    return succeed();
}

}  // namespace fxport::d3d11
