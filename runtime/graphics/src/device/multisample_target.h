// INTERNAL, GL-free: a multisampled render target for a front end other than XNA's (D3D11's
// SampleDesc.Count > 1). It is bound and drawn into as any RenderTarget2D; a shader reads it sample
// by sample (Texture2DMS); its texels reach the CPU only through resolveInto. XNA's own
// preferredMultiSampleCount is not honoured (RenderTarget2D), so nothing of XNA's changes.
// MultisampleArray is the same as layers of one array (D3D11's Texture2DMSArray).
#pragma once

#include "fxport/graphics/render_target.h"
#include "fxport/graphics/texture_2d_array.h"

namespace fxport::core {

class MultisampleTarget final : public RenderTarget2D {
public:
    // Throws ArgumentError when the driver cannot make `samples` samples of `format` (it may give
    // more for a count it lacks: that too is refused, since a shader would see another count).
    MultisampleTarget(GraphicsDevice& device, int width, int height, SurfaceFormat format, int samples);
    // D3D's ResolveSubresource: each pixel's samples averaged into level 0 of `destination`, a
    // single-sample texture of the same size and format.
    void resolveInto(Texture2D& destination) const;
};

// Layers of multisampled texels, one level. Its views (Texture2DArray's view constructor, and the
// Texture2D and RenderTarget2D over layers) are multisampled too: a TEXTURE2DMSARRAY
// shader-resource view, a render-target view of some layers.
class MultisampleArray final : public Texture2DArray {
public:
    // Throws ArgumentError as MultisampleTarget does.
    MultisampleArray(GraphicsDevice& device, int width, int height, int layers, SurfaceFormat format, int samples);
    // D3D's ResolveSubresource of one layer: its samples averaged into level 0 of `destination`, a
    // single-sample texture of the same size and format, or into one layer and level of an array.
    void resolveInto(int layer, Texture2D& destination);
    void resolveInto(int layer, Texture2DArray& destination, int destinationLayer, int destinationLevel);

private:
    void resolveLayer(int layer, const Texture& destination, int destinationLayer, int destinationLevel, int width, int height);
};

}  // namespace fxport::core
