// DXGI's start-up calls as D3D11 tutorials make them: the Rastertek D3DClass::Initialize sequence
// compiled as written (the factory, adapter, output, display modes, adapter description, then the
// device and swap chain), the count-then-fill protocol of GetDisplayModeList, NOT_FOUND past the
// one adapter and output, the device's IDXGIDevice and its chain up to the factory that makes a
// swap chain, ResizeBuffers with D3D's rule on outstanding back-buffer references, and the
// reference counts coming back to 0. Oracles: the GL renderer string the platform read when the
// context was made, and pixels read back from the back buffer.
#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "d3d11_test_support.h"
#include "fxport/d3d11/core_access.h"

namespace {

using namespace d3d11test;

// GL_RENDERER, as the platform read it when the device's context was made ("renderer / version").
std::string glRendererOf(ID3D11Device* device) {
    const std::string name = CoreDeviceOf(*device).rendererName();
    return name.substr(0, name.rfind(" / "));
}

DXGI_SWAP_CHAIN_DESC swapChainDesc(UINT width, UINT height) {
    DXGI_SWAP_CHAIN_DESC sd;
    sd.BufferCount = 1;
    sd.BufferDesc.Width = width;
    sd.BufferDesc.Height = height;
    sd.BufferDesc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    sd.BufferUsage = DXGI_USAGE_RENDER_TARGET_OUTPUT;
    sd.SampleDesc.Count = 1;
    sd.Windowed = TRUE;
    return sd;
}

// Clears the back buffer of `swapChain` to `rgba` through a view, then reads it back: every pixel
// must be `expected`; the buffer's size must be width x height.
void expectClearedBackBuffer(Device& d, IDXGISwapChain* swapChain, UINT width, UINT height, const FLOAT rgba[4],
                             std::array<std::uint8_t, 4> expected) {
    ComPtr<ID3D11Texture2D> backBuffer;
    ASSERT_EQ(swapChain->GetBuffer(0, __uuidof(ID3D11Texture2D), reinterpret_cast<void**>(backBuffer.GetAddressOf())), S_OK) << lastError();
    D3D11_TEXTURE2D_DESC desc;
    backBuffer->GetDesc(&desc);
    EXPECT_EQ(desc.Width, width);
    EXPECT_EQ(desc.Height, height);
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(backBuffer.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    d.context->ClearRenderTargetView(rtv.Get(), rgba);
    EXPECT_EQ(swapChain->Present(0, 0), S_OK);
    const auto pixels = readPixels(d, backBuffer.Get());
    ASSERT_EQ(pixels.size(), std::size_t(width) * height);
    const auto wrong = std::count_if(pixels.begin(), pixels.end(), [&](const std::array<std::uint8_t, 4>& p) { return p != expected; });
    EXPECT_EQ(wrong, 0) << "of " << pixels.size() << " pixels";
}

// Rastertek's D3DClass::Initialize and Shutdown, line by line (wcstombs_s, MSVC's, is wcstombs here).
TEST(D3D11Dxgi, RastertekInitializeSequenceRunsAsWritten) {
    const int screenWidth = 800, screenHeight = 600;
    const bool m_vsync_enabled = true;
    int m_videoCardMemory = -1;
    char m_videoCardDescription[128] = {};
    HRESULT result;
    IDXGIFactory* factory;
    IDXGIAdapter* adapter;
    IDXGIOutput* adapterOutput;
    unsigned int numModes, i, numerator = 0, denominator = 0;
    size_t stringLength;
    DXGI_MODE_DESC* displayModeList;
    DXGI_ADAPTER_DESC adapterDesc;

    result = CreateDXGIFactory(__uuidof(IDXGIFactory), (void**)&factory);
    ASSERT_FALSE(FAILED(result)) << lastError();
    result = factory->EnumAdapters(0, &adapter);
    ASSERT_FALSE(FAILED(result)) << lastError();
    result = adapter->EnumOutputs(0, &adapterOutput);
    ASSERT_FALSE(FAILED(result)) << lastError();
    result = adapterOutput->GetDisplayModeList(DXGI_FORMAT_R8G8B8A8_UNORM, DXGI_ENUM_MODES_INTERLACED, &numModes, NULL);
    ASSERT_FALSE(FAILED(result)) << lastError();
    displayModeList = new DXGI_MODE_DESC[numModes];
    result = adapterOutput->GetDisplayModeList(DXGI_FORMAT_R8G8B8A8_UNORM, DXGI_ENUM_MODES_INTERLACED, &numModes, displayModeList);
    ASSERT_FALSE(FAILED(result)) << lastError();
    for (i = 0; i < numModes; i++) {
        if (displayModeList[i].Width == (unsigned int)screenWidth) {
            if (displayModeList[i].Height == (unsigned int)screenHeight) {
                numerator = displayModeList[i].RefreshRate.Numerator;
                denominator = displayModeList[i].RefreshRate.Denominator;
            }
        }
    }
    result = adapter->GetDesc(&adapterDesc);
    ASSERT_FALSE(FAILED(result)) << lastError();
    m_videoCardMemory = (int)(adapterDesc.DedicatedVideoMemory / 1024 / 1024);
    stringLength = wcstombs(m_videoCardDescription, adapterDesc.Description, 128);
    ASSERT_NE(stringLength, (size_t)-1);
    delete[] displayModeList;
    displayModeList = 0;
    EXPECT_EQ(adapterOutput->Release(), 0u);
    adapterOutput = 0;
    EXPECT_EQ(adapter->Release(), 0u);
    adapter = 0;
    EXPECT_EQ(factory->Release(), 0u);
    factory = 0;

    EXPECT_EQ(numerator, 60u);  // the 800x600 mode is there, at 60/1 Hz
    EXPECT_EQ(denominator, 1u);
    EXPECT_GE(m_videoCardMemory, 0);

    DXGI_SWAP_CHAIN_DESC swapChainDesc;
    swapChainDesc.BufferCount = 1;
    swapChainDesc.BufferDesc.Width = screenWidth;
    swapChainDesc.BufferDesc.Height = screenHeight;
    swapChainDesc.BufferDesc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    if (m_vsync_enabled) {
        swapChainDesc.BufferDesc.RefreshRate.Numerator = numerator;
        swapChainDesc.BufferDesc.RefreshRate.Denominator = denominator;
    } else {
        swapChainDesc.BufferDesc.RefreshRate.Numerator = 0;
        swapChainDesc.BufferDesc.RefreshRate.Denominator = 1;
    }
    swapChainDesc.BufferUsage = DXGI_USAGE_RENDER_TARGET_OUTPUT;
    swapChainDesc.OutputWindow = nullptr;
    swapChainDesc.SampleDesc.Count = 1;
    swapChainDesc.SampleDesc.Quality = 0;
    swapChainDesc.Windowed = true;
    swapChainDesc.BufferDesc.ScanlineOrdering = DXGI_MODE_SCANLINE_ORDER_UNSPECIFIED;
    swapChainDesc.BufferDesc.Scaling = DXGI_MODE_SCALING_UNSPECIFIED;
    swapChainDesc.SwapEffect = DXGI_SWAP_EFFECT_DISCARD;
    swapChainDesc.Flags = 0;
    D3D_FEATURE_LEVEL featureLevel = D3D_FEATURE_LEVEL_11_0;
    IDXGISwapChain* m_swapChain;
    ID3D11Device* m_device;
    ID3D11DeviceContext* m_deviceContext;
    result = D3D11CreateDeviceAndSwapChain(NULL, D3D_DRIVER_TYPE_HARDWARE, NULL, 0, &featureLevel, 1, D3D11_SDK_VERSION, &swapChainDesc,
                                           &m_swapChain, &m_device, NULL, &m_deviceContext);
    ASSERT_FALSE(FAILED(result)) << lastError();
    // The description is the GL driver's name of the GPU, as the platform read it.
    EXPECT_EQ(std::string(m_videoCardDescription), glRendererOf(m_device));
    EXPECT_FALSE(std::string(m_videoCardDescription).empty());

    ID3D11Texture2D* backBufferPtr;
    ID3D11RenderTargetView* m_renderTargetView;
    result = m_swapChain->GetBuffer(0, __uuidof(ID3D11Texture2D), (LPVOID*)&backBufferPtr);
    ASSERT_FALSE(FAILED(result)) << lastError();
    result = m_device->CreateRenderTargetView(backBufferPtr, NULL, &m_renderTargetView);
    ASSERT_FALSE(FAILED(result)) << lastError();
    backBufferPtr->Release();
    backBufferPtr = 0;
    m_deviceContext->OMSetRenderTargets(1, &m_renderTargetView, NULL);
    const float color[4] = {0.2f, 1.0f, 0.0f, 1.0f};  // 0.2 * 255 = 51
    m_deviceContext->ClearRenderTargetView(m_renderTargetView, color);
    EXPECT_EQ(m_swapChain->Present(m_vsync_enabled ? 1 : 0, 0), S_OK);
    {
        Device d;
        d.device = m_device;
        d.context = m_deviceContext;
        ComPtr<ID3D11Texture2D> shown;
        ASSERT_EQ(m_swapChain->GetBuffer(0, __uuidof(ID3D11Texture2D), (void**)shown.GetAddressOf()), S_OK);
        const auto pixels = readPixels(d, shown.Get());
        ASSERT_EQ(pixels.size(), std::size_t(screenWidth) * screenHeight);
        EXPECT_EQ(pixels[pixels.size() / 2], (std::array<std::uint8_t, 4>{51, 255, 0, 255}));
    }

    // Shutdown: windowed first (a full-screen swap chain may not be released), then every object.
    if (m_swapChain) m_swapChain->SetFullscreenState(false, NULL);
    m_deviceContext->ClearState();  // not Rastertek's: unbound, the view's last Release says 0
    EXPECT_EQ(m_renderTargetView->Release(), 0u);
    m_deviceContext->Release();
    m_device->Release();
    EXPECT_EQ(m_swapChain->Release(), 0u);  // it held the device: the last reference goes with it
}

TEST(D3D11Dxgi, DisplayModeListCountsThenFillsAndSaysMoreData) {
    ComPtr<IDXGIFactory1> factory;
    ASSERT_EQ(CreateDXGIFactory1(__uuidof(IDXGIFactory1), reinterpret_cast<void**>(factory.GetAddressOf())), S_OK) << lastError();
    ComPtr<IDXGIAdapter1> adapter;
    ASSERT_EQ(factory->EnumAdapters1(0, adapter.GetAddressOf()), S_OK) << lastError();
    ComPtr<IDXGIOutput> output;
    ASSERT_EQ(adapter->EnumOutputs(0, output.GetAddressOf()), S_OK) << lastError();

    UINT count = 0;
    ASSERT_EQ(output->GetDisplayModeList(DXGI_FORMAT_B8G8R8A8_UNORM, 0, &count, nullptr), S_OK) << lastError();
    ASSERT_GE(count, 4u);
    std::vector<DXGI_MODE_DESC> modes(count);
    UINT filled = count;
    ASSERT_EQ(output->GetDisplayModeList(DXGI_FORMAT_B8G8R8A8_UNORM, 0, &filled, modes.data()), S_OK) << lastError();
    EXPECT_EQ(filled, count);
    for (const auto& [w, h] : {std::pair{640u, 480u}, {800u, 600u}, {1024u, 768u}, {1280u, 720u}, {1920u, 1080u}, {3840u, 2160u}}) {
        const bool listed = std::any_of(modes.begin(), modes.end(), [&](const DXGI_MODE_DESC& m) { return m.Width == w && m.Height == h; });
        EXPECT_TRUE(listed) << w << "x" << h;
    }
    for (std::size_t k = 0; k < modes.size(); ++k) {
        EXPECT_EQ(modes[k].Format, DXGI_FORMAT_B8G8R8A8_UNORM);
        EXPECT_EQ(modes[k].RefreshRate.Numerator, 60u);
        EXPECT_EQ(modes[k].RefreshRate.Denominator, 1u);
        if (k > 0) {
            EXPECT_TRUE(modes[k - 1].Width < modes[k].Width || (modes[k - 1].Width == modes[k].Width && modes[k - 1].Height < modes[k].Height));
        }
    }

    // Room for fewer: those are written, the count says how many, and DXGI_ERROR_MORE_DATA.
    std::vector<DXGI_MODE_DESC> some(count - 1);
    UINT room = count - 1;
    EXPECT_EQ(output->GetDisplayModeList(DXGI_FORMAT_B8G8R8A8_UNORM, 0, &room, some.data()), DXGI_ERROR_MORE_DATA);
    EXPECT_EQ(room, count - 1);
    EXPECT_EQ(some.back().Width, modes[count - 2].Width);
    EXPECT_EQ(some.back().Height, modes[count - 2].Height);
    UINT none = 0;
    DXGI_MODE_DESC unused;
    EXPECT_EQ(output->GetDisplayModeList(DXGI_FORMAT_B8G8R8A8_UNORM, 0, &none, &unused), DXGI_ERROR_MORE_DATA);
    EXPECT_EQ(none, 0u);
    EXPECT_EQ(output->GetDisplayModeList(DXGI_FORMAT_B8G8R8A8_UNORM, 0, nullptr, nullptr), DXGI_ERROR_INVALID_CALL);
    // A format no display scans out from has no modes.
    UINT floats = 99;
    EXPECT_EQ(output->GetDisplayModeList(DXGI_FORMAT_R32_FLOAT, 0, &floats, nullptr), S_OK);
    EXPECT_EQ(floats, 0u);

    DXGI_MODE_DESC want;
    want.Width = 1000;
    want.Height = 700;
    want.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    DXGI_MODE_DESC closest;
    ASSERT_EQ(output->FindClosestMatchingMode(&want, &closest, nullptr), S_OK) << lastError();
    EXPECT_EQ(closest.Width, 1024u);  // |24| + |68| beats 800x600's |200| + |100|
    EXPECT_EQ(closest.Height, 768u);
    EXPECT_EQ(closest.RefreshRate.Numerator, 60u);
    want.Format = DXGI_FORMAT_UNKNOWN;
    EXPECT_EQ(output->FindClosestMatchingMode(&want, &closest, nullptr), DXGI_ERROR_INVALID_CALL);
    DXGI_OUTPUT_DESC od;
    ASSERT_EQ(output->GetDesc(&od), S_OK);
    EXPECT_EQ(std::wstring(od.DeviceName), L"\\\\.\\DISPLAY1");
    EXPECT_EQ(od.DesktopCoordinates.right, 1920);
}

TEST(D3D11Dxgi, OneAdapterAndOneOutputThenNotFound) {
    IDXGIFactory* factory = nullptr;
    ASSERT_EQ(CreateDXGIFactory(__uuidof(IDXGIFactory), (void**)&factory), S_OK) << lastError();
    IDXGIAdapter* adapter = nullptr;
    IDXGIAdapter* second = reinterpret_cast<IDXGIAdapter*>(&factory);  // must come back null
    EXPECT_EQ(factory->EnumAdapters(1, &second), DXGI_ERROR_NOT_FOUND);
    EXPECT_EQ(second, nullptr);
    ASSERT_EQ(factory->EnumAdapters(0, &adapter), S_OK);
    IDXGIOutput* output = nullptr;
    EXPECT_EQ(adapter->EnumOutputs(1, &output), DXGI_ERROR_NOT_FOUND);
    EXPECT_EQ(output, nullptr);
    // A loop over adapters as D3D code writes it ends after one.
    UINT found = 0;
    for (IDXGIAdapter* a; factory->EnumAdapters(found, &a) != DXGI_ERROR_NOT_FOUND; ++found) a->Release();
    EXPECT_EQ(found, 1u);
    // IDXGIAdapter1's description: the same, with Flags saying a software rasteriser.
    IDXGIAdapter1* adapter1 = nullptr;
    ASSERT_EQ(adapter->QueryInterface(__uuidof(IDXGIAdapter1), (void**)&adapter1), S_OK) << lastError();
    DXGI_ADAPTER_DESC1 d1;
    ASSERT_EQ(adapter1->GetDesc1(&d1), S_OK);
    Device d;
    const std::string renderer = glRendererOf(d.device.Get());
    EXPECT_EQ(std::wstring(d1.Description), std::wstring(renderer.begin(), renderer.end()));
    if (renderer.find("llvmpipe") != std::string::npos) {
        EXPECT_EQ(d1.Flags, UINT(DXGI_ADAPTER_FLAG_SOFTWARE));
        EXPECT_EQ(d1.VendorId, 0u);  // Mesa's, not a GPU maker's
    }
    // The enumerated adapter makes a device, with D3D's driver type for it.
    ComPtr<ID3D11Device> onAdapter;
    EXPECT_EQ(D3D11CreateDevice(adapter, D3D_DRIVER_TYPE_HARDWARE, nullptr, 0, nullptr, 0, D3D11_SDK_VERSION, onAdapter.GetAddressOf(), nullptr,
                                nullptr),
              E_INVALIDARG);
    EXPECT_EQ(D3D11CreateDevice(adapter, D3D_DRIVER_TYPE_UNKNOWN, nullptr, 0, nullptr, 0, D3D11_SDK_VERSION, onAdapter.GetAddressOf(), nullptr,
                                nullptr),
              S_OK)
        << lastError();
    EXPECT_EQ(adapter1->Release(), 1u);  // the QueryInterface reference; `adapter` holds the object
    EXPECT_EQ(adapter->Release(), 0u);
    EXPECT_EQ(factory->Release(), 0u);
}

TEST(D3D11Dxgi, DeviceToFactoryChainMakesASwapChainThatDraws) {
    ID3D11Device* device = nullptr;
    ID3D11DeviceContext* context = nullptr;
    ASSERT_EQ(D3D11CreateDevice(nullptr, D3D_DRIVER_TYPE_HARDWARE, nullptr, 0, nullptr, 0, D3D11_SDK_VERSION, &device, nullptr, &context), S_OK);
    IDXGIDevice* dxgiDevice = nullptr;
    ASSERT_EQ(device->QueryInterface(__uuidof(IDXGIDevice), (void**)&dxgiDevice), S_OK) << lastError();
    IDXGIAdapter* adapter = nullptr;
    ASSERT_EQ(dxgiDevice->GetAdapter(&adapter), S_OK) << lastError();
    IDXGIFactory* factory = nullptr;
    ASSERT_EQ(adapter->GetParent(__uuidof(IDXGIFactory), (void**)&factory), S_OK) << lastError();
    DXGI_SWAP_CHAIN_DESC desc = swapChainDesc(24, 16);
    IDXGISwapChain* swapChain = nullptr;
    ASSERT_EQ(factory->CreateSwapChain(device, &desc, &swapChain), S_OK) << lastError();
    int window = 0;
    EXPECT_EQ(factory->MakeWindowAssociation(&window, DXGI_MWA_NO_ALT_ENTER), S_OK);
    HWND associated = nullptr;
    EXPECT_EQ(factory->GetWindowAssociation(&associated), S_OK);
    EXPECT_EQ(associated, &window);

    // COM's identity: both interfaces of the device give one IUnknown; the same adapter each time;
    // the swap chain's parent is the factory that made it.
    IUnknown* viaDevice = nullptr;
    IUnknown* viaDxgi = nullptr;
    ASSERT_EQ(device->QueryInterface(__uuidof(IUnknown), (void**)&viaDevice), S_OK);
    ASSERT_EQ(dxgiDevice->QueryInterface(__uuidof(IUnknown), (void**)&viaDxgi), S_OK);
    EXPECT_EQ(viaDevice, viaDxgi);
    viaDevice->Release();
    viaDxgi->Release();
    IDXGIAdapter* again = nullptr;
    ASSERT_EQ(dxgiDevice->GetAdapter(&again), S_OK);
    EXPECT_EQ(again, adapter);
    again->Release();
    IDXGIFactory* parent = nullptr;
    ASSERT_EQ(swapChain->GetParent(__uuidof(IDXGIFactory), (void**)&parent), S_OK) << lastError();
    EXPECT_EQ(parent, factory);
    parent->Release();
    ComPtr<ID3D11Device> held(device);
    ComPtr<IDXGIDevice1> dxgi1;  // ComPtr's As, and IID_PPV_ARGS, reach the same object
    ASSERT_EQ(held.As(&dxgi1), S_OK) << lastError();
    EXPECT_EQ(static_cast<IDXGIDevice*>(dxgi1.Get()), dxgiDevice);
    IDXGIFactory1* factory1 = nullptr;
    ASSERT_EQ(factory->QueryInterface(IID_PPV_ARGS(&factory1)), S_OK) << lastError();
    EXPECT_EQ(static_cast<IDXGIFactory*>(factory1), factory);
    factory1->Release();
    dxgi1.Reset();
    held.Reset();
    void* nothing = &window;
    EXPECT_EQ(device->QueryInterface(__uuidof(IDXGIFactory), &nothing), E_NOINTERFACE);
    EXPECT_EQ(nothing, nullptr);

    Device d;
    d.device = device;
    d.context = context;
    const FLOAT blue[4] = {0, 0, 1, 1};
    expectClearedBackBuffer(d, swapChain, 24, 16, blue, {0, 0, 255, 255});
    BOOL fullscreen = TRUE;
    IDXGIOutput* target = reinterpret_cast<IDXGIOutput*>(&window);
    EXPECT_EQ(swapChain->GetFullscreenState(&fullscreen, &target), S_OK);
    EXPECT_EQ(fullscreen, FALSE);
    EXPECT_EQ(target, nullptr);
    d.device.Reset();
    d.context.Reset();

    // Every reference given back: the swap chain's on the device last.
    EXPECT_EQ(factory->Release(), 2u);  // the adapter and the swap chain it made hold it
    EXPECT_EQ(dxgiDevice->Release(), 3u);  // the device's count: device, context, swap chain
    context->Release();
    EXPECT_EQ(device->Release(), 1u);
    EXPECT_EQ(swapChain->Release(), 0u);
    EXPECT_EQ(adapter->Release(), 0u);
}

TEST(D3D11Dxgi, ResizeBuffersWaitsForTheBackBufferToBeFreeThenGivesTheNewSize) {
    DXGI_SWAP_CHAIN_DESC desc = swapChainDesc(16, 8);
    ComPtr<IDXGISwapChain> swapChain;
    Device d;
    d.device.Reset();
    d.context.Reset();
    ASSERT_EQ(D3D11CreateDeviceAndSwapChain(nullptr, D3D_DRIVER_TYPE_HARDWARE, nullptr, 0, nullptr, 0, D3D11_SDK_VERSION, &desc,
                                            swapChain.GetAddressOf(), d.device.GetAddressOf(), nullptr, d.context.GetAddressOf()),
              S_OK)
        << lastError();
    ComPtr<ID3D11Texture2D> old;
    ASSERT_EQ(swapChain->GetBuffer(0, __uuidof(ID3D11Texture2D), reinterpret_cast<void**>(old.GetAddressOf())), S_OK);
    // Held directly, through a view, through a view bound to the context: refused each time.
    EXPECT_EQ(swapChain->ResizeBuffers(0, 40, 20, DXGI_FORMAT_UNKNOWN, 0), DXGI_ERROR_INVALID_CALL);
    EXPECT_NE(lastError().find("reference"), std::string::npos) << lastError();
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(old.Get(), nullptr, rtv.GetAddressOf()), S_OK);
    old.Reset();
    EXPECT_EQ(swapChain->ResizeBuffers(0, 40, 20, DXGI_FORMAT_UNKNOWN, 0), DXGI_ERROR_INVALID_CALL);
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    rtv.Reset();
    EXPECT_EQ(swapChain->ResizeBuffers(0, 40, 20, DXGI_FORMAT_UNKNOWN, 0), DXGI_ERROR_INVALID_CALL);
    d.context->OMSetRenderTargets(0, nullptr, nullptr);
    ASSERT_EQ(swapChain->ResizeBuffers(0, 40, 20, DXGI_FORMAT_UNKNOWN, 0), S_OK) << lastError();

    DXGI_SWAP_CHAIN_DESC now;
    ASSERT_EQ(swapChain->GetDesc(&now), S_OK);
    EXPECT_EQ(now.BufferDesc.Width, 40u);
    EXPECT_EQ(now.BufferDesc.Height, 20u);
    EXPECT_EQ(now.BufferDesc.Format, DXGI_FORMAT_R8G8B8A8_UNORM);
    EXPECT_EQ(now.BufferCount, 1u);
    const FLOAT red[4] = {1, 0, 0, 1};
    expectClearedBackBuffer(d, swapChain.Get(), 40, 20, red, {255, 0, 0, 255});
    // 0 x 0 keeps the size (headless, there is no window's to take).
    ASSERT_EQ(swapChain->ResizeBuffers(2, 0, 0, DXGI_FORMAT_UNKNOWN, 0), S_OK) << lastError();
    ASSERT_EQ(swapChain->GetDesc(&now), S_OK);
    EXPECT_EQ(now.BufferDesc.Width, 40u);
    EXPECT_EQ(now.BufferCount, 2u);

    // The output the swap chain is on lists its size, which is no common one.
    ComPtr<IDXGIOutput> output;
    ASSERT_EQ(swapChain->GetContainingOutput(output.GetAddressOf()), S_OK) << lastError();
    DXGI_MODE_DESC want;
    want.Width = 41;
    want.Height = 19;
    want.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    DXGI_MODE_DESC closest;
    ASSERT_EQ(output->FindClosestMatchingMode(&want, &closest, d.device.Get()), S_OK) << lastError();
    EXPECT_EQ(closest.Width, 40u);
    EXPECT_EQ(closest.Height, 20u);
    EXPECT_EQ(swapChain->ResizeTarget(&want), S_OK);
}

}  // namespace
