// Multisampled 2D textures (SampleDesc.Count > 1): the description checks, and ResolveSubresource.
// fxport's are render targets (a shader may also read them, Texture2DMS, through a TEXTURE2DMS
// view) of one level and one slice, with the standard sample pattern: GL's fixed sample
// locations. Their texels reach the CPU as D3D code reads them: resolved into a single-sample
// texture, then copied to a staging one.
#include "context.h"
#include "d3d11_impl.h"
#include "device/multisample_target.h"
#include "guarded.h"

namespace fxport::d3d11 {

HRESULT checkMultisampleDesc(const D3D11_TEXTURE2D_DESC& d, bool hasData) {
    const std::string at = "CreateTexture2D: D3D11_TEXTURE2D_DESC.";
    const UINT count = d.SampleDesc.Count;
    if ((count & (count - 1)) != 0 || count > 32)
        return fail(E_INVALIDARG, at + "SampleDesc.Count = " + std::to_string(count) + " (1, 2, 4, 8, 16 or 32)");
    if (d.SampleDesc.Quality != 0 && d.SampleDesc.Quality != 0xffffffffu)
        return fail(E_INVALIDARG, at + "SampleDesc.Quality = " + std::to_string(d.SampleDesc.Quality) +
                                      " (fxport has quality level 0 and D3D11_STANDARD_MULTISAMPLE_PATTERN)");
    if (d.MipLevels != 1) return fail(E_INVALIDARG, at + "MipLevels = " + std::to_string(d.MipLevels) + " for a multisampled texture (must be 1)");
    if (hasData) return fail(E_INVALIDARG, at + "SampleDesc.Count = " + std::to_string(count) + " with pInitialData (a multisampled texture starts undefined)");
    if (d.Usage != D3D11_USAGE_DEFAULT)
        return fail(E_INVALIDARG, at + "Usage = " + std::to_string(d.Usage) + " for a multisampled texture (must be USAGE_DEFAULT)");
    if (d.BindFlags & D3D11_BIND_UNORDERED_ACCESS)
        return fail(E_INVALIDARG, at + "BindFlags = " + std::to_string(d.BindFlags) + ": a multisampled texture has no unordered-access views");
    if (d.MiscFlags) return fail(E_INVALIDARG, at + "MiscFlags = " + std::to_string(d.MiscFlags) + " for a multisampled texture (must be 0)");
    if (d.ArraySize != 1)
        return fail(E_NOTIMPL, at + "ArraySize = " + std::to_string(d.ArraySize) + " with SampleDesc.Count = " + std::to_string(count) +
                                   ": multisampled texture arrays are not supported yet");
    // Colour targets (read by Texture2DMS too), or depth-stencil buffers drawn beside them.
    const bool colour = (d.BindFlags & D3D11_BIND_RENDER_TARGET) && !(d.BindFlags & D3D11_BIND_DEPTH_STENCIL);
    if (!colour && d.BindFlags != D3D11_BIND_DEPTH_STENCIL)
        return fail(E_NOTIMPL, at + "BindFlags = " + std::to_string(d.BindFlags) + " with SampleDesc.Count = " + std::to_string(count) +
                                   ": fxport's multisampled textures are colour render targets (RENDER_TARGET, and SHADER_RESOURCE) or "
                                   "depth-stencil buffers (DEPTH_STENCIL alone: a shader does not read multisampled depth yet)");
    return S_OK;
}

void Context::ResolveSubresource(ID3D11Resource* pDst, UINT DstSubresource, ID3D11Resource* pSrc, UINT SrcSubresource, DXGI_FORMAT Format) {
    const char* call = "ResolveSubresource";
    auto *dst = own<Texture>(pDst, device_), *src = own<Texture>(pSrc, device_);
    if (!dst || !src) return note("ResolveSubresource: the resources are not two 2D textures of this device");
    auto* samples = dynamic_cast<core::MultisampleTarget*>(src->colour.get());
    if (!samples) return note("ResolveSubresource: the source was not made with SampleDesc.Count > 1");
    if (dst->desc.SampleDesc.Count != 1 || !dst->colour || dst->cube)
        return note("ResolveSubresource: the destination is not a single-sample 2D texture of USAGE_DEFAULT");
    if (DstSubresource != 0 || SrcSubresource != 0)
        return note("ResolveSubresource: DstSubresource = " + std::to_string(DstSubresource) + ", SrcSubresource = " + std::to_string(SrcSubresource) +
                    ": fxport resolves subresource 0 into subresource 0");
    if (Format != src->desc.Format || Format != dst->desc.Format)
        return note(std::string("ResolveSubresource: Format = ") + formatName(Format) + " for a " + formatName(src->desc.Format) + " source and a " +
                    formatName(dst->desc.Format) + " destination (fxport resolves between textures of that one format)");
    guarded(call, [&] {
        samples->resolveInto(*dst->colour);
        return succeed();
    });
}

}  // namespace fxport::d3d11
