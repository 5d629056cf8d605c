// D3DX10CreateShaderResourceViewFromFile (fxport/d3d10/d3dx10tex.h): the file becomes a
// Texture2D of the device core (Texture2D::FromFile), given a full mip chain where the file has
// one level, held by a D3D11 texture object of BIND_SHADER_RESOURCE, and viewed whole.
#include <algorithm>

#include "d3d11_impl.h"
#include "device/image_io.h"
#include "fxport/d3d10/d3dx10tex.h"
#include "guarded.h"

namespace fxport::d3d10 {

namespace {

using d3d11::fail;

// `loaded` with every level down to 1x1: level 0 as loaded, each further one halved from the last.
std::unique_ptr<Texture2D> withMipChain(GraphicsDevice& core, std::unique_ptr<Texture2D> loaded) {
    if (loaded->LevelCount() > 1 || (loaded->Width() == 1 && loaded->Height() == 1)) return loaded;
    int w = loaded->Width(), h = loaded->Height();
    auto out = std::make_unique<Texture2D>(core, w, h, true, SurfaceFormat::Color);
    out->Name = loaded->Name;
    std::vector<Color> level = loaded->GetData<Color>();
    for (int l = 0; l < out->LevelCount(); ++l) {
        if (l > 0) {
            level = detail::halve(level, w, h);
            w = std::max(1, w / 2), h = std::max(1, h / 2);
        }
        out->SetData(l, nullptr, level.data(), level.size());
    }
    return out;
}

HRESULT load(ID3D10Device* device10, const std::string& path, D3DX10_IMAGE_LOAD_INFO* info, void* pump, ID3D10ShaderResourceView** pp) {
    const char* call = "D3DX10CreateShaderResourceViewFromFile";
    auto* device = device10 ? dynamic_cast<d3d11::Device*>(device10->GetD3D11Device()) : nullptr;
    if (!device) return fail(E_INVALIDARG, std::string(call) + ": pDevice is null or not fxport's");
    if (info) return fail(E_NOTIMPL, std::string(call) + ": pLoadInfo is not null: fxport loads with D3DX10's defaults only");
    if (pump) return fail(E_NOTIMPL, std::string(call) + ": pPump is not null: fxport loads at once (no thread pump)");
    if (!pp) return fail(E_INVALIDARG, std::string(call) + ": ppShaderResourceView is null");
    return d3d11::guarded(call, [&] {
        std::unique_ptr<Texture2D> texture = withMipChain(device->core(), Texture2D::FromFile(device->core(), path));
        D3D11_TEXTURE2D_DESC desc;
        desc.Width = UINT(texture->Width());
        desc.Height = UINT(texture->Height());
        desc.MipLevels = UINT(texture->LevelCount());
        desc.ArraySize = 1;
        desc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
        desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
        ComPtr<d3d11::Texture> held;
        held.Attach(new d3d11::Texture(device, desc));  // its one reference; the view takes its own
        held->format = SurfaceFormat::Color;
        held->levels = texture->LevelCount();
        held->colour = std::move(texture);
        return device->CreateShaderResourceView(held.Get(), nullptr, pp);
    });
}

HRESULT answer(HRESULT hr, HRESULT* pHResult) {
    if (pHResult) *pHResult = hr;
    return hr;
}

}  // namespace

HRESULT D3DX10CreateShaderResourceViewFromFile(ID3D10Device* pDevice, LPCSTR pSrcFile, D3DX10_IMAGE_LOAD_INFO* pLoadInfo, void* pPump,
                                               ID3D10ShaderResourceView** ppShaderResourceView, HRESULT* pHResult) {
    if (!pSrcFile) return answer(fail(E_INVALIDARG, "D3DX10CreateShaderResourceViewFromFile: pSrcFile is null"), pHResult);
    return answer(load(pDevice, pSrcFile, pLoadInfo, pPump, ppShaderResourceView), pHResult);
}

HRESULT D3DX10CreateShaderResourceViewFromFile(ID3D10Device* pDevice, const wchar_t* pSrcFile, D3DX10_IMAGE_LOAD_INFO* pLoadInfo,
                                               void* pPump, ID3D10ShaderResourceView** ppShaderResourceView, HRESULT* pHResult) {
    if (!pSrcFile) return answer(fail(E_INVALIDARG, "D3DX10CreateShaderResourceViewFromFile: pSrcFile is null"), pHResult);
    return answer(load(pDevice, d3d11::narrowPath(pSrcFile), pLoadInfo, pPump, ppShaderResourceView), pHResult);
}

}  // namespace fxport::d3d10
