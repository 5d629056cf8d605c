// DXGI's swap chain with D3D's names, headless: the swap chain owns a back buffer texture (a
// render target and shader resource of BufferDesc's size and format) that GetBuffer hands out,
// and Present() finishes the frame's GL work (nothing is shown; fxport's D3D front ends have no
// window yet). D3D11CreateDeviceAndSwapChain and D3D10CreateDeviceAndSwapChain make one.
#pragma once

#include "fxport/d3d11/d3d11_interfaces.h"

namespace fxport::d3d11 {

// COM's interface identifiers, for GetBuffer's riid (a port writes IID_ID3D11Texture2D where D3D
// code writes __uuidof(ID3D11Texture2D)). fxport compares them only with its own constants.
struct GUID {
    std::uint32_t Data1 = 0;
    std::uint16_t Data2 = 0, Data3 = 0;
    std::uint8_t Data4[8] = {};
};
using IID = GUID;
using REFIID = const IID&;
inline bool operator==(const GUID& a, const GUID& b) {
    if (a.Data1 != b.Data1 || a.Data2 != b.Data2 || a.Data3 != b.Data3) return false;
    for (int i = 0; i < 8; ++i)
        if (a.Data4[i] != b.Data4[i]) return false;
    return true;
}
inline constexpr IID IID_ID3D11Texture2D = {0x6f15aaf2, 0xd208, 0x4e89, {0x9a, 0xb4, 0x48, 0x95, 0x35, 0xd3, 0x4f, 0x9c}};
inline constexpr IID IID_ID3D10Texture2D = {0x9b7e4c04, 0x342c, 0x4106, {0xa1, 0x9f, 0x4f, 0x27, 0x04, 0xf6, 0x89, 0xf0}};

using HWND = void*;
struct DXGI_RATIONAL {
    UINT Numerator = 0;
    UINT Denominator = 0;
};
enum DXGI_MODE_SCANLINE_ORDER : UINT { DXGI_MODE_SCANLINE_ORDER_UNSPECIFIED = 0, DXGI_MODE_SCANLINE_ORDER_PROGRESSIVE = 1 };
enum DXGI_MODE_SCALING : UINT { DXGI_MODE_SCALING_UNSPECIFIED = 0, DXGI_MODE_SCALING_CENTERED = 1, DXGI_MODE_SCALING_STRETCHED = 2 };
struct DXGI_MODE_DESC {
    UINT Width = 0;
    UINT Height = 0;
    DXGI_RATIONAL RefreshRate;
    DXGI_FORMAT Format = DXGI_FORMAT_UNKNOWN;
    DXGI_MODE_SCANLINE_ORDER ScanlineOrdering = DXGI_MODE_SCANLINE_ORDER_UNSPECIFIED;
    DXGI_MODE_SCALING Scaling = DXGI_MODE_SCALING_UNSPECIFIED;
};
using DXGI_USAGE = UINT;
constexpr DXGI_USAGE DXGI_USAGE_SHADER_INPUT = 0x10;
constexpr DXGI_USAGE DXGI_USAGE_RENDER_TARGET_OUTPUT = 0x20;
enum DXGI_SWAP_EFFECT : UINT { DXGI_SWAP_EFFECT_DISCARD = 0, DXGI_SWAP_EFFECT_SEQUENTIAL = 1, DXGI_SWAP_EFFECT_FLIP_SEQUENTIAL = 3 };
struct DXGI_SWAP_CHAIN_DESC {
    DXGI_MODE_DESC BufferDesc;
    DXGI_SAMPLE_DESC SampleDesc;
    DXGI_USAGE BufferUsage = 0;
    UINT BufferCount = 0;
    HWND OutputWindow = nullptr;  // ignored: the swap chain is headless
    BOOL Windowed = TRUE;
    DXGI_SWAP_EFFECT SwapEffect = DXGI_SWAP_EFFECT_DISCARD;
    UINT Flags = 0;
};

class IDXGISwapChain : public IUnknown {
public:
    // Ends the frame (the GL work is flushed); SyncInterval and Flags are ignored.
    virtual HRESULT Present(UINT SyncInterval, UINT Flags) = 0;
    // Buffer 0 only: the back buffer, with a reference, as IID_ID3D11Texture2D / IID_ID3D10Texture2D.
    virtual HRESULT GetBuffer(UINT Buffer, REFIID riid, void** ppSurface) = 0;
    // Headless: full-screen is refused (DXGI_STATUS-like S_FALSE), windowed accepted.
    virtual HRESULT SetFullscreenState(BOOL Fullscreen, void* pTarget) = 0;
    virtual HRESULT GetDesc(DXGI_SWAP_CHAIN_DESC* pDesc) = 0;
    // fxport: frames presented so far.
    virtual UINT PresentCount() = 0;
};

// D3D11CreateDevice, and a headless swap chain whose back buffer is pSwapChainDesc->BufferDesc's
// size and format (E_INVALIDARG naming the field when it cannot be made).
HRESULT D3D11CreateDeviceAndSwapChain(void* pAdapter, D3D_DRIVER_TYPE DriverType, void* Software, UINT Flags,
                                      const D3D_FEATURE_LEVEL* pFeatureLevels, UINT FeatureLevels, UINT SDKVersion,
                                      const DXGI_SWAP_CHAIN_DESC* pSwapChainDesc, IDXGISwapChain** ppSwapChain,
                                      ID3D11Device** ppDevice, D3D_FEATURE_LEVEL* pFeatureLevel,
                                      ID3D11DeviceContext** ppImmediateContext);
// fxport: the swap chain of `device` for `desc` (what both CreateDeviceAndSwapChain calls use).
HRESULT CreateHeadlessSwapChain(ID3D11Device* device, const DXGI_SWAP_CHAIN_DESC* desc, IDXGISwapChain** ppSwapChain);

}  // namespace fxport::d3d11
