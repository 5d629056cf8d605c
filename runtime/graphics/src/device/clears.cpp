// Clears of the bound targets: executed through the backend, the pending one (recorded by the
// pending-clears pass, device/passes/pending_clear.cpp) executed for what needs it -- a draw, a
// read-back, leaving the targets -- and DiscardContents. Without the pass nothing is pending and
// every clear is executed as it comes (GraphicsDevice::Clear).
#include <algorithm>
#include <vector>

#include "device/device_impl.h"
#include "device/optimization_passes.h"
#include "fxport/graphics/render_target.h"

namespace fxport {

namespace {
constexpr unsigned kColor = unsigned(ClearOptions::Target);
constexpr unsigned kDepth = unsigned(ClearOptions::DepthBuffer);
constexpr unsigned kStencil = unsigned(ClearOptions::Stencil);
long channels(unsigned bits) { return long((bits & kColor) != 0) + long((bits & kDepth) != 0) + long((bits & kStencil) != 0); }
}  // namespace

void GraphicsDevice::Impl::executeClear(const Rectangle& rect, unsigned options, const Vector4& color, float depth,
                                        int stencil) {
    if (options == 0) return;
    if (boundFramebuffer == 0) bindTargets();
    if constexpr (kLazyDepthBuilt) options = holdDepthClear(rect, options, depth, stencil);  // a depth buffer not made yet (depth_storage.cpp)
    if (options == 0) return;
    noteWrittenTargets((options & kColor) != 0, (options & (kDepth | kStencil)) != 0, rect, true);
    clearStats.executed += channels(options);
    const int colorTargets = int(std::max<std::size_t>(1, targets.size()));
    backend->clearFramebuffer(boundFramebuffer, rect, colorTargets, (options & kColor) != 0, color, (options & kDepth) != 0,
                              (options & kStencil) != 0, depth, stencil);
    // Put back what the shadow says the backend has.
    shadow.reapply();
}

void GraphicsDevice::Impl::resolvePendingClear(unsigned options) {
    unsigned now = pendingClear.options & options;
    if (now == 0) return;
    pendingClear.options &= ~now;
    executeClear(Rectangle(0, 0, targetWidth, targetHeight), now, pendingClear.color, pendingClear.depth,
                 pendingClear.stencil);
}

void GraphicsDevice::Impl::resolvePendingClearBeforeDraw(const fxport::DepthStencilState& state) {
    if (pendingClear.options == 0) return;
    // A depth test reads the depth buffer, a stencil test the stencil buffer; writes need a test on
    // (D3D writes depth only where the depth test is enabled). D24S8 clears both in one call, so a
    // draw that needs either resolves both.
    unsigned needed = kColor;
    if (state.DepthBufferEnable || state.StencilEnable) needed |= kDepth | kStencil;
    resolvePendingClear(needed);
}

void GraphicsDevice::Impl::resolvePendingClearBeforeRead(const Texture* texture) {
    storageBarrier();  // a read-back after a shader wrote the texture as an image (storage_bindings.cpp)
    if (!(pendingClear.options & kColor)) return;
    bool bound = targets.empty() ? texture == backBuffer.get()
                                 : std::any_of(targets.begin(), targets.end(),
                                               [&](const RenderTargetBinding& b) { return b.RenderTarget == texture; });
    if (bound) resolvePendingClear(kColor);
}

void GraphicsDevice::DiscardContents(ClearOptions options) { impl_->discardContents(unsigned(options)); }

void GraphicsDevice::Impl::discardContents(unsigned options) {
    if (!honourDiscards) return;
    const unsigned dropped = pendingClear.options & options;
    clearStats.discarded += channels(dropped);
    pendingClear.options &= ~dropped;
    if constexpr (kLazyDepthBuilt) discardWaitingDepthClear(options, clearStats.discarded);
    if (boundFramebuffer == 0) bindTargets();
    const int colorTargets = (options & kColor) ? int(std::max<std::size_t>(1, targets.size())) : 0;
    backend->invalidateFramebuffer(colorTargets, (options & kDepth) != 0, (options & kStencil) != 0);  // boundFramebuffer
}

void GraphicsDevice::Impl::leaveBoundTargets() {
    resolvePendingClear(kColor);  // a render target is read as a texture after it is unbound
    if (boundUsage() != fxport::RenderTargetUsage::DiscardContents) {
        resolvePendingClear(~0u);
        return;
    }
    // Nothing tested this depth/stencil buffer since the clear, nothing can read it, and binding
    // the target again clears it again.
    clearStats.dropped += channels(pendingClear.options);
    pendingClear.options = 0;
    if constexpr (kLazyDepthBuilt) leaveDiscardedDepth();
}

}  // namespace fxport
