// INTERNAL, GL-free: a multisampled render target for a front end other than XNA's (D3D11's
// SampleDesc.Count > 1). It is bound and drawn into as any RenderTarget2D; a shader reads it sample
// by sample (Texture2DMS); its texels reach the CPU only through resolveInto. XNA's own
// preferredMultiSampleCount is not honoured (RenderTarget2D), so nothing of XNA's changes.
#pragma once

#include "fxport/graphics/render_target.h"

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

}  // namespace fxport::core
