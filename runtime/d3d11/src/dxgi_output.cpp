// The adapter's one output, headless: a virtual 1920 x 1080 desktop whose display modes are the
// common sizes below (and the swap chain's size, for the output a swap chain gives) at 60 Hz,
// listed in the formats a D3D11 back buffer scans out from.
#include <algorithm>
#include <cstdlib>
#include <vector>

#include "dxgi_impl.h"

namespace fxport::d3d11 {

namespace {

struct Size {
    UINT width, height;
};
// The sizes tutorials ask for and monitors have (4:3, 16:9, 16:10, 5:4), ascending as DXGI lists.
constexpr Size kCommonSizes[] = {{640, 480},   {720, 480},   {800, 600},   {1024, 768},  {1152, 864},  {1280, 720},  {1280, 768},
                                 {1280, 800},  {1280, 960},  {1280, 1024}, {1360, 768},  {1366, 768},  {1440, 900},  {1600, 900},
                                 {1600, 1200}, {1680, 1050}, {1920, 1080}, {1920, 1200}, {2560, 1440}, {2560, 1600}, {3840, 2160}};
constexpr Size kDesktop = {1920, 1080};
constexpr DXGI_RATIONAL kRefreshRate = {60, 1};

// D3D11's display scan-out formats (a back buffer of another format cannot be shown full-screen).
bool scansOut(DXGI_FORMAT f) {
    switch (f) {
    case DXGI_FORMAT_R8G8B8A8_UNORM:
    case DXGI_FORMAT_R8G8B8A8_UNORM_SRGB:
    case DXGI_FORMAT_B8G8R8A8_UNORM:
    case DXGI_FORMAT_B8G8R8A8_UNORM_SRGB:
    case DXGI_FORMAT_R10G10B10A2_UNORM:
    case DXGI_FORMAT_R16G16B16A16_FLOAT: return true;
    default: return false;
    }
}

DXGI_MODE_DESC modeOf(Size s, DXGI_FORMAT format) {
    DXGI_MODE_DESC m;
    m.Width = s.width;
    m.Height = s.height;
    m.RefreshRate = kRefreshRate;
    m.Format = format;
    m.ScanlineOrdering = DXGI_MODE_SCANLINE_ORDER_PROGRESSIVE;
    m.Scaling = DXGI_MODE_SCALING_UNSPECIFIED;
    return m;
}

class Output final : public Counted<IDXGIOutput> {
public:
    Output(IDXGIAdapter* adapter, Size swapChain) : adapter_(adapter), sizes_(std::begin(kCommonSizes), std::end(kCommonSizes)) {
        const bool listed = std::any_of(sizes_.begin(), sizes_.end(), [&](Size s) { return s.width == swapChain.width && s.height == swapChain.height; });
        if (swapChain.width != 0 && !listed) {
            auto at = std::find_if(sizes_.begin(), sizes_.end(), [&](Size s) {
                return s.width > swapChain.width || (s.width == swapChain.width && s.height > swapChain.height);
            });
            sizes_.insert(at, swapChain);
        }
    }
    HRESULT QueryInterface(REFIID riid, void** ppv) override {
        return answerQuery<IUnknown, IDXGIObject, IDXGIOutput>(this, "IDXGIOutput", riid, ppv);
    }
    HRESULT GetParent(REFIID riid, void** ppParent) override {
        if (!ppParent) return fail(DXGI_ERROR_INVALID_CALL, "IDXGIOutput::GetParent: ppParent is null");
        return adapter_->QueryInterface(riid, ppParent);
    }
    HRESULT GetDesc(DXGI_OUTPUT_DESC* pDesc) override {
        if (!pDesc) return fail(E_INVALIDARG, "IDXGIOutput::GetDesc: pDesc is null");
        *pDesc = DXGI_OUTPUT_DESC{};
        const wchar_t name[] = L"\\\\.\\DISPLAY1";
        std::copy(std::begin(name), std::end(name), pDesc->DeviceName);
        pDesc->DesktopCoordinates = RECT{0, 0, INT(kDesktop.width), INT(kDesktop.height)};
        pDesc->AttachedToDesktop = TRUE;
        pDesc->Rotation = DXGI_MODE_ROTATION_IDENTITY;
        return succeed();
    }
    HRESULT GetDisplayModeList(DXGI_FORMAT EnumFormat, UINT, UINT* pNumModes, DXGI_MODE_DESC* pDesc) override {
        if (!pNumModes) return fail(DXGI_ERROR_INVALID_CALL, "IDXGIOutput::GetDisplayModeList: pNumModes is null");
        const UINT count = scansOut(EnumFormat) ? UINT(sizes_.size()) : 0;
        if (!pDesc) {
            *pNumModes = count;
            return succeed();
        }
        const UINT written = std::min(*pNumModes, count);
        for (UINT i = 0; i < written; ++i) pDesc[i] = modeOf(sizes_[i], EnumFormat);
        const UINT room = *pNumModes;
        *pNumModes = written;
        if (written < count)
            return fail(DXGI_ERROR_MORE_DATA, "IDXGIOutput::GetDisplayModeList: *pNumModes = " + std::to_string(room) + ", but there are " +
                                                  std::to_string(count) + " modes (call with pDesc null first to get the count)");
        return succeed();
    }
    HRESULT FindClosestMatchingMode(const DXGI_MODE_DESC* pModeToMatch, DXGI_MODE_DESC* pClosestMatch, IUnknown* pConcernedDevice) override {
        const char* call = "IDXGIOutput::FindClosestMatchingMode: ";
        if (!pModeToMatch || !pClosestMatch) return fail(DXGI_ERROR_INVALID_CALL, std::string(call) + "pModeToMatch or pClosestMatch is null");
        const DXGI_MODE_DESC& want = *pModeToMatch;
        if ((want.Width == 0) != (want.Height == 0))
            return fail(DXGI_ERROR_INVALID_CALL, std::string(call) + "Width x Height = " + std::to_string(want.Width) + " x " +
                                                     std::to_string(want.Height) + " (both 0, or neither)");
        DXGI_FORMAT format = want.Format;
        if (format == DXGI_FORMAT_UNKNOWN && !pConcernedDevice)
            return fail(DXGI_ERROR_INVALID_CALL, std::string(call) + "Format UNKNOWN needs pConcernedDevice");
        if (format == DXGI_FORMAT_UNKNOWN) format = DXGI_FORMAT_R8G8B8A8_UNORM;
        if (!scansOut(format))
            return fail(DXGI_ERROR_NOT_FOUND, std::string(call) + "Format " + std::to_string(format) + " is not a scan-out format (no mode has it)");
        const Size target = want.Width == 0 ? kDesktop : Size{want.Width, want.Height};
        auto distance = [&](Size s) { return std::abs(INT(s.width) - INT(target.width)) + std::abs(INT(s.height) - INT(target.height)); };
        const Size best = *std::min_element(sizes_.begin(), sizes_.end(), [&](Size a, Size b) { return distance(a) < distance(b); });
        *pClosestMatch = modeOf(best, format);
        return succeed();
    }
    HRESULT WaitForVBlank() override { return succeed(); }

private:
    ComPtr<IDXGIAdapter> adapter_;
    std::vector<Size> sizes_;
};

}  // namespace

IDXGIOutput* makeOutput(IDXGIAdapter* adapter, UINT swapWidth, UINT swapHeight) { return new Output(adapter, Size{swapWidth, swapHeight}); }

}  // namespace fxport::d3d11
