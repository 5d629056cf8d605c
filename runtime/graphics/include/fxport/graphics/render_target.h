// Render targets: a texture plus (optionally) a depth/stencil buffer, as XNA 4 makes them.
// Bound with GraphicsDevice::SetRenderTarget(s); sampled like any texture once unbound.
#pragma once

#include <cstdint>
#include <vector>

#include "fxport/graphics/texture.h"
#include "fxport/graphics/texture_2d_array.h"

namespace fxport {

// fxport, for the device (runtime/graphics/src/depth_storage.cpp), not for games: a target's
// depth/stencil buffer. With DeviceOptimizations::LazyDepthStorage it is made at the first draw
// into the target that tests depth or stencil; until then the target's last whole-target clear of
// each channel waits here, and runs on the buffer when it is made.
struct DepthStorage {
    DepthFormat format = DepthFormat::None;  // what the target was made with (reported as made)
    int width = 0, height = 0;
    int samples = 0;  // > 0: a multisampled buffer (a D3D11 depth target beside a multisampled colour one)
    std::uint32_t renderbuffer = 0;  // the GL buffer; 0 while not made (or format None)
    // The buffer is a depth texture a shader also samples (a D3D11 shadow map: the texture owns it,
    // made at once) rather than a renderbuffer of the device's own.
    bool isTexture = false;
    unsigned waitingClear = 0;       // ClearOptions::DepthBuffer / Stencil bits to run when it is made
    float clearDepth = 1;
    int clearStencil = 0;
};

class RenderTarget2D : public Texture2D {
public:
    RenderTarget2D(fxport::GraphicsDevice& device, int width, int height, bool mipMap = false,
                   SurfaceFormat preferredFormat = SurfaceFormat::Color,
                   DepthFormat preferredDepthFormat = DepthFormat::None, int preferredMultiSampleCount = 0,
                   fxport::RenderTargetUsage usage = fxport::RenderTargetUsage::DiscardContents);
    // fxport: a target over one layer of one level of `array` (D3D11's render-target view of an
    // array slice): draws into it write the array's texels. No depth buffer; `array` must outlive it.
    // `layers` > 1: a layered target over that many layers from `layer` (a view of several slices):
    // each primitive goes to the layer its SV_RenderTargetArrayIndex names (the first when none is
    // written, as D3D), a clear clears every layer; its texels are read through `array`.
    RenderTarget2D(Texture2DArray& array, int layer, int level, int layers = 1);
    // fxport: the same over rows of a 1D texture (D3D11's 1D render-target view): one texel high,
    // layered over several layers of a 1D array. `line` must outlive it.
    RenderTarget2D(Texture1D& line, int layer, int level, int layers = 1);
    ~RenderTarget2D() override;

    DepthFormat DepthStencilFormat() const { return depth_.format; }
    fxport::RenderTargetUsage RenderTargetUsage() const { return usage_; }
    // XNA's preferredMultiSampleCount is not honoured (0, as XNA reports no multisampling); the
    // D3D11 front end's multisampled targets (device core's MultisampleTarget) report their count.
    int MultiSampleCount() const { return samples_; }
    bool isRenderTarget() const override { return true; }
    // The depth/stencil buffer's GL name: 0 until a draw needs it (LazyDepthStorage) or for None.
    std::uint32_t depthRenderbuffer() const { return depth_.renderbuffer; }
    DepthStorage& depthStorage() { return depth_; }
    // fxport: level 0 as RGBA floats, top row first, whatever the format (GL's conversion: unorm to
    // [0,1], half to float, absent channels as GL fills them: 0, 0, 1). For checks and references.
    std::vector<Vector4> GetDataAsVector4() const;

protected:
    void releaseGpuObjects() override;

private:
    RenderTarget2D(fxport::GraphicsDevice& device, int width, SurfaceFormat format, std::uint32_t row);  // over a 1D view
    fxport::RenderTargetUsage usage_;
    DepthStorage depth_;
};

class RenderTargetCube : public TextureCube {
public:
    RenderTargetCube(fxport::GraphicsDevice& device, int size, bool mipMap = false,
                     SurfaceFormat preferredFormat = SurfaceFormat::Color,
                     DepthFormat preferredDepthFormat = DepthFormat::None, int preferredMultiSampleCount = 0,
                     fxport::RenderTargetUsage usage = fxport::RenderTargetUsage::DiscardContents);
    ~RenderTargetCube() override;

    DepthFormat DepthStencilFormat() const { return depth_.format; }
    fxport::RenderTargetUsage RenderTargetUsage() const { return usage_; }
    bool isRenderTarget() const override { return true; }
    // The depth/stencil buffer's GL name: 0 until a draw needs it (LazyDepthStorage) or for None.
    std::uint32_t depthRenderbuffer() const { return depth_.renderbuffer; }
    DepthStorage& depthStorage() { return depth_; }
    // fxport: level 0 of one face as RGBA floats (as RenderTarget2D::GetDataAsVector4).
    std::vector<Vector4> GetDataAsVector4(CubeMapFace face) const;

protected:
    void releaseGpuObjects() override;

private:
    fxport::RenderTargetUsage usage_;
    DepthStorage depth_;
};

// One entry of SetRenderTargets: a 2D target, or one face of a cube target.
struct RenderTargetBinding {
    Texture* RenderTarget = nullptr;  // a RenderTarget2D or RenderTargetCube
    fxport::CubeMapFace CubeMapFace = fxport::CubeMapFace::PositiveX;

    RenderTargetBinding() = default;
    RenderTargetBinding(RenderTarget2D* target) : RenderTarget(target) {}
    RenderTargetBinding(RenderTarget2D& target) : RenderTarget(&target) {}
    RenderTargetBinding(RenderTargetCube* target, fxport::CubeMapFace face) : RenderTarget(target), CubeMapFace(face) {}
    RenderTargetBinding(RenderTargetCube& target, fxport::CubeMapFace face) : RenderTarget(&target), CubeMapFace(face) {}
    bool operator==(const RenderTargetBinding&) const = default;
};

}  // namespace fxport
