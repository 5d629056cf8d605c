// Depth/stencil buffers of render targets (and of D3D11's depth-stencil views): made, counted,
// released, found for the bound targets. Without lazy depth storage (device/passes/depth_storage.cpp,
// FXPORT_PASS_LAZY_DEPTH; DeviceOptimizations::LazyDepthStorage) each is made with its target.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "device/device_impl.h"
#include "fxport/graphics/render_target.h"

namespace fxport {

namespace {

constexpr unsigned kDepth = unsigned(ClearOptions::DepthBuffer);
constexpr unsigned kStencil = unsigned(ClearOptions::Stencil);

long channels(unsigned bits) { return long((bits & kDepth) != 0) + long((bits & kStencil) != 0); }

// As drivers store them: 24-bit depth takes 4 bytes with or without stencil.
std::int64_t bytesOf(const DepthStorage& storage) {
    int perPixel = storage.format == DepthFormat::None ? 0 : storage.format == DepthFormat::Depth16 ? 2 : 4;
    if (storage.format == DepthFormat::Depth32FStencil8) perPixel = 8;
    return std::int64_t(storage.width) * std::int64_t(storage.height) * perPixel * std::max(storage.samples, 1);
}

Texture* firstBound(const std::vector<RenderTargetBinding>& targets, RenderTarget2D* backBuffer) {
    return targets.empty() ? backBuffer : targets[0].RenderTarget;
}

}  // namespace

DepthStorageStatistics GraphicsDevice::depthStorageStatistics() const { return impl_->depthStats; }

void GraphicsDevice::Impl::adoptDepthStorage(DepthStorage& storage) {
    if (storage.format == DepthFormat::None) return;
    ++depthStats.requested;
    depthStats.requestedBytes += bytesOf(storage);
    if (!lazyDepthStorage) makeDepthStorage(storage);
}

void GraphicsDevice::Impl::releaseDepthStorage(DepthStorage& storage) {
    if (!storage.isTexture) deleteRenderbuffer(storage.renderbuffer);  // a depth texture is its texture's
    storage.renderbuffer = 0;
    storage.waitingClear = 0;
}

DepthStorage* GraphicsDevice::Impl::boundDepthStorage() {
    if (depthOverride) return depthOverride->format == DepthFormat::None ? nullptr : depthOverride;
    Texture* first = firstBound(targets, backBuffer.get());
    if (!first) return nullptr;  // the back buffer while it is being made
    DepthStorage& storage = first->kind() == Texture::Kind::TextureCube
                                ? static_cast<RenderTargetCube*>(first)->depthStorage()
                                : static_cast<RenderTarget2D*>(first)->depthStorage();
    return storage.format == DepthFormat::None ? nullptr : &storage;
}

bool GraphicsDevice::Impl::depthTestIsMoot(const fxport::DepthStencilState& state) {
    if (state.StencilEnable || state.DepthBufferWriteEnable) return false;
    const DepthStorage* storage = boundDepthStorage();
    return storage && depthTestPassesAll(state, *storage);
}

// A buffer not made yet holds one value, that of the last clear of its depth (still pending on the
// binding, or waiting on the target). The buffers are fixed-point, so GL clamps every fragment's
// depth (and a shader's SV_Depth) to [0, 1] before the test: against 1, LessEqual cannot fail (the
// tutorials' DepthRead light passes), against 0, GreaterEqual cannot, Always never does. Such a
// test that writes nothing draws what no test draws.
bool GraphicsDevice::Impl::depthTestPassesAll(const fxport::DepthStencilState& state, const DepthStorage& storage) const {
    float value = 0;
    if (pendingClear.options & kDepth) value = pendingClear.depth;
    else if (storage.waitingClear & kDepth) value = storage.clearDepth;
    else return state.DepthBufferFunction == CompareFunction::Always;  // never cleared: contents unknown
    switch (state.DepthBufferFunction) {
    case CompareFunction::Always: return true;
    case CompareFunction::LessEqual: return value >= 1;
    case CompareFunction::GreaterEqual: return value <= 0;
    default: return false;
    }
}

void GraphicsDevice::Impl::makeDepthStorage(DepthStorage& storage) {
    storage.renderbuffer = createRenderbuffer();
    backend->allocateRenderbuffer(storage.renderbuffer, storage.format, storage.width, storage.height, storage.samples);
    ++depthStats.allocated;
    depthStats.allocatedBytes += bytesOf(storage);
    if (&storage != boundDepthStorage()) return;  // made with its target: nothing is bound or waits
    // The target's framebuffers have no depth attachment: make them again.
    dropFramebuffersUsing(firstBound(targets, backBuffer.get())->backendObject());
    bindTargets();
    // A clear of the channel still pending on the binding came after the waiting one and replaces it.
    const unsigned replaced = storage.waitingClear & pendingClear.options;
    clearStats.replaced += channels(replaced);
    const unsigned waiting = storage.waitingClear & ~replaced;
    storage.waitingClear = 0;
    executeClear(Rectangle(0, 0, targetWidth, targetHeight), waiting, Vector4(), storage.clearDepth,
                 storage.clearStencil);
}

}  // namespace fxport
