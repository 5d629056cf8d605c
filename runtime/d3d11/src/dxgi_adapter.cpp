// The DXGI adapter: the GL driver's GPU described with DXGI_ADAPTER_DESC's fields from what the
// driver reports (AdapterIdentity): its renderer string, its vendor's PCI id, its video memory
// where a vendor extension tells it. Output 0 is its one output.
#include <algorithm>
#include <cctype>

#include "dxgi_impl.h"
#include "fxport/graphics/gpu_limits.h"

namespace fxport::d3d11 {

namespace {

// The PCI vendor id of a GL_VENDOR string; 0 for one that names no GPU maker (Mesa's software
// rasterisers say "Mesa" or "VMware, Inc.").
UINT pciVendorId(std::string vendor) {
    std::transform(vendor.begin(), vendor.end(), vendor.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    auto says = [&](const char* name) { return vendor.find(name) != std::string::npos; };
    if (says("nvidia")) return 0x10DE;
    if (says("amd") || says("ati technologies") || says("advanced micro devices")) return 0x1002;
    if (says("intel")) return 0x8086;
    return 0;
}

class Adapter final : public Counted<IDXGIAdapter1> {
public:
    Adapter(IDXGIFactory1* factory, const AdapterIdentity& id) : factory_(factory), id_(id) {}
    HRESULT QueryInterface(REFIID riid, void** ppv) override {
        return answerQuery<IUnknown, IDXGIObject, IDXGIAdapter, IDXGIAdapter1>(this, "IDXGIAdapter", riid, ppv);
    }
    HRESULT GetParent(REFIID riid, void** ppParent) override {
        if (!ppParent) return fail(DXGI_ERROR_INVALID_CALL, "IDXGIAdapter::GetParent: ppParent is null");
        return factory_->QueryInterface(riid, ppParent);
    }
    HRESULT EnumOutputs(UINT Output, IDXGIOutput** ppOutput) override {
        if (!ppOutput) return fail(DXGI_ERROR_INVALID_CALL, "IDXGIAdapter::EnumOutputs: ppOutput is null");
        *ppOutput = nullptr;
        if (Output != 0)
            return fail(DXGI_ERROR_NOT_FOUND, "IDXGIAdapter::EnumOutputs: Output = " + std::to_string(Output) + " (the adapter has one output, 0)");
        *ppOutput = makeOutput(this, 0, 0);
        return succeed();
    }
    HRESULT GetDesc(DXGI_ADAPTER_DESC* pDesc) override {
        if (!pDesc) return fail(E_INVALIDARG, "IDXGIAdapter::GetDesc: pDesc is null");
        *pDesc = describe();
        return succeed();
    }
    HRESULT GetDesc1(DXGI_ADAPTER_DESC1* pDesc) override {
        if (!pDesc) return fail(E_INVALIDARG, "IDXGIAdapter1::GetDesc1: pDesc is null");
        static_cast<DXGI_ADAPTER_DESC&>(*pDesc) = describe();
        pDesc->Flags = GpuLimits::softwareRenderer(id_.renderer) ? DXGI_ADAPTER_FLAG_SOFTWARE : DXGI_ADAPTER_FLAG_NONE;
        return succeed();
    }

private:
    DXGI_ADAPTER_DESC describe() const {
        DXGI_ADAPTER_DESC d;
        // GL strings are ASCII in practice: each byte widens to one WCHAR; the last one stays 0.
        const std::size_t n = std::min(id_.renderer.size(), std::size(d.Description) - 1);
        for (std::size_t i = 0; i < n; ++i) d.Description[i] = WCHAR(static_cast<unsigned char>(id_.renderer[i]));
        d.VendorId = pciVendorId(id_.vendor);
        // Only a dedicated-memory figure is DXGI's DedicatedVideoMemory; ATI_meminfo's free texture
        // memory is the nearest AMD's own driver tells (docs/API.md says so).
        d.DedicatedVideoMemory = id_.memory == AdapterIdentity::Memory::Unknown ? 0 : SIZE_T(id_.videoMemoryBytes);
        d.AdapterLuid = LUID{1, 0};  // the one adapter
        return d;
    }

    ComPtr<IDXGIFactory1> factory_;
    AdapterIdentity id_;
};

}  // namespace

IDXGIAdapter1* makeAdapter(IDXGIFactory1* factory, const AdapterIdentity& id) { return new Adapter(factory, id); }

AdapterIdentity currentAdapterIdentity() {
    if (GraphicsDevice* device = GraphicsDevice::current()) return device->adapterIdentity();
    PresentationParameters p;  // the smallest device: its context is all the question needs
    p.BackBufferWidth = 1;
    p.BackBufferHeight = 1;
    p.DepthStencilFormat = DepthFormat::None;
    GraphicsDevice asked(p);
    return asked.adapterIdentity();
}

}  // namespace fxport::d3d11
