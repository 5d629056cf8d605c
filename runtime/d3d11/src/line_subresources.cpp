// The context's transfers of 1D textures (d3d11_impl.h): one subresource is one row of texels,
// kept by the device core's Texture1D or, for USAGE_STAGING, in CPU memory. Copies that involve
// a staging texture, and regions, travel through the CPU: a row is at most 16384 texels.
#include <cstring>

#include "d3d11_impl.h"

namespace fxport::d3d11 {

namespace {

int levelOf(const LineTexture& t, int sub) { return sub % t.levels; }
int sliceOf(const LineTexture& t, int sub) { return sub / t.levels; }

HRESULT checkSub(const char* call, const char* name, const LineTexture& t, UINT sub) {
    if (sub < UINT(t.subresources())) return S_OK;
    return fail(E_INVALIDARG, std::string(call) + ": " + name + " = " + std::to_string(sub) + " of " + std::to_string(t.subresources()) +
                                  " subresources of the 1D texture");
}

// A D3D11_BOX over a row: [left, right) inside `width`, top/bottom and front/back the row itself.
HRESULT checkRowBox(const std::string& at, const D3D11_BOX& b, int width) {
    if (b.right <= b.left || b.right > UINT(width) || b.top != 0 || b.bottom != 1 || b.front != 0 || b.back != 1)
        return fail(E_INVALIDARG, at + " {left " + std::to_string(b.left) + ", right " + std::to_string(b.right) + ", top " + std::to_string(b.top) +
                                      ", bottom " + std::to_string(b.bottom) + "}: a 1D level is [0, " + std::to_string(width) + ") x [0, 1)");
    return S_OK;
}

}  // namespace

std::vector<std::uint8_t> readLine(LineTexture& t, int sub) {
    if (!t.texels) return t.staging[std::size_t(sub)];  // STAGING
    std::vector<std::uint8_t> row(t.rowBytes(levelOf(t, sub)));
    t.texels->getData(levelOf(t, sub), sliceOf(t, sub), row.data(), row.size());
    return row;
}

void writeLine(LineTexture& t, int sub, int x, const std::uint8_t* texels, int count) {
    const std::size_t texel = std::size_t(bytesPerPixel(t.format)), bytes = texel * std::size_t(count);
    if (t.texels) return t.texels->setData(levelOf(t, sub), sliceOf(t, sub), x, count, texels, bytes);
    std::memcpy(t.staging[std::size_t(sub)].data() + std::size_t(x) * texel, texels, bytes);
}

// A DYNAMIC texture hands out a CPU row too, uploaded at Unmap (its one subresource).
HRESULT mapLine(LineTexture& t, UINT sub, D3D11_MAPPED_SUBRESOURCE& out) {
    if (HRESULT hr = checkSub("Map", "Subresource", t, sub); FAILED(hr)) return hr;
    if (t.mapped >= 0) return fail(E_INVALIDARG, "Map: the 1D texture is already mapped");
    if (t.staging.empty()) t.staging.emplace_back(t.rowBytes(0), 0);
    t.mapped = int(sub);
    const UINT bytes = UINT(t.rowBytes(levelOf(t, int(sub))));
    out = D3D11_MAPPED_SUBRESOURCE{t.staging[sub].data(), bytes, bytes};
    return succeed();
}

HRESULT unmapLine(LineTexture& t, UINT sub) {
    if (t.mapped != int(sub)) return fail(E_INVALIDARG, "Unmap: subresource " + std::to_string(sub) + " of the 1D texture is not mapped");
    t.mapped = -1;
    if (t.texels) writeLine(t, int(sub), 0, t.staging[sub].data(), t.levelWidth(levelOf(t, int(sub))));
    return succeed();
}

HRESULT updateLine(LineTexture& t, UINT sub, const D3D11_BOX* box, const void* data) {
    if (t.desc.Usage != D3D11_USAGE_DEFAULT) return fail(E_INVALIDARG, "UpdateSubresource: the 1D texture's Usage = " + std::to_string(t.desc.Usage) + " (only USAGE_DEFAULT)");
    if (HRESULT hr = checkSub("UpdateSubresource", "DstSubresource", t, sub); FAILED(hr)) return hr;
    const int width = t.levelWidth(levelOf(t, int(sub)));
    if (box)
        if (HRESULT hr = checkRowBox("UpdateSubresource: pDstBox", *box, width); FAILED(hr)) return hr;
    const int x = box ? int(box->left) : 0, count = box ? int(box->right - box->left) : width;
    writeLine(t, int(sub), x, static_cast<const std::uint8_t*>(data), count);
    return succeed();
}

HRESULT copyLines(LineTexture& d, LineTexture& s) {
    if (d.desc.Width != s.desc.Width || d.desc.ArraySize != s.desc.ArraySize || d.desc.Format != s.desc.Format || d.levels != s.levels)
        return fail(E_INVALIDARG, "CopyResource: the 1D textures differ in Width, ArraySize, Format or MipLevels");
    if (d.texels && s.texels) {
        core::copyTexture(*d.texels, *s.texels);  // on the GPU, every level and slice
        return succeed();
    }
    for (int sub = 0; sub < s.subresources(); ++sub) {
        const std::vector<std::uint8_t> row = readLine(s, sub);
        writeLine(d, sub, 0, row.data(), s.levelWidth(levelOf(s, sub)));
    }
    return succeed();
}

HRESULT copyLineRegion(LineTexture& d, UINT dsub, UINT x, LineTexture& s, UINT ssub, const D3D11_BOX* box) {
    const char* call = "CopySubresourceRegion";
    if (d.desc.Format != s.desc.Format)
        return fail(E_INVALIDARG, std::string(call) + ": the 1D textures' formats differ (" + formatName(d.desc.Format) + ", " + formatName(s.desc.Format) + ")");
    if (HRESULT hr = checkSub(call, "DstSubresource", d, dsub); FAILED(hr)) return hr;
    if (HRESULT hr = checkSub(call, "SrcSubresource", s, ssub); FAILED(hr)) return hr;
    const int sourceWidth = s.levelWidth(levelOf(s, int(ssub))), destinationWidth = d.levelWidth(levelOf(d, int(dsub)));
    if (box)
        if (HRESULT hr = checkRowBox(std::string(call) + ": pSrcBox", *box, sourceWidth); FAILED(hr)) return hr;
    const int left = box ? int(box->left) : 0, count = box ? int(box->right - box->left) : sourceWidth;
    if (x > UINT(destinationWidth) || count > destinationWidth - int(x))
        return fail(E_INVALIDARG, std::string(call) + ": " + std::to_string(count) + " texels at DstX = " + std::to_string(x) + " overrun the destination's " +
                                      std::to_string(destinationWidth) + "-texel level");
    const std::vector<std::uint8_t> row = readLine(s, int(ssub));
    writeLine(d, int(dsub), int(x), row.data() + std::size_t(left) * std::size_t(bytesPerPixel(s.format)), count);
    return succeed();
}

}  // namespace fxport::d3d11
