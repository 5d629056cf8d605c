// Depth/stencil buffers made when a draw first needs them (issue 16). XNA games give render targets
// a DepthFormat (and keep the back buffer's default Depth24Stencil8) that nothing draws into with a
// depth or stencil test: light maps, post-processing targets, 2D games. With
// DeviceOptimizations::LazyDepthStorage a target's buffer is made at the first draw into it that
// tests depth or stencil (XNA: the first bound target's buffer serves all of an MRT binding). Until
// then no draw has read or written it, so only the last whole-target clear of each channel can be
// seen: it waits on the target and runs on the new buffer first. A clear of part of it makes the
// buffer at once. The pixels are those of making every buffer with its target (tests render both).
// This file is the pass (FXPORT_PASS_LAZY_DEPTH); the buffers themselves are device/depth_buffers.cpp's.
#include "device/device_impl.h"

namespace fxport {

namespace {

constexpr unsigned kDepth = unsigned(ClearOptions::DepthBuffer);
constexpr unsigned kStencil = unsigned(ClearOptions::Stencil);
constexpr unsigned kDepthStencil = kDepth | kStencil;

long channels(unsigned bits) { return long((bits & kDepth) != 0) + long((bits & kStencil) != 0); }

}  // namespace

void GraphicsDevice::Impl::makeDepthStorageFor(const fxport::DepthStencilState& state) {
    // D3D (and GL) write depth only where the depth test is on, so a draw without either test
    // neither reads nor writes the buffer.
    if (!state.DepthBufferEnable && !state.StencilEnable) return;
    DepthStorage* storage = boundDepthStorage();
    if (!storage || storage->renderbuffer != 0) return;
    if (depthTestIsMoot(state)) return;
    makeDepthStorage(*storage);
}

unsigned GraphicsDevice::Impl::holdDepthClear(const Rectangle& rect, unsigned options, float depth, int stencil) {
    const unsigned bits = options & kDepthStencil;
    if (bits == 0) return options;
    DepthStorage* storage = boundDepthStorage();
    if (!storage || storage->renderbuffer != 0) return options;
    const bool wholeTarget = rect.X <= 0 && rect.Y <= 0 && rect.X + rect.Width >= targetWidth &&
                             rect.Y + rect.Height >= targetHeight;
    if (!wholeTarget) {
        // Pixels outside the rectangle keep what the waiting clear left: the buffer is needed now.
        makeDepthStorage(*storage);
        return options;
    }
    clearStats.replaced += channels(storage->waitingClear & bits);
    storage->waitingClear |= bits;
    if (bits & kDepth) storage->clearDepth = depth;
    if (bits & kStencil) storage->clearStencil = stencil;
    return options & ~bits;
}

void GraphicsDevice::Impl::discardWaitingDepthClear(unsigned options, long& counter) {
    DepthStorage* storage = boundDepthStorage();
    if (!storage) return;
    const unsigned dropped = storage->waitingClear & options;
    counter += channels(dropped);
    storage->waitingClear &= ~dropped;
}

void GraphicsDevice::Impl::leaveDiscardedDepth() {
    if (!lazyDepthStorage) return;
    DepthStorage* storage = boundDepthStorage();
    if (!storage) return;
    // XNA clears a DiscardContents target's depth and stencil when it is bound again, and nothing
    // can read them while it is not bound: a clear still waiting is never seen, and GL may drop
    // the buffer's contents (a tiled GPU then does not write them back to memory).
    discardWaitingDepthClear(kDepthStencil, clearStats.dropped);
    if (storage->renderbuffer == 0) return;
    if (boundFramebuffer == 0) bindTargets();
    backend->invalidateFramebuffer(0, true, hasStencil(storage->format));  // boundFramebuffer
    ++depthStats.invalidated;
}

}  // namespace fxport
