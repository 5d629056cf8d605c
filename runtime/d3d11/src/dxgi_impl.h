// INTERNAL: the DXGI objects (dxgi.h) for each other and the device: their makers, the reference
// counting and QueryInterface they share, and the device's IDXGIDevice.
#pragma once

#include <atomic>
#include <string>

#include "d3d11_impl.h"
#include "fxport/d3d11/dxgi.h"
#include "fxport/graphics/adapter_identity.h"

namespace fxport::d3d11 {

// "{6f15aaf2-d208-4e89-9ab4-489535d34f9c}", for messages (query_interface.cpp).
std::string guidText(REFIID riid);

// QueryInterface of an object that is each of `Interfaces`: *ppv = the one riid names, with a
// reference; E_NOINTERFACE (naming `object` and the identifier) otherwise.
template <class... Interfaces, class Self>
HRESULT answerQuery(Self* self, const char* object, REFIID riid, void** ppv) {
    if (!ppv) return fail(E_POINTER, std::string(object) + "::QueryInterface: ppvObject is null");
    *ppv = nullptr;
    const bool found = ((riid == uuidOf<Interfaces>() ? (*ppv = static_cast<Interfaces*>(self), true) : false) || ...);
    if (!found) return fail(E_NOINTERFACE, std::string(object) + "::QueryInterface: no interface " + guidText(riid));
    self->AddRef();
    return succeed();
}

// A DXGI object: a reference count from 1, freed at 0.
template <class Interface>
class Counted : public Interface {
public:
    ULONG AddRef() override { return ++references_; }
    ULONG Release() override {
        const ULONG left = --references_;
        if (left == 0) delete this;
        return left;
    }

private:
    std::atomic<ULONG> references_{1};
};

// --- makers, each with a reference for the caller
// The factory CreateDXGIFactory makes (dxgi_factory.cpp).
IDXGIFactory1* makeFactory();
// The adapter of the driver `id` describes, whose parent is `factory` (dxgi_adapter.cpp).
IDXGIAdapter1* makeAdapter(IDXGIFactory1* factory, const AdapterIdentity& id);
// What the driver of the current device says of its GPU; without a device, what a device made
// for the question says (CreateDXGIFactory comes before D3D11CreateDevice in D3D code).
AdapterIdentity currentAdapterIdentity();
// The output of `adapter`; a mode of swapWidth x swapHeight is listed too when not 0 (dxgi_output.cpp).
IDXGIOutput* makeOutput(IDXGIAdapter* adapter, UINT swapWidth, UINT swapHeight);
// A headless swap chain of `device` whose GetParent gives `factory` (null: the device's adapter's
// factory), as CreateHeadlessSwapChain checks `desc` (swap_chain.cpp).
HRESULT makeSwapChain(ID3D11Device* device, const DXGI_SWAP_CHAIN_DESC* desc, IDXGIFactory* factory, IDXGISwapChain** ppSwapChain);

// The device's IDXGIDevice (dxgi_device.cpp): part of the device, so it shares its reference count
// and QueryInterface (COM's rule: every interface of an object gives the same IUnknown).
class DxgiDevice final : public IDXGIDevice1 {
public:
    explicit DxgiDevice(Device& device) : device_(device) {}
    ULONG AddRef() override;
    ULONG Release() override;
    HRESULT QueryInterface(REFIID riid, void** ppv) override;
    HRESULT GetParent(REFIID riid, void** ppParent) override;
    HRESULT GetAdapter(IDXGIAdapter** pAdapter) override;
    HRESULT SetGPUThreadPriority(INT Priority) override;
    HRESULT GetGPUThreadPriority(INT* pPriority) override;
    HRESULT SetMaximumFrameLatency(UINT MaxLatency) override;
    HRESULT GetMaximumFrameLatency(UINT* pMaxLatency) override;

private:
    Device& device_;
    ComPtr<IDXGIAdapter1> adapter_;  // made at the first GetAdapter, the same one after
    INT priority_ = 0;
    UINT maxLatency_ = 3;
};

}  // namespace fxport::d3d11
