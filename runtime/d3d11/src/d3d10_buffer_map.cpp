// ID3D10Buffer::Map / Unmap: D3D10 maps a buffer through the buffer itself; fxport's D3D10 buffer
// is the D3D11 one, so these are the device's immediate context's Map/Unmap of subresource 0, with
// every rule and message of those.
#include "context.h"

namespace fxport::d3d11 {

HRESULT Buffer::Map(D3D11_MAP MapType, UINT MapFlags, void** ppData) {
    if (!ppData) return fail(E_INVALIDARG, "ID3D10Buffer::Map: ppData is null");
    *ppData = nullptr;
    D3D11_MAPPED_SUBRESOURCE subresource;
    const HRESULT hr = device().context().Map(this, 0, MapType, MapFlags, &subresource);
    if (SUCCEEDED(hr)) *ppData = subresource.pData;
    return hr;
}

void Buffer::Unmap() { device().context().Unmap(this, 0); }

}  // namespace fxport::d3d11
