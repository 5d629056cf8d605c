// DXGI with D3D's names, headless: the factory, its one adapter (the GL driver's GPU) with one
// output, the D3D11 device's IDXGIDevice, and the swap chain.
//
// The swap chain owns a back buffer texture (a render target and shader resource of BufferDesc's
// size and format) that GetBuffer hands out; Present() finishes the frame's GL work (nothing is
// shown: fxport's D3D front ends have no window yet). D3D11CreateDeviceAndSwapChain,
// D3D10CreateDeviceAndSwapChain and IDXGIFactory::CreateSwapChain make one.
//
// The adapter and output answer what a headless GL device can honestly tell: the adapter's
// Description is GL_RENDERER, VendorId the PCI id of GL_VENDOR where known (NVIDIA 0x10DE, AMD
// 0x1002, Intel 0x8086, else 0), DedicatedVideoMemory what GL_NVX_gpu_memory_info (else
// GL_ATI_meminfo's free texture memory) reports, else 0. The output's display modes are common
// sizes from 640x480 to 3840x2160 (and the swap chain's size, for the output GetContainingOutput
// gives) at 60 Hz in the scan-out formats.
//
//   IDXGIFactory* factory; CreateDXGIFactory(__uuidof(IDXGIFactory), (void**)&factory);
//   IDXGIAdapter* adapter; factory->EnumAdapters(0, &adapter);  // 1: DXGI_ERROR_NOT_FOUND
#pragma once

#include <cstddef>

#include "fxport/d3d11/d3d11_interfaces.h"

