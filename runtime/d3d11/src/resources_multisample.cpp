// Multisampled 2D textures (SampleDesc.Count > 1): the description checks, and ResolveSubresource.
// fxport's are render targets (a shader may also read them, Texture2DMS, through a TEXTURE2DMS
// view) of one level, with the standard sample pattern: GL's fixed sample locations; arrays of
// them (Texture2DMSArray) are made in resources_array.cpp. Their texels reach the CPU as D3D code
// reads them: resolved (a slice at a time) into a single-sample texture, then copied to a staging one.
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
    if (d.ArraySize != 1 && d.BindFlags != (D3D11_BIND_RENDER_TARGET | D3D11_BIND_SHADER_RESOURCE) && d.BindFlags != D3D11_BIND_RENDER_TARGET)
        return fail(E_NOTIMPL, at + "BindFlags = " + std::to_string(d.BindFlags) + " with ArraySize = " + std::to_string(d.ArraySize) + " and SampleDesc.Count = " +
                                   std::to_string(count) + ": fxport's multisampled arrays are colour render targets (RENDER_TARGET, and SHADER_RESOURCE; "
                                   "no multisampled depth arrays yet)");
    // Colour targets (read by Texture2DMS too), or depth-stencil buffers drawn beside them.
    const bool colour = (d.BindFlags & D3D11_BIND_RENDER_TARGET) && !(d.BindFlags & D3D11_BIND_DEPTH_STENCIL);
    if (!colour && d.BindFlags != D3D11_BIND_DEPTH_STENCIL)
        return fail(E_NOTIMPL, at + "BindFlags = " + std::to_string(d.BindFlags) + " with SampleDesc.Count = " + std::to_string(count) +
                                   ": fxport's multisampled textures are colour render targets (RENDER_TARGET, and SHADER_RESOURCE) or "
                                   "depth-stencil buffers (DEPTH_STENCIL alone: a shader does not read multisampled depth yet)");
    return S_OK;
}

// A multisampled texture has one level, so its subresource is its slice; the destination's is
// D3D's level + slice * MipLevels of a single-sample texture or array of the source's size there.
void Context::ResolveSubresource(ID3D11Resource* pDst, UINT DstSubresource, ID3D11Resource* pSrc, UINT SrcSubresource, DXGI_FORMAT Format) {
    const char* call = "ResolveSubresource";
    auto *dst = own<Texture>(pDst, device_), *src = own<Texture>(pSrc, device_);
    if (!dst || !src) return note("ResolveSubresource: the resources are not two 2D textures of this device");
    auto* samples = dynamic_cast<core::MultisampleTarget*>(src->colour.get());
    auto* layers = dynamic_cast<core::MultisampleArray*>(src->array.get());
    if (!samples && !layers) return note("ResolveSubresource: the source was not made with SampleDesc.Count > 1");
    if (dst->desc.SampleDesc.Count != 1 || !(dst->colour || dst->array) || dst->cube || dst->desc.Usage != D3D11_USAGE_DEFAULT)
        return note("ResolveSubresource: the destination is not a single-sample 2D texture or array of USAGE_DEFAULT");
    if (SrcSubresource >= UINT(src->slices()))
        return note("ResolveSubresource: SrcSubresource = " + std::to_string(SrcSubresource) + " (the source has " + std::to_string(src->slices()) +
                    " slices of one level)");
    Subresource at;
    if (!splitSubresource(*dst, DstSubresource, at))
        return note("ResolveSubresource: DstSubresource = " + std::to_string(DstSubresource) + " (the destination has " +
                    std::to_string(dst->subresources()) + ")");
    if (dst->levelWidth(at.level) != int(src->desc.Width) || dst->levelHeight(at.level) != int(src->desc.Height))
        return note("ResolveSubresource: DstSubresource = " + std::to_string(DstSubresource) + " is " + std::to_string(dst->levelWidth(at.level)) + "x" +
                    std::to_string(dst->levelHeight(at.level)) + ", the source " + std::to_string(src->desc.Width) + "x" + std::to_string(src->desc.Height));
    if (Format != src->desc.Format || Format != dst->desc.Format)
        return note(std::string("ResolveSubresource: Format = ") + formatName(Format) + " for a " + formatName(src->desc.Format) + " source and a " +
                    formatName(dst->desc.Format) + " destination (fxport resolves between textures of that one format)");
    if (samples && dst->array)
        return note("ResolveSubresource: a multisampled 2D texture into a slice of an array: not yet (resolve into a 2D texture)");
    guarded(call, [&] {
        if (layers && dst->array) layers->resolveInto(int(SrcSubresource), *dst->array, at.slice, at.level);
        else if (layers) layers->resolveInto(int(SrcSubresource), *dst->colour);
        else samples->resolveInto(*dst->colour);
        return succeed();
    });
}

}  // namespace fxport::d3d11
