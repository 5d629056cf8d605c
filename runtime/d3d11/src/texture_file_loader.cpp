// The texture-file loader of D3DX10/D3DX11 and DirectXTK (texture_file_loader.h). A DDS file's
// texels go to the device core as stored (BC blocks stay blocks); where the runtime cannot hold them
// so (a DXGI format it lacks, such as B8G8R8X8, or a partial mip chain: the core makes one level or
// the full chain) a file whose texels decode to RGBA8 is loaded decoded, its chain completed by 2x2
// averages as Texture2D/TextureCube/Texture3D::FromFile do.
#include "texture_file_loader.h"

#include <algorithm>
#include <bit>
#include <fstream>

#include "device/dds_image.h"
#include "device/image_io.h"
#include "guarded.h"

namespace fxport::d3d11 {

namespace {

using detail::DdsImage;

D3D11_TEXTURE2D_DESC shaderResource2D(const DdsImage& dds, DXGI_FORMAT format) {
    D3D11_TEXTURE2D_DESC d;
    d.Width = UINT(dds.width);
    d.Height = UINT(dds.height);
    d.MipLevels = UINT(dds.levelCount);
    d.ArraySize = UINT(dds.arraySize * (dds.cube ? 6 : 1));
    d.Format = format;
    d.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    d.MiscFlags = dds.cube ? UINT(D3D11_RESOURCE_MISC_TEXTURECUBE) : 0u;
    return d;
}

// A cube (fxport's CreateTexture2D makes cubes of one level: built here from the core's TextureCube).
Texture* newCube(Device* device, const DdsImage& dds, DXGI_FORMAT format, SurfaceFormat surface) {
    ComPtr<Texture> t;
    t.Attach(new Texture(device, shaderResource2D(dds, format)));
    t->format = surface;
    t->levels = dds.levelCount;
    t->cube = std::make_unique<fxport::TextureCube>(device->core(), dds.width, dds.levelCount > 1, surface);
    for (int face = 0; face < 6; ++face)
        for (int level = 0; level < dds.levelCount; ++level) {
            const std::vector<std::uint8_t>& bytes = dds.stored[std::size_t(face * dds.levelCount + level)];
            t->cube->setData(CubeMapFace(face), level, bytes.data(), bytes.size());
        }
    return t.Detach();
}

// A 2D texture or array through CreateTexture2D (subresource item * levels + level, rows packed).
HRESULT newTexture2D(Device* device, const DdsImage& dds, DXGI_FORMAT format, SurfaceFormat surface, ID3D11Resource** out) {
    const D3D11_TEXTURE2D_DESC d = shaderResource2D(dds, format);
    std::vector<D3D11_SUBRESOURCE_DATA> data(dds.stored.size());
    for (std::size_t i = 0; i < data.size(); ++i) {
        const int level = int(i % std::size_t(dds.levelCount));
        data[i].pSysMem = dds.stored[i].data();
        data[i].SysMemPitch = UINT(rowBytes(surface, std::max(1, dds.width >> level)));
    }
    ID3D11Texture2D* texture = nullptr;
    const HRESULT hr = device->CreateTexture2D(&d, data.data(), &texture);
    if (SUCCEEDED(hr)) *out = texture;
    return hr;
}

HRESULT newVolume(Device* device, const DdsImage& dds, DXGI_FORMAT format, SurfaceFormat surface, ID3D11Resource** out) {
    D3D11_TEXTURE3D_DESC d;
    d.Width = UINT(dds.width);
    d.Height = UINT(dds.height);
    d.Depth = UINT(dds.depth);
    d.MipLevels = UINT(dds.levelCount);
    d.Format = format;
    d.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    std::vector<D3D11_SUBRESOURCE_DATA> data(dds.stored.size());
    for (std::size_t level = 0; level < data.size(); ++level) {
        const int w = std::max(1, dds.width >> level), h = std::max(1, dds.height >> level);
        data[level].pSysMem = dds.stored[level].data();
        data[level].SysMemPitch = UINT(rowBytes(surface, w));
        data[level].SysMemSlicePitch = UINT(rowBytes(surface, w) * std::size_t(rowCount(surface, h)));
    }
    ID3D11Texture3D* volume = nullptr;
    const HRESULT hr = device->CreateTexture3D(&d, data.data(), &volume);
    if (SUCCEEDED(hr)) *out = volume;
    return hr;
}

// A core texture of Color texels (decoded) held by a D3D11 object of R8G8B8A8_UNORM.
HRESULT wrapDecoded(Device* device, std::unique_ptr<fxport::Texture2D> flat, std::unique_ptr<fxport::TextureCube> cube, ID3D11Resource** out) {
    D3D11_TEXTURE2D_DESC d;
    d.Width = UINT(flat ? flat->Width() : cube->Size());
    d.Height = UINT(flat ? flat->Height() : cube->Size());
    d.MipLevels = UINT(flat ? flat->LevelCount() : cube->LevelCount());
    d.ArraySize = flat ? 1 : 6;
    d.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    d.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    d.MiscFlags = flat ? 0u : UINT(D3D11_RESOURCE_MISC_TEXTURECUBE);
    auto* t = new Texture(device, d);
    t->format = SurfaceFormat::Color;
    t->levels = int(d.MipLevels);
    t->colour = std::move(flat);
    t->cube = std::move(cube);
    *out = t;
    return succeed();
}

// A DX10 TEXTURE1D file: its rows as stored (item-major, then level), one subresource each.
HRESULT newLine(Device* device, const DdsImage& dds, DXGI_FORMAT format, ID3D11Resource** out) {
    D3D11_TEXTURE1D_DESC d;
    d.Width = UINT(dds.width);
    d.MipLevels = UINT(dds.levelCount);
    d.ArraySize = UINT(dds.arraySize);
    d.Format = format;
    d.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    std::vector<D3D11_SUBRESOURCE_DATA> data(dds.stored.size());
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = {dds.stored[i].data(), UINT(dds.stored[i].size()), 0};
    ID3D11Texture1D* line = nullptr;
    const HRESULT hr = device->CreateTexture1D(&d, data.data(), &line);
    if (SUCCEEDED(hr)) *out = line;
    return hr;
}

// The DDS decoded to RGBA8 as the device core's FromFile decodes it (completing a partial chain).
HRESULT loadDecodedDds(Device* device, const std::string& path, const DdsImage& dds, ID3D11Resource** out) {
    if (dds.volume) {
        std::unique_ptr<fxport::Texture3D> texels = fxport::Texture3D::FromFile(device->core(), path);
        D3D11_TEXTURE3D_DESC d;
        d.Width = UINT(texels->Width());
        d.Height = UINT(texels->Height());
        d.Depth = UINT(texels->Depth());
        d.MipLevels = UINT(texels->LevelCount());
        d.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
        d.BindFlags = D3D11_BIND_SHADER_RESOURCE;
        auto* v = new Volume(device, d);
        v->texels = std::move(texels);
        *out = v;
        return succeed();
    }
    if (dds.cube) return wrapDecoded(device, nullptr, fxport::TextureCube::FromFile(device->core(), path), out);
    return wrapDecoded(device, detail::texture2DFromDds(device->core(), path), nullptr, out);
}

int fullChain(const DdsImage& dds) { return int(std::bit_width(unsigned(std::max({dds.width, dds.height, dds.depth})))); }

HRESULT loadDds(Device* device, const std::string& path, const TextureFileRequest& r, ID3D11Resource** out) {
    const std::string at = std::string(r.call) + ": " + path;
    DdsImage dds = detail::readDds(path, detail::DdsContent::Stored);
    if (r.alphaMode) *r.alphaMode = dds.alphaMode;
    if (r.maxSize && std::size_t(std::max({dds.width, dds.height, dds.depth})) > r.maxSize)
        return fail(E_NOTIMPL, at + ": " + std::to_string(dds.width) + "x" + std::to_string(dds.height) + " is larger than maxsize " +
                                   std::to_string(r.maxSize) + " (fxport does not drop levels to fit)");
    const DXGI_FORMAT format = DXGI_FORMAT(dds.dxgiFormat);
    SurfaceFormat surface = SurfaceFormat::Color;
    const bool held = dds.dxgiFormat && textureFormat(format, surface) && !depthFamilyOf(format);
    if (dds.oneDimensional) {  // any chain: CreateTexture1D takes every level count
        if (!held) return fail(E_NOTIMPL, at + ": " + formatName(format) + " (" + std::to_string(dds.dxgiFormat) + ") is not a 1D texture format fxport samples");
        return newLine(device, dds, format, out);
    }
    const bool chainFits = dds.levelCount == 1 || dds.levelCount == fullChain(dds) || (dds.arraySize > 1 && !dds.cube);
    if (dds.dxgiFormat == 0 || !held || !chainFits) {
        if (dds.arraySize == 1 && dds.decodable) return loadDecodedDds(device, path, dds, out);
        if (!held)
            return fail(E_NOTIMPL, at + ": " + formatName(format) + " (" + std::to_string(dds.dxgiFormat) + ") is not a texture format fxport samples");
        return fail(E_NOTIMPL, at + ": " + std::to_string(dds.levelCount) + " of " + std::to_string(fullChain(dds)) +
                                   " mip levels: fxport makes 1 level or the full chain of a cube, volume or 2D texture");
    }
    if (dds.cube && dds.width != dds.height)
        return fail(E_INVALIDARG, at + ": a cube map of " + std::to_string(dds.width) + "x" + std::to_string(dds.height) + " faces (a cube's are square)");
    if (dds.cube && dds.arraySize > 1) return fail(E_NOTIMPL, at + ": a cube array of " + std::to_string(dds.arraySize) + " cubes; fxport's cubes are single");
    if (dds.volume) return newVolume(device, dds, format, surface, out);
    if (dds.cube) {
        *out = newCube(device, dds, format, surface);
        return succeed();
    }
    return newTexture2D(device, dds, format, surface, out);
}

// An image through stb_image as Texture2D::FromFile reads it, R8G8B8A8_UNORM, with the full chain of
// 2x2 box averages (D3DX's default) or one level.
HRESULT loadImage(Device* device, const std::string& path, const TextureFileRequest& r, ID3D11Resource** out) {
    detail::Image image = detail::loadImage(path);  // throws ArgumentError naming the file
    if (r.maxSize && std::size_t(std::max(image.width, image.height)) > r.maxSize)
        return fail(E_NOTIMPL, std::string(r.call) + ": " + path + ": " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                   " is larger than maxsize " + std::to_string(r.maxSize) + " (fxport does not resize)");
    const int levels = r.imageMipChain ? int(std::bit_width(unsigned(std::max(image.width, image.height)))) : 1;
    std::vector<std::vector<Color>> chain{std::move(image.pixels)};
    for (int l = 1; l < levels; ++l)
        chain.push_back(detail::halve(chain.back(), std::max(1, image.width >> (l - 1)), std::max(1, image.height >> (l - 1))));
    D3D11_TEXTURE2D_DESC d;
    d.Width = UINT(image.width);
    d.Height = UINT(image.height);
    d.MipLevels = UINT(levels);
    d.ArraySize = 1;
    d.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    d.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    std::vector<D3D11_SUBRESOURCE_DATA> data(chain.size());
    for (std::size_t l = 0; l < chain.size(); ++l) {
        data[l].pSysMem = chain[l].data();
        data[l].SysMemPitch = UINT(std::max(1, image.width >> l) * 4);
    }
    ID3D11Texture2D* texture = nullptr;
    const HRESULT hr = device->CreateTexture2D(&d, data.data(), &texture);
    if (SUCCEEDED(hr)) *out = texture;
    return hr;
}

// DDS files are known by their magic, as D3DX knows them (not by their name).
bool startsLikeDds(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char magic[4] = {};
    return in.read(magic, 4) && std::equal(magic, magic + 4, "DDS ");
}

}  // namespace

HRESULT loadTextureFile(Device* device, const std::string& path, const TextureFileRequest& r, ID3D11Resource** out) {
    *out = nullptr;
    return guarded(r.call, [&]() -> HRESULT {
        const bool dds = startsLikeDds(path);
        if (dds && !r.dds) return fail(E_INVALIDARG, std::string(r.call) + ": " + path + " is a DDS file (CreateDDSTextureFromFile loads those)");
        if (!dds && !r.images) return fail(E_INVALIDARG, std::string(r.call) + ": " + path + " is not a DDS file (no 'DDS ' magic)");
        return dds ? loadDds(device, path, r, out) : loadImage(device, path, r, out);
    });
}

}  // namespace fxport::d3d11
