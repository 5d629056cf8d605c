// Clears that wait until something needs them (issue 16): XNA 4 clears a DiscardContents target
// when it is bound, and ports clear it again right after; D3D drivers fold such clears, GL ones
// execute both. The device records a clear of the whole target per channel (colour, depth,
// stencil) and sends it when a draw or a read-back needs that channel, so a clear replaced by the
// next one, and a depth/stencil clear of a target nothing draws into with depth, cost nothing. The
// pixels are the same as executing every clear at once (DeviceOptimizations::DeferClears=false
// does that; tests compare the two). A depth/stencil buffer that no draw has needed yet does not
// exist (LazyDepthStorage): a clear of it waits on its target instead (depth_storage.cpp).
// This file is the pass (FXPORT_PASS_PENDING_CLEARS): recording a clear, and the two folds that
// know it (a covering sprite drops it, a blend onto its zero colour is a write). Executing what is
// pending when something needs it is the core's (device/clears.cpp): without the pass nothing is
// ever pending, as with DeferClears and DropCoveredClears off.
#include <algorithm>
#include <vector>

#include "device/device_impl.h"
#include "fxport/xlate/compiled_effect.h"
#include "fxport/graphics/render_target.h"

namespace fxport {

namespace {
constexpr unsigned kColor = unsigned(ClearOptions::Target);
constexpr unsigned kDepth = unsigned(ClearOptions::DepthBuffer);
constexpr unsigned kStencil = unsigned(ClearOptions::Stencil);
long channels(unsigned bits) { return long((bits & kColor) != 0) + long((bits & kDepth) != 0) + long((bits & kStencil) != 0); }
}  // namespace

void GraphicsDevice::Impl::recordClear(unsigned options, const Vector4& color, float depth, int stencil) {
    clearStats.replaced += channels(pendingClear.options & options);
    pendingClear.options |= options;
    if (options & kColor) pendingClear.color = color;
    if (options & kDepth) pendingClear.depth = depth;
    if (options & kStencil) pendingClear.stencil = stencil;
}

// The sprite's rectangle covers the viewport (SpriteBatch checked: an unrotated, unflipped sprite
// through SpriteBatch's own vertex shader and XNA's matrix, no transform, corners at or beyond the
// viewport's; the -0.5 of the matrix and the +0.5 - 1/256 of the D3D9 pixel-centre emulation leave
// its edges 1/256 pixel up-left of the viewport's, so every pixel centre is strictly inside).
// Every pixel is then written unless something here stops it: blending, a write mask, a depth or
// stencil test, the scissor, culling of a clockwise sprite, a viewport smaller than the target,
// several targets (a sprite effect writes one), or a pixel shader that can discard. Otherwise the
// clear's colour is never seen and is not sent.
void GraphicsDevice::Impl::dropColorClearUnderCoveringSprite(const ShaderProgram* spriteVertexShader) {
    if (!dropCoveredClears || !(pendingClear.options & kColor)) return;
    if (boundFramebuffer == 0) bindTargets();  // targetWidth/Height are the bound targets'
    const fxport::BlendState& blend = device.BlendState;
    const fxport::DepthStencilState& depth = device.DepthStencilState;
    const fxport::RasterizerState& raster = device.RasterizerState;
    const fxport::Viewport& viewport = device.Viewport;
    const ShaderProgram* vertex = shaders[0];
    const ShaderProgram* pixel = shaders[1];
    const bool writesAll = blend.ColorWriteChannels == fxport::ColorWriteChannels::All;
    const bool ownVertexShader = vertex && vertex == spriteVertexShader && vertex->shader &&
                                 vertex->shader->needsD3D9PixelOffset;
    const bool pixelMayDiscard = !pixel || !pixel->shader || emulation.alphaTest || emulation.fixedFunction || pixel->mayDiscard;
    if (blend.blendingEnabled() || !writesAll || depth.DepthBufferEnable || depth.StencilEnable ||
        raster.ScissorTestEnable || raster.CullMode == fxport::CullMode::CullClockwiseFace ||
        raster.FillMode != fxport::FillMode::Solid || blend.MultiSampleMask != -1 || targets.size() > 1 ||
        !ownVertexShader || pixelMayDiscard || viewport.X != 0 || viewport.Y != 0 ||
        viewport.Width != targetWidth || viewport.Height != targetHeight)
        return;
    pendingClear.options &= ~kColor;
    ++clearStats.covered;
}

// The pending colour clear is zero in every channel and is executed for this draw, so every
// pixel the draw blends onto holds 0. On an unsigned-normalized target the source is clamped to
// [0, 1] and every factor is finite, so with source factor One: Add gives src + 0 * f = src,
// Subtract src - 0 * f = src, Max max(src, 0) = src -- the same bits a write gives, whether the
// blender works in fixed point or in float. (Min and ReverseSubtract give 0; float targets could
// meet 0 * Inf.) A write draws no blend and may run as a compute pass.
bool GraphicsDevice::Impl::blendOverZeroClearIsWrite() const {
    if (!dropCoveredClears || !(pendingClear.options & kColor) || !(pendingClear.color == Vector4(0, 0, 0, 0))) return false;
    const fxport::BlendState& blend = device.BlendState;
    if (!blend.blendingEnabled()) return false;
    auto writes = [](fxport::Blend source, fxport::BlendFunction function) {
        return source == fxport::Blend::One && (function == fxport::BlendFunction::Add ||
                                                function == fxport::BlendFunction::Subtract || function == fxport::BlendFunction::Max);
    };
    if (!writes(blend.ColorSourceBlend, blend.ColorBlendFunction) || !writes(blend.AlphaSourceBlend, blend.AlphaBlendFunction))
        return false;
    auto unsignedNormalized = [](SurfaceFormat f) {
        return f == SurfaceFormat::Color || f == SurfaceFormat::Bgr565 || f == SurfaceFormat::Bgra5551 ||
               f == SurfaceFormat::Bgra4444 || f == SurfaceFormat::Rgba1010102 || f == SurfaceFormat::Rg32 ||
               f == SurfaceFormat::Rgba64;
    };
    if (targets.empty()) return unsignedNormalized(backBuffer->Format());
    return std::all_of(targets.begin(), targets.end(),
                       [&](const RenderTargetBinding& b) { return unsignedNormalized(b.RenderTarget->Format()); });
}

}  // namespace fxport