namespace fxport::d3d11 {

// GetBuffer's D3D10 spelling (ID3D10Texture2D is ID3D11Texture2D, so __uuidof gives D3D11's).
inline constexpr IID IID_ID3D10Texture2D = {0x9b7e4c04, 0x342c, 0x4106, {0xa1, 0x9f, 0x4f, 0x27, 0x04, 0xf6, 0x89, 0xf0}};

constexpr HRESULT DXGI_ERROR_NOT_FOUND = HRESULT(0x887A0002u);
constexpr HRESULT DXGI_ERROR_MORE_DATA = HRESULT(0x887A0003u);
constexpr HRESULT DXGI_ERROR_UNSUPPORTED = HRESULT(0x887A0004u);
constexpr HRESULT DXGI_ERROR_NOT_CURRENTLY_AVAILABLE = HRESULT(0x887A0022u);

using HWND = void*;
using HMONITOR = void*;
using HMODULE = void*;
using WCHAR = wchar_t;  // 32 bits on Linux: convert with wcstombs (MSVC's wcstombs_s is not there)
using LONG = std::int32_t;
using DWORD = std::uint32_t;
using RECT = D3D11_RECT;
struct LUID {
    DWORD LowPart = 0;
    LONG HighPart = 0;
};

struct DXGI_RATIONAL {
    UINT Numerator = 0;
    UINT Denominator = 0;
};
enum DXGI_MODE_SCANLINE_ORDER : UINT {
    DXGI_MODE_SCANLINE_ORDER_UNSPECIFIED = 0,
    DXGI_MODE_SCANLINE_ORDER_PROGRESSIVE = 1,
    DXGI_MODE_SCANLINE_ORDER_UPPER_FIELD_FIRST = 2,
    DXGI_MODE_SCANLINE_ORDER_LOWER_FIELD_FIRST = 3
};
enum DXGI_MODE_SCALING : UINT { DXGI_MODE_SCALING_UNSPECIFIED = 0, DXGI_MODE_SCALING_CENTERED = 1, DXGI_MODE_SCALING_STRETCHED = 2 };
enum DXGI_MODE_ROTATION : UINT {
    DXGI_MODE_ROTATION_UNSPECIFIED = 0,
    DXGI_MODE_ROTATION_IDENTITY = 1,
    DXGI_MODE_ROTATION_ROTATE90 = 2,
    DXGI_MODE_ROTATION_ROTATE180 = 3,
    DXGI_MODE_ROTATION_ROTATE270 = 4
};
struct DXGI_MODE_DESC {
    UINT Width = 0;
    UINT Height = 0;
    DXGI_RATIONAL RefreshRate;
    DXGI_FORMAT Format = DXGI_FORMAT_UNKNOWN;
    DXGI_MODE_SCANLINE_ORDER ScanlineOrdering = DXGI_MODE_SCANLINE_ORDER_UNSPECIFIED;
    DXGI_MODE_SCALING Scaling = DXGI_MODE_SCALING_UNSPECIFIED;
};
// GetDisplayModeList's Flags: the listed modes are progressive and need no scaling, so every
// combination lists the same modes.
constexpr UINT DXGI_ENUM_MODES_INTERLACED = 1;
constexpr UINT DXGI_ENUM_MODES_SCALING = 2;

using DXGI_USAGE = UINT;
constexpr DXGI_USAGE DXGI_USAGE_SHADER_INPUT = 0x10;
constexpr DXGI_USAGE DXGI_USAGE_RENDER_TARGET_OUTPUT = 0x20;
enum DXGI_SWAP_EFFECT : UINT { DXGI_SWAP_EFFECT_DISCARD = 0, DXGI_SWAP_EFFECT_SEQUENTIAL = 1, DXGI_SWAP_EFFECT_FLIP_SEQUENTIAL = 3 };
enum DXGI_SWAP_CHAIN_FLAG : UINT {
    DXGI_SWAP_CHAIN_FLAG_NONPREROTATED = 1,
    DXGI_SWAP_CHAIN_FLAG_ALLOW_MODE_SWITCH = 2,
    DXGI_SWAP_CHAIN_FLAG_GDI_COMPATIBLE = 4
};
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

struct DXGI_ADAPTER_DESC {
    WCHAR Description[128] = {};
    UINT VendorId = 0;
    UINT DeviceId = 0;  // 0: GL does not tell the PCI device, subsystem or revision
    UINT SubSysId = 0;
    UINT Revision = 0;
    SIZE_T DedicatedVideoMemory = 0;
    SIZE_T DedicatedSystemMemory = 0;
    SIZE_T SharedSystemMemory = 0;
    LUID AdapterLuid;
};
enum DXGI_ADAPTER_FLAG : UINT { DXGI_ADAPTER_FLAG_NONE = 0, DXGI_ADAPTER_FLAG_REMOTE = 1, DXGI_ADAPTER_FLAG_SOFTWARE = 2 };
struct DXGI_ADAPTER_DESC1 : DXGI_ADAPTER_DESC {
    UINT Flags = 0;  // DXGI_ADAPTER_FLAG_SOFTWARE for a software rasteriser (llvmpipe ...)
};
struct DXGI_OUTPUT_DESC {
    WCHAR DeviceName[32] = {};
    RECT DesktopCoordinates;
    BOOL AttachedToDesktop = FALSE;
    DXGI_MODE_ROTATION Rotation = DXGI_MODE_ROTATION_UNSPECIFIED;
    HMONITOR Monitor = nullptr;
};
// MakeWindowAssociation's Flags (recorded; there is no window to watch).
constexpr UINT DXGI_MWA_NO_WINDOW_CHANGES = 1;
constexpr UINT DXGI_MWA_NO_ALT_ENTER = 2;
constexpr UINT DXGI_MWA_NO_PRINT_SCREEN = 4;

// GetParent: the object that made this one -- an output's adapter, an adapter's factory, a swap
// chain's factory -- as riid asks (E_NOINTERFACE when it is not that).
class IDXGIObject : public IUnknown {
public:
    virtual HRESULT GetParent(REFIID riid, void** ppParent) = 0;
};
class IDXGIDeviceSubObject : public IDXGIObject {
public:
    // The device that the object belongs to, as riid asks (IID_ID3D11Device, IID_IDXGIDevice).
    virtual HRESULT GetDevice(REFIID riid, void** ppDevice) = 0;
};

class IDXGIOutput : public IDXGIObject {
public:
    // DeviceName L"\\\\.\\DISPLAY1", attached to a virtual 1920 x 1080 desktop (headless: no screen).
    virtual HRESULT GetDesc(DXGI_OUTPUT_DESC* pDesc) = 0;
    // DXGI's two calls: pDesc null sets *pNumModes to the count; otherwise up to *pNumModes modes
    // are written (ascending by width, then height), *pNumModes set to how many, and
    // DXGI_ERROR_MORE_DATA returned when that was not all. A format that is not a scan-out format
    // (R8G8B8A8_UNORM(_SRGB), B8G8R8A8_UNORM(_SRGB), R10G10B10A2_UNORM, R16G16B16A16_FLOAT) has none.
    virtual HRESULT GetDisplayModeList(DXGI_FORMAT EnumFormat, UINT Flags, UINT* pNumModes, DXGI_MODE_DESC* pDesc) = 0;
    // The listed mode nearest pModeToMatch: its Format (R8G8B8A8_UNORM when UNKNOWN and a device is
    // given; DXGI_ERROR_INVALID_CALL without one), the size nearest in |dW| + |dH| (0 x 0: the
    // desktop's 1920 x 1080), 60 Hz.
    virtual HRESULT FindClosestMatchingMode(const DXGI_MODE_DESC* pModeToMatch, DXGI_MODE_DESC* pClosestMatch,
                                            IUnknown* pConcernedDevice) = 0;
    virtual HRESULT WaitForVBlank() = 0;  // returns at once: there is no display to wait for
};

class IDXGIAdapter : public IDXGIObject {
public:
    // Output 0 only (DXGI_ERROR_NOT_FOUND past it).
    virtual HRESULT EnumOutputs(UINT Output, IDXGIOutput** ppOutput) = 0;
    virtual HRESULT GetDesc(DXGI_ADAPTER_DESC* pDesc) = 0;
};
class IDXGIAdapter1 : public IDXGIAdapter {
public:
    virtual HRESULT GetDesc1(DXGI_ADAPTER_DESC1* pDesc) = 0;
};

class IDXGISwapChain;

class IDXGIFactory : public IDXGIObject {
public:
    // Adapter 0 only, the GL driver's GPU (DXGI_ERROR_NOT_FOUND past it).
    virtual HRESULT EnumAdapters(UINT Adapter, IDXGIAdapter** ppAdapter) = 0;
    // Recorded (GetWindowAssociation gives the window back); nothing watches a window.
    virtual HRESULT MakeWindowAssociation(HWND WindowHandle, UINT Flags) = 0;
    virtual HRESULT GetWindowAssociation(HWND* pWindowHandle) = 0;
    // The headless swap chain of pDevice (a D3D11 device) for pDesc, as D3D11CreateDeviceAndSwapChain makes it.
    virtual HRESULT CreateSwapChain(IUnknown* pDevice, DXGI_SWAP_CHAIN_DESC* pDesc, IDXGISwapChain** ppSwapChain) = 0;
};
class IDXGIFactory1 : public IDXGIFactory {
public:
    virtual HRESULT EnumAdapters1(UINT Adapter, IDXGIAdapter1** ppAdapter) = 0;
    virtual BOOL IsCurrent() = 0;  // TRUE: the one adapter never changes
};

// The DXGI side of a D3D11 device: device->QueryInterface(__uuidof(IDXGIDevice), ...). It is the
// device's own object (the same reference count); its GetParent gives the adapter.
class IDXGIDevice : public IDXGIObject {
public:
    // The adapter the device runs on (the same one each time); its parent is a factory.
    virtual HRESULT GetAdapter(IDXGIAdapter** pAdapter) = 0;
    // Recorded and given back (-7..7); GL has no GPU thread priority.
    virtual HRESULT SetGPUThreadPriority(INT Priority) = 0;
    virtual HRESULT GetGPUThreadPriority(INT* pPriority) = 0;
};
class IDXGIDevice1 : public IDXGIDevice {
public:
    // Recorded and given back (1..16, 0 = the default 3); Present does not queue frames.
    virtual HRESULT SetMaximumFrameLatency(UINT MaxLatency) = 0;
    virtual HRESULT GetMaximumFrameLatency(UINT* pMaxLatency) = 0;
};

class IDXGISwapChain : public IDXGIDeviceSubObject {
public:
    // Ends the frame (the GL work is flushed); SyncInterval and Flags are ignored.
    virtual HRESULT Present(UINT SyncInterval, UINT Flags) = 0;
    // Buffer 0 only: the back buffer, with a reference, as IID_ID3D11Texture2D / IID_ID3D10Texture2D.
    virtual HRESULT GetBuffer(UINT Buffer, REFIID riid, void** ppSurface) = 0;
    // Headless: full-screen is refused (DXGI_STATUS-like S_FALSE), windowed accepted.
    virtual HRESULT SetFullscreenState(BOOL Fullscreen, IDXGIOutput* pTarget) = 0;
    // Always windowed (*pFullscreen FALSE, *ppTarget null).
    virtual HRESULT GetFullscreenState(BOOL* pFullscreen, IDXGIOutput** ppTarget) = 0;
    virtual HRESULT GetDesc(DXGI_SWAP_CHAIN_DESC* pDesc) = 0;
    // A new back buffer of Width x Height (0: keep the old one) and NewFormat (UNKNOWN: keep);
    // BufferCount 0 keeps the count. D3D's rule: DXGI_ERROR_INVALID_CALL while anything still holds
    // the old back buffer (a reference from GetBuffer, a view of it, a view bound to the context).
    // The new one is blank; GetBuffer gives it.
    virtual HRESULT ResizeBuffers(UINT BufferCount, UINT Width, UINT Height, DXGI_FORMAT NewFormat, UINT SwapChainFlags) = 0;
    // Resizes the window: headless there is none, so nothing changes (the caller's ResizeBuffers does).
    virtual HRESULT ResizeTarget(const DXGI_MODE_DESC* pNewTargetParameters) = 0;
    // The one output, whose mode list has the swap chain's size too.
    virtual HRESULT GetContainingOutput(IDXGIOutput** ppOutput) = 0;
    // fxport: frames presented so far.
    virtual UINT PresentCount() = 0;
};

FXPORT_INTERFACE_ID(IDXGIObject, 0xaec22fb8, 0x76f3, 0x4639, 0x9b, 0xe0, 0x28, 0xeb, 0x43, 0xa6, 0x7a, 0x2e)
FXPORT_INTERFACE_ID(IDXGIDeviceSubObject, 0x3d3e0379, 0xf9de, 0x4d58, 0xbb, 0x6c, 0x18, 0xd6, 0x29, 0x92, 0xf1, 0xa6)
FXPORT_INTERFACE_ID(IDXGIOutput, 0xae02eedb, 0xc735, 0x4690, 0x8d, 0x52, 0x5a, 0x8d, 0xc2, 0x02, 0x13, 0xaa)
FXPORT_INTERFACE_ID(IDXGIAdapter, 0x2411e7e1, 0x12ac, 0x4ccf, 0xbd, 0x14, 0x97, 0x98, 0xe8, 0x53, 0x4d, 0xc0)
FXPORT_INTERFACE_ID(IDXGIAdapter1, 0x29038f61, 0x3839, 0x4626, 0x91, 0xfd, 0x08, 0x68, 0x79, 0x01, 0x1a, 0x05)
FXPORT_INTERFACE_ID(IDXGIFactory, 0x7b7166ec, 0x21c7, 0x44ae, 0xb2, 0x1a, 0xc9, 0xae, 0x32, 0x1a, 0xe3, 0x69)
FXPORT_INTERFACE_ID(IDXGIFactory1, 0x770aae78, 0xf26f, 0x4dba, 0xa8, 0x29, 0x25, 0x3c, 0x83, 0xd1, 0xb3, 0x87)
FXPORT_INTERFACE_ID(IDXGIDevice, 0x54ec77fa, 0x1377, 0x44e6, 0x8c, 0x32, 0x88, 0xfd, 0x5f, 0x44, 0xc8, 0x4c)
FXPORT_INTERFACE_ID(IDXGIDevice1, 0x77db970f, 0x6276, 0x48ba, 0xba, 0x28, 0x07, 0x01, 0x43, 0xb4, 0x39, 0x2c)
FXPORT_INTERFACE_ID(IDXGISwapChain, 0x310d36a0, 0xd2e7, 0x4c0a, 0xaa, 0x04, 0x6a, 0x9d, 0x23, 0xb8, 0x88, 0x6a)

// A factory (riid IID_IDXGIFactory or IID_IDXGIFactory1), with a reference.
HRESULT CreateDXGIFactory(REFIID riid, void** ppFactory);
HRESULT CreateDXGIFactory1(REFIID riid, void** ppFactory);

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
