// IUnknown::QueryInterface for the objects that answer only IUnknown (resources, views, shaders,
// states ...): D3D's objects answer more (a texture its IDXGISurface), which fxport does not have.
// The device and the DXGI objects override it with their interfaces (dxgi_device.cpp, dxgi_impl.h).
#include <cstdio>

#include "dxgi_impl.h"

namespace fxport::d3d11 {

std::string guidText(REFIID g) {
    char text[40];
    std::snprintf(text, sizeof text, "{%08x-%04x-%04x-%02x%02x-%02x%02x%02x%02x%02x%02x}", unsigned(g.Data1), unsigned(g.Data2),
                  unsigned(g.Data3), g.Data4[0], g.Data4[1], g.Data4[2], g.Data4[3], g.Data4[4], g.Data4[5], g.Data4[6], g.Data4[7]);
    return text;
}

HRESULT IUnknown::QueryInterface(REFIID riid, void** ppvObject) {
    if (!ppvObject) return fail(E_POINTER, "QueryInterface: ppvObject is null");
    *ppvObject = nullptr;
    if (!(riid == IID_IUnknown))
        return fail(E_NOINTERFACE, "QueryInterface: no interface " + guidText(riid) +
                                       " (this object answers IUnknown only; the device answers ID3D11Device and IDXGIDevice)");
    AddRef();
    *ppvObject = this;
    return succeed();
}

}  // namespace fxport::d3d11
