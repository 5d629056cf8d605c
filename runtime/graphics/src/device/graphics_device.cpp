#include "fxport/graphics/graphics_device.h"

#include <algorithm>
#include <cstring>
#include <iostream>

#include "device/compute_passes.h"
#include "device/device_impl.h"
#include "device/optimization_passes.h"
#include "fxport/graphics/effect.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/gpu_limits.h"
#include "fxport/platform/graphics_context.h"
#include "fxport/xlate/compiled_effect.h"
#include "device/image_io.h"
#include "device/primitive_counts.h"

namespace fxport {

namespace {

std::string slotError(int slot) {
    return "slot " + std::to_string(slot) + " is outside 0.." + std::to_string(kMaxTextureSlots - 1);
}


// What SetRenderTargets needs of a bound target, 2D or cube.
struct TargetInfo {
    int width, height;
    BackendObject depth;
    DepthFormat depthFormat;
    RenderTargetUsage usage;
};
TargetInfo targetInfo(const Texture* t) {
    if (t->kind() == Texture::Kind::TextureCube) {
        auto* c = static_cast<const RenderTargetCube*>(t);
        return {c->Size(), c->Size(), c->depthRenderbuffer(), c->DepthStencilFormat(), c->RenderTargetUsage()};
    }
    auto* r = static_cast<const RenderTarget2D*>(t);
    return {r->Width(), r->Height(), r->depthRenderbuffer(), r->DepthStencilFormat(), r->RenderTargetUsage()};
}

// Live devices, oldest first; the last one made current is what GL calls go to. Never destroyed:
// a device held by a global (D3D11 programs keep theirs in globals) is destroyed after the
// function-local statics made after it, and its destructor still reads this list.
std::vector<GraphicsDevice*>& liveDevices() {
    static auto* devices = new std::vector<GraphicsDevice*>();
    return *devices;
}

platform::Platform choosePlatform(const std::string& name) {
    return name.empty() ? platform::defaultPlatform() : platform::platformFromString(name);
}

}  // namespace

// --- slot collections

TextureSlot& TextureCollection::operator[](int slot) {
    if (slot < 0 || slot >= kMaxTextureSlots) throw ArgumentError("GraphicsDevice.Textures: " + slotError(slot));
    return slots_[std::size_t(slot)];
}
const TextureSlot& TextureCollection::operator[](int slot) const {
    if (slot < 0 || slot >= kMaxTextureSlots) throw ArgumentError("GraphicsDevice.Textures: " + slotError(slot));
    return slots_[std::size_t(slot)];
}

SamplerStateCollection::SamplerStateCollection() { slots_.fill(SamplerState::LinearWrap); }
SamplerState& SamplerStateCollection::operator[](int slot) {
    if (slot < 0 || slot >= kMaxTextureSlots) throw ArgumentError("GraphicsDevice.SamplerStates: " + slotError(slot));
    return slots_[std::size_t(slot)];
}
const SamplerState& SamplerStateCollection::operator[](int slot) const {
    if (slot < 0 || slot >= kMaxTextureSlots) throw ArgumentError("GraphicsDevice.SamplerStates: " + slotError(slot));
    return slots_[std::size_t(slot)];
}

// --- construction

namespace {

// DeviceOptimizations::ComputePasses left unset: compute passes are exact everywhere, faster only
// where fragment output is this GPU's limit. A software rasteriser is never asked (its probe would
// cost every device a measurement; llvmpipe runs them several times slower).
bool computePassesAreFaster(GraphicsDevice& device) {
    return !GpuLimits::softwareRenderer(device.rendererName()) && GpuLimits::ForDevice(device).computePassesFaster();
}

// The back buffer's largest side: GL 4.5's (and D3D11's) guaranteed texture size. Checked before
// the context exists (OSMesa would allocate 100000x100000 pixels and throw std::bad_alloc).
constexpr int kMaxBackBufferSide = 16384;

void checkBackBufferSize(const char* call, int width, int height) {
    if (width <= 0 || height <= 0)
        throw ArgumentError(std::string(call) + ": back buffer size " + std::to_string(width) + "x" + std::to_string(height) + " must be positive");
    if (width > kMaxBackBufferSide || height > kMaxBackBufferSide)
        throw ArgumentError(std::string(call) + ": back buffer size " + std::to_string(width) + "x" + std::to_string(height) +
                            " is larger than " + std::to_string(kMaxBackBufferSide) + "x" + std::to_string(kMaxBackBufferSide) +
                            ", the largest fxport makes");
}

}  // namespace

namespace {

// The backend createDeviceOver hands the constructor it calls (the public constructor has no
// parameter for it: a host never picks one).
thread_local std::unique_ptr<Backend> backendForNextDevice;

}  // namespace

std::unique_ptr<GraphicsDevice> createDeviceOver(std::unique_ptr<Backend> backend, const PresentationParameters& parameters) {
    if (!backend) throw ArgumentError("createDeviceOver: no backend");
    backendForNextDevice = std::move(backend);
    try {
        return std::make_unique<GraphicsDevice>(parameters);
    } catch (...) {
        backendForNextDevice.reset();
        throw;
    }
}

GraphicsDevice::GraphicsDevice(const fxport::PresentationParameters& parameters) : parameters_(parameters) {
    std::unique_ptr<Backend> backend = std::move(backendForNextDevice);
    checkBackBufferSize("GraphicsDevice", parameters_.BackBufferWidth, parameters_.BackBufferHeight);
    if (!backend) {
        platform::ContextDesc desc;
        desc.platform = choosePlatform(parameters_.platform);
        desc.width = parameters_.BackBufferWidth;
        desc.height = parameters_.BackBufferHeight;
        desc.debug = parameters_.debug;
        desc.title = parameters_.windowTitle;
        context_ = platform::GraphicsContext::create(desc);
        backend = createGlBackend();
    }
    impl_ = std::make_unique<Impl>(*this, std::move(backend));
    liveDevices().push_back(this);
    const DeviceOptimizations optimizations = parameters_.Optimizations.withEnvironment();
    impl_->deferClears = kPendingClearsBuilt && optimizations.DeferClears;  // left out of the build: off
    impl_->honourDiscards = optimizations.HonourDiscards;
    impl_->lazyDepthStorage = kLazyDepthBuilt && optimizations.LazyDepthStorage;  // left out of the build: off
    impl_->dropCoveredClears = kPendingClearsBuilt && optimizations.DropCoveredClears;

    // The D3D conventions (docs/DESIGN.md): NDC z in [0,1], and window y from the top row so
    // render targets come out top-row-first.
    Backend& api = *impl_->backend;
    api.adoptD3DConventions();

    impl_->backBuffer = std::make_unique<RenderTarget2D>(*this, parameters_.BackBufferWidth, parameters_.BackBufferHeight,
                                                          false, parameters_.BackBufferFormat,
                                                          parameters_.DepthStencilFormat);
    impl_->backBuffer->Name = "BackBuffer";
    SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    ScissorRectangle = Rectangle(0, 0, parameters_.BackBufferWidth, parameters_.BackBufferHeight);

    // Compute passes are the GL backend's own (gl/passes/) and need its context; unset, they run
    // where this GPU runs them faster. A build without them (FXPORT_PASS_COMPUTE=OFF) has none,
    // as a context without compute.
    if constexpr (kComputePassesBuilt) {
        const bool computePasses =
            context_ && (optimizations.ComputePasses ? *optimizations.ComputePasses : computePassesAreFaster(*this));
        if (computePasses) impl_->computePasses = createComputePasses(*this);
    }
}

void GraphicsDevice::Reset(const fxport::PresentationParameters& parameters) {
    checkBackBufferSize("GraphicsDevice.Reset", parameters.BackBufferWidth, parameters.BackBufferHeight);
    makeCurrent();
    parameters_.BackBufferWidth = parameters.BackBufferWidth;
    parameters_.BackBufferHeight = parameters.BackBufferHeight;
    parameters_.BackBufferFormat = parameters.BackBufferFormat;
    parameters_.DepthStencilFormat = parameters.DepthStencilFormat;
    parameters_.RenderTargetUsage = parameters.RenderTargetUsage;
    std::erase_if(impl_->boundSinceMark,
                  [&](const RenderTargetBinding& b) { return b.RenderTarget == impl_->backBuffer.get(); });
    std::erase_if(impl_->writtenSinceMark,
                  [&](const WrittenTarget& w) { return w.binding.RenderTarget == impl_->backBuffer.get(); });
    impl_->backBuffer.reset();  // its framebuffers go with it
    impl_->backBuffer = std::make_unique<RenderTarget2D>(*this, parameters_.BackBufferWidth, parameters_.BackBufferHeight,
                                                          false, parameters_.BackBufferFormat,
                                                          parameters_.DepthStencilFormat);
    impl_->backBuffer->Name = "BackBuffer";
    SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    ScissorRectangle = Rectangle(0, 0, parameters_.BackBufferWidth, parameters_.BackBufferHeight);
}

GraphicsDevice::~GraphicsDevice() {
    // Resources the program still holds are disposed now (their GL objects die with the context)
    // and cut loose, so their destructors later do not reach a dead device.
    if (context_) context_->makeCurrent();
    impl_->backBuffer.reset();
    std::vector<GraphicsResource*> remaining = impl_->resources;
    for (GraphicsResource* r : remaining) r->Dispose();
    for (GraphicsResource* r : remaining) r->device_ = nullptr;
    impl_->releaseAll();
    impl_.reset();
    context_.reset();
    auto& devices = liveDevices();
    devices.erase(std::remove(devices.begin(), devices.end(), this), devices.end());
    if (!devices.empty()) devices.back()->makeCurrent();
}

void GraphicsDevice::makeCurrent() {
    if (context_) context_->makeCurrent();
    auto& devices = liveDevices();
    devices.erase(std::remove(devices.begin(), devices.end(), this), devices.end());
    devices.push_back(this);
}

GraphicsDevice* GraphicsDevice::current() { return liveDevices().empty() ? nullptr : liveDevices().back(); }

std::string GraphicsDevice::rendererName() const { return context_ ? context_->rendererName() : "no context (a device over a test backend)"; }

int GraphicsDevice::maxTextureSize() const { return impl_->backend->maxTextureSize(); }
bool GraphicsDevice::supportsTextureFormat(SurfaceFormat format) const { return impl_->isSampleable(format); }
bool GraphicsDevice::supportsRenderTargetFormat(SurfaceFormat format) const {
    return impl_->isSampleable(format) && impl_->backend->isColorRenderable(format);
}
int GraphicsDevice::maxSampleCount() const { return impl_->backend->maxSamples(); }
AdapterIdentity GraphicsDevice::adapterIdentity() const { return impl_->backend->adapterIdentity(); }

GpuObjectCounts GraphicsDevice::liveGpuObjects() const { return impl_->live; }

ClearStatistics GraphicsDevice::clearStatistics() const { return impl_->clearStats; }

ComputePassStatistics GraphicsDevice::computePassStatistics() const {
    return impl_->computePasses ? impl_->computePasses->currentStatistics() : ComputePassStatistics{};
}

void GraphicsDevice::finish() { impl_->backend->finish(); }

// --- render targets

void GraphicsDevice::SetRenderTarget(RenderTarget2D* target) {
    if (target == nullptr) SetRenderTargets(std::vector<RenderTargetBinding>{});
    else SetRenderTargets(std::vector<RenderTargetBinding>{RenderTargetBinding(target)});
}

void GraphicsDevice::SetRenderTarget(RenderTargetCube* target, CubeMapFace face) {
    if (target == nullptr) throw ArgumentError("GraphicsDevice.SetRenderTarget: the cube target is null");
    SetRenderTargets(std::vector<RenderTargetBinding>{RenderTargetBinding(target, face)});
}

void GraphicsDevice::SetRenderTargets(const std::vector<RenderTargetBinding>& bindings) {
    if (bindings.size() > std::size_t(kMaxRenderTargets))
        throw ArgumentError("GraphicsDevice.SetRenderTargets: " + std::to_string(bindings.size()) +
                            " targets; at most " + std::to_string(kMaxRenderTargets));
    int width = 0, height = 0;
    for (std::size_t i = 0; i < bindings.size(); ++i) {
        Texture* t = bindings[i].RenderTarget;
        std::string where = "GraphicsDevice.SetRenderTargets: binding " + std::to_string(i);
        if (t == nullptr) throw ArgumentError(where + " is null");
        if (!t->isRenderTarget())
            throw ArgumentError(where + " ('" + t->Name + "') is a texture, not a render target");
        if (t->IsDisposed()) throw InvalidOperation(where + " ('" + t->Name + "') was disposed");
        if (&t->device() != this) throw InvalidOperation(where + " ('" + t->Name + "') was made by another GraphicsDevice");
        for (std::size_t j = 0; j < i; ++j)
            if (bindings[j].RenderTarget == t)
                throw ArgumentError(where + " ('" + t->Name + "') is binding " + std::to_string(j) + " too; bind each target once");
        int w = targetInfo(t).width, h = targetInfo(t).height;
        if (i == 0) {
            width = w;
            height = h;
        } else if (w != width || h != height) {
            throw ArgumentError(where + " is " + std::to_string(w) + "x" + std::to_string(h) + ", binding 0 is " +
                                std::to_string(width) + "x" + std::to_string(height) +
                                ": all render targets must have the same size");
        }
    }
    impl_->leaveBoundTargets();
    std::vector<RenderTargetBinding> previous = impl_->targets;
    impl_->targets = bindings;
    impl_->generateMipsOfUnboundTargets(previous);
    impl_->bindTargets();
    impl_->noteBoundTargets();
    Viewport = fxport::Viewport(0, 0, impl_->targetWidth, impl_->targetHeight);
    // XNA 4 on Windows clears a DiscardContents target (colour to purple, depth and stencil too)
    // whenever it is set, to behave like the Xbox where the contents are lost; code written for it
    // relies on the depth clear (the deferred tutorial never clears its G-buffer depth).
    // PreserveContents keeps them. The back buffer follows PresentationParameters.
    fxport::RenderTargetUsage usage =
        bindings.empty() ? parameters_.RenderTargetUsage : targetInfo(bindings[0].RenderTarget).usage;
    if (usage == fxport::RenderTargetUsage::DiscardContents)
        Clear(ClearOptions::Target | ClearOptions::DepthBuffer | ClearOptions::Stencil, DiscardColor, 1.0f, 0);
}

fxport::RenderTargetUsage GraphicsDevice::Impl::boundUsage() const {
    return targets.empty() ? device.parameters_.RenderTargetUsage : targetInfo(targets[0].RenderTarget).usage;
}

std::vector<RenderTargetBinding> GraphicsDevice::GetRenderTargets() const { return impl_->targets; }

void GraphicsDevice::Impl::noteBoundTargets() {
    if (!trackingBoundTargets) return;
    auto note = [&](const RenderTargetBinding& b) {
        if (std::find(boundSinceMark.begin(), boundSinceMark.end(), b) == boundSinceMark.end()) boundSinceMark.push_back(b);
    };
    if (targets.empty()) note(RenderTargetBinding(backBuffer.get()));
    for (const RenderTargetBinding& b : targets) note(b);
    int bytes = 0;
    if (targets.empty()) bytes = bytesPerPixel(backBuffer->Format());
    for (const RenderTargetBinding& b : targets)
        if (b.RenderTarget) bytes += bytesPerPixel(b.RenderTarget->Format());
    widestColorBytesSinceMark = std::max(widestColorBytesSinceMark, bytes);
}

void GraphicsDevice::markBoundTargets() {
    impl_->trackingBoundTargets = true;
    impl_->boundSinceMark.clear();
    impl_->writtenSinceMark.clear();
    impl_->widestColorBytesSinceMark = 0;
    impl_->blendedSinceMark = false;
    impl_->noteBoundTargets();
}

int GraphicsDevice::colorBytesPerFragmentSinceMark() const { return impl_->widestColorBytesSinceMark; }
bool GraphicsDevice::blendedSinceMark() const { return impl_->blendedSinceMark; }

std::vector<RenderTargetBinding> GraphicsDevice::targetsBoundSinceMark() const { return impl_->boundSinceMark; }

void GraphicsDevice::Impl::noteWrittenTargets(bool color, bool depthStencil, const Rectangle& area, bool cleared) {
    if (!trackingBoundTargets) return;
    // Within the target: a viewport may reach past it.
    const int x0 = std::max(area.X, 0), y0 = std::max(area.Y, 0);
    const int x1 = std::min(area.X + area.Width, targetWidth), y1 = std::min(area.Y + area.Height, targetHeight);
    const double pixels = x1 > x0 && y1 > y0 ? double(x1 - x0) * double(y1 - y0) : 0.0;
    auto note = [&](const RenderTargetBinding& b, bool depth) {
        if (!color && !depth) return;
        for (WrittenTarget& w : writtenSinceMark)
            if (w.binding == b) {
                w.color = w.color || color;
                w.depthStencil = w.depthStencil || depth;
                double& most = cleared ? w.clearedPixels : w.drawnPixels;
                most = std::max(most, pixels);
                if (cleared && color) w.colorClearedPixels = std::max(w.colorClearedPixels, pixels);
                return;
            }
        writtenSinceMark.push_back({b, color, depth, cleared ? 0.0 : pixels, cleared ? pixels : 0.0, cleared && color ? pixels : 0.0});
    };
    // The first target's depth/stencil buffer serves them all (XNA: MRT use the first's).
    if (targets.empty()) note(RenderTargetBinding(backBuffer.get()), depthStencil);
    for (std::size_t i = 0; i < targets.size(); ++i) note(targets[i], depthStencil && i == 0);
}

void GraphicsDevice::Impl::noteDrawnTargets() {
    if (!trackingBoundTargets) return;
    const DepthStorage* depth = boundDepthStorage();  // made by now if the draw needs it
    const bool tests = device.DepthStencilState.DepthBufferEnable || device.DepthStencilState.StencilEnable;
    const fxport::Viewport& v = device.Viewport;
    Rectangle area(v.X, v.Y, v.Width, v.Height);
    if (!moreViewports.empty()) area = Rectangle(0, 0, targetWidth, targetHeight);  // a D3D11 draw into several: the whole target
    else if (device.RasterizerState.ScissorTestEnable) {
        const Rectangle& s = device.ScissorRectangle;
        const int x0 = std::max(area.X, s.X), y0 = std::max(area.Y, s.Y);
        const int x1 = std::min(area.X + area.Width, s.X + s.Width), y1 = std::min(area.Y + area.Height, s.Y + s.Height);
        area = Rectangle(x0, y0, std::max(x1 - x0, 0), std::max(y1 - y0, 0));
    }
    noteWrittenTargets(true, depth && depth->renderbuffer != 0 && tests, area, false);
}

std::vector<GraphicsDevice::WrittenTarget> GraphicsDevice::targetsWrittenSinceMark() const {
    return impl_->writtenSinceMark;
}

RenderTarget2D& GraphicsDevice::backBufferTarget() { return *impl_->backBuffer; }

void GraphicsDevice::Impl::generateMipsOfUnboundTargets(const std::vector<RenderTargetBinding>& previous) {
    // XNA regenerates a mipmapped render target's chain when it stops being a target.
    for (const RenderTargetBinding& b : previous) {
        if (!b.RenderTarget || b.RenderTarget->LevelCount() <= 1 || b.RenderTarget->IsDisposed()) continue;
        if (std::find(targets.begin(), targets.end(), b) == targets.end()) backend->generateMipmaps(b.RenderTarget->backendObject());
    }
}

void GraphicsDevice::Impl::bindTargets() {
    std::vector<RenderTargetBinding> bindings = targets;
    if (bindings.empty()) bindings.push_back(RenderTargetBinding(backBuffer.get()));
    Texture* first = bindings[0].RenderTarget;
    TargetInfo info = targetInfo(first);
    BackendObject depth = depthOverride ? depthOverride->renderbuffer : info.depth;
    DepthFormat depthFormat = depthOverride ? depthOverride->format : info.depthFormat;
    std::vector<std::uint64_t> key;
    for (const RenderTargetBinding& b : bindings)
        key.push_back((std::uint64_t(b.RenderTarget->backendObject()) << 8) |
                      (b.RenderTarget->kind() == Texture::Kind::TextureCube ? 1 + std::uint64_t(b.CubeMapFace) : 0));
    const bool depthIsTexture = depthOverride && depthOverride->isTexture;
    key.push_back(std::uint64_t(depth) << 8 | (depthIsTexture ? 0xfe : 0xff));
    targetWidth = info.width;
    targetHeight = info.height;
    auto it = framebuffers.find(key);
    BackendObject fbo = 0;
    if (it != framebuffers.end()) {
        fbo = it->second;
    } else {
        std::vector<ColorAttachment> colour;
        for (const RenderTargetBinding& b : bindings)
            colour.push_back({b.RenderTarget->backendObject(), b.RenderTarget->kind() == Texture::Kind::TextureCube ? int(b.CubeMapFace) : -1});
        std::string problem;
        fbo = backend->createFramebuffer(colour, depth, hasStencil(depthFormat), depthIsTexture, problem);
        if (fbo == 0)
            throw InvalidOperation("GraphicsDevice.SetRenderTargets: the driver rejects this combination of targets (" +
                                   std::string(surfaceFormatName(first->Format())) + ", " + problem + ")");
        ++live.framebuffers;
        framebuffers.emplace(key, fbo);
    }
    if (fbo != boundFramebuffer) {
        backend->bindFramebuffer(fbo);
        boundFramebuffer = fbo;
    }
}

void GraphicsDevice::Impl::dropFramebuffersUsing(BackendObject texture) {
    for (auto it = framebuffers.begin(); it != framebuffers.end();) {
        bool uses = std::any_of(it->first.begin(), it->first.end(), [&](std::uint64_t k) {
            return (k & 0xff) != 0xff && BackendObject(k >> 8) == texture;
        });
        if (uses) {
            if (boundFramebuffer == it->second) {
                backend->bindFramebuffer(0);
                boundFramebuffer = 0;
            }
            backend->deleteFramebuffer(it->second);
            --live.framebuffers;
            it = framebuffers.erase(it);
        } else {
            ++it;
        }
    }
}

// --- clear

void GraphicsDevice::Clear(Color color) {
    Clear(ClearOptions::Target | ClearOptions::DepthBuffer | ClearOptions::Stencil, color.ToVector4(), 1.0f, 0);
}

void GraphicsDevice::Clear(ClearOptions options, Color color, float depth, int stencil) {
    Clear(options, color.ToVector4(), depth, stencil);
}

void GraphicsDevice::Clear(ClearOptions options, Vector4 color, float depth, int stencil) {
    Impl& d = *impl_;
    if (d.boundFramebuffer == 0) d.bindTargets();  // the back buffer's FBO was dropped
    unsigned bits = unsigned(options) & unsigned(ClearOptions::Target | ClearOptions::DepthBuffer | ClearOptions::Stencil);
    d.clearStats.requested += long((bits & 1u) != 0) + long((bits & 2u) != 0) + long((bits & 4u) != 0);
    // D3D9 clears the viewport rectangle, whatever the scissor, write masks and blend say; a clear of
    // the whole target may wait (device/passes/pending_clear.cpp).
    bool wholeTarget = Viewport.X == 0 && Viewport.Y == 0 && Viewport.Width == d.targetWidth && Viewport.Height == d.targetHeight;
    if constexpr (kPendingClearsBuilt) {
        if (d.deferClears && wholeTarget) {
            d.recordClear(bits, color, depth, stencil);
            return;
        }
    }
    d.resolvePendingClear(~0u);
    d.executeClear(Rectangle(Viewport.X, Viewport.Y, Viewport.Width, Viewport.Height), bits, color, depth, stencil);
}

// --- draws

void GraphicsDevice::SetVertexBuffer(VertexBuffer* buffer, int vertexOffset) {
    if (buffer && buffer->IsDisposed()) throw InvalidOperation("GraphicsDevice.SetVertexBuffer: the buffer was disposed");
    if (buffer && &buffer->device() != this)
        throw InvalidOperation("GraphicsDevice.SetVertexBuffer: " + buffer->describe() + " was made by another GraphicsDevice");
    if (vertexOffset < 0) throw ArgumentError("GraphicsDevice.SetVertexBuffer: vertex offset " + std::to_string(vertexOffset) + " is negative");
    impl_->vertexBuffer = buffer;
    impl_->vertexOffset = vertexOffset;
    impl_->vertexBindings.clear();
    if (buffer) impl_->vertexBindings.push_back(VertexBufferBinding(buffer, vertexOffset));
}

void GraphicsDevice::DrawIndexedPrimitives(PrimitiveType primitiveType, int baseVertex, int, int, int startIndex,
                                           int primitiveCount) {
    Impl& d = *impl_;
    if (!d.vertexBuffer) throw InvalidOperation("DrawIndexedPrimitives: no vertex buffer set (SetVertexBuffer)");
    if (!Indices) throw InvalidOperation("DrawIndexedPrimitives: no index buffer set (GraphicsDevice.Indices)");
    if (Indices->IsDisposed()) throw InvalidOperation("DrawIndexedPrimitives: the index buffer was disposed");
    if (&Indices->device() != this) throw InvalidOperation("DrawIndexedPrimitives: the index buffer was made by another GraphicsDevice");
    checkPrimitiveType(primitiveType, "DrawIndexedPrimitives");
    int count = vertexCountFor(primitiveType, primitiveCount);
    if (primitiveCount <= 0 || startIndex < 0 || startIndex + count > Indices->IndexCount())
        throw ArgumentError("DrawIndexedPrimitives: " + std::to_string(primitiveCount) + " primitives from index " +
                            std::to_string(startIndex) + " need " + std::to_string(count) + " indices; the index buffer has " +
                            std::to_string(Indices->IndexCount()));
    if (d.vertexBindings.size() > 1) return d.drawBindings("DrawIndexedPrimitives", primitiveType, count, startIndex, baseVertex, true, 1);
    d.drawingPoints = primitiveType == PrimitiveType::PointList;
    d.flush("DrawIndexedPrimitives");
    Impl::VertexArray& va = d.bindVertexBuffer();
    if (va.elements != Indices->backendObject()) {
        va.elements = Indices->backendObject();
        d.backend->setIndexBuffer(va.vao, va.elements);
    }
    const bool wide = Indices->IndexElementSize() == IndexElementSize::ThirtyTwoBits;
    const DrawCall draw{primitiveType, 0, count, startIndex, true, baseVertex, wide ? 4 : 2};
    if (d.computePasses && d.computePasses->tryDraw(primitiveType, primitiveCount, draw)) return;
    d.issueDraw(draw);
}

void GraphicsDevice::DrawPrimitives(PrimitiveType primitiveType, int vertexStart, int primitiveCount) {
    Impl& d = *impl_;
    if (!d.vertexBuffer) throw InvalidOperation("DrawPrimitives: no vertex buffer set (SetVertexBuffer)");
    checkPrimitiveType(primitiveType, "DrawPrimitives");
    int count = vertexCountFor(primitiveType, primitiveCount);
    if (primitiveCount <= 0 || vertexStart < 0 || d.vertexOffset + vertexStart + count > d.vertexBuffer->VertexCount())
        throw ArgumentError("DrawPrimitives: " + std::to_string(primitiveCount) + " primitives from vertex " +
                            std::to_string(vertexStart) + " overrun the vertex buffer's " +
                            std::to_string(d.vertexBuffer->VertexCount()) + " vertices");
    if (d.vertexBindings.size() > 1) return d.drawBindings("DrawPrimitives", primitiveType, count, vertexStart, 0, false, 1);
    d.drawingPoints = primitiveType == PrimitiveType::PointList;
    d.flush("DrawPrimitives");
    d.bindVertexBuffer();
    const DrawCall draw{primitiveType, 0, count, vertexStart};
    if (d.computePasses && d.computePasses->tryDraw(primitiveType, primitiveCount, draw)) return;
    d.issueDraw(draw);
}

GraphicsDevice::Impl::VertexArray& GraphicsDevice::Impl::bindVertexBuffer() {
    const VertexDeclaration& declaration = vertexBuffer->VertexDeclaration();
    VertexArray& va = vertexArrayFor(declaration);
    const std::int64_t offset = std::int64_t(vertexOffset) * declaration.VertexStride();
    if (va.buffer != vertexBuffer->backendObject() || va.offset != offset || va.stride != declaration.VertexStride()) {
        va.buffer = vertexBuffer->backendObject();
        va.offset = offset;
        va.stride = declaration.VertexStride();
        backend->setVertexBuffer(va.vao, 0, va.buffer, std::size_t(va.offset), va.stride);
    }
    return va;
}

void GraphicsDevice::Impl::streamUserData(BackendObject& buffer, std::size_t& capacity, const void* data, std::size_t bytes) {
    if (buffer == 0) buffer = createBuffer();
    // Orphan: a fresh store each time, so the driver never waits for the previous draw.
    if (bytes > capacity) capacity = std::max<std::size_t>(bytes, 64 * 1024);
    backend->orphanBuffer(buffer, capacity);
    backend->writeBuffer(buffer, 0, bytes, data);
}

void GraphicsDevice::drawUser(PrimitiveType type, const void* vertices, std::size_t stride,
                              const VertexDeclaration& declaration, int primitiveCount) {
    Impl& d = *impl_;
    if (primitiveCount <= 0) throw ArgumentError("DrawUserPrimitives: primitive count " + std::to_string(primitiveCount));
    checkPrimitiveType(type, "DrawUserPrimitives");
    if (stride != std::size_t(declaration.VertexStride()))
        throw ArgumentError("DrawUserPrimitives: the vertex type has " + std::to_string(stride) +
                            " bytes, its declaration's stride is " + std::to_string(declaration.VertexStride()));
    d.drawingPoints = type == PrimitiveType::PointList;
    d.flush("DrawUserPrimitives");
    int count = vertexCountFor(type, primitiveCount);
    d.streamUserData(d.userVertices, d.userVerticesSize, vertices, std::size_t(count) * stride);
    Impl::VertexArray& va = d.vertexArrayFor(declaration);
    va.buffer = d.userVertices;
    va.offset = 0;
    va.stride = int(stride);
    d.backend->setVertexBuffer(va.vao, 0, va.buffer, 0, va.stride);
    DrawCall draw{type, 0, count, 0};
    if (d.computePasses && primitiveCount <= 2) draw.userDataHash = hashBytes(vertices, std::size_t(count) * stride);
    if (d.computePasses && d.computePasses->tryDraw(type, primitiveCount, draw)) return;
    d.issueDraw(draw);
}

void GraphicsDevice::drawUserIndexed(PrimitiveType type, const void* vertices, std::size_t stride, int vertexCount,
                                     const VertexDeclaration& declaration, const void* indices, int indexSize,
                                     int primitiveCount) {
    Impl& d = *impl_;
    if (primitiveCount <= 0 || vertexCount <= 0)
        throw ArgumentError("DrawUserIndexedPrimitives: primitive count " + std::to_string(primitiveCount) +
                            ", vertex count " + std::to_string(vertexCount));
    if (stride != std::size_t(declaration.VertexStride()))
        throw ArgumentError("DrawUserIndexedPrimitives: the vertex type has " + std::to_string(stride) +
                            " bytes, its declaration's stride is " + std::to_string(declaration.VertexStride()));
    checkPrimitiveType(type, "DrawUserIndexedPrimitives");
    int count = vertexCountFor(type, primitiveCount);
    // An index past the vertices given would read past the caller's array in the driver.
    for (int i = 0; i < count; ++i) {
        std::uint32_t index = indexSize == 2 ? static_cast<const std::uint16_t*>(indices)[i] : static_cast<const std::uint32_t*>(indices)[i];
        if (index >= std::uint32_t(vertexCount))
            throw ArgumentError("DrawUserIndexedPrimitives: index " + std::to_string(i) + " is " + std::to_string(index) + ", beyond the " +
                                std::to_string(vertexCount) + " vertices given");
    }
    d.drawingPoints = type == PrimitiveType::PointList;
    d.flush("DrawUserIndexedPrimitives");
    d.streamUserData(d.userVertices, d.userVerticesSize, vertices, std::size_t(vertexCount) * stride);
    d.streamUserData(d.userIndices, d.userIndicesSize, indices, std::size_t(count) * std::size_t(indexSize));
    Impl::VertexArray& va = d.vertexArrayFor(declaration);
    va.buffer = d.userVertices;
    va.offset = 0;
    va.stride = int(stride);
    d.backend->setVertexBuffer(va.vao, 0, va.buffer, 0, va.stride);
    va.elements = d.userIndices;
    d.backend->setIndexBuffer(va.vao, va.elements);
    DrawCall draw{type, 0, count, 0, true, 0, indexSize};
    if (d.computePasses && primitiveCount <= 2)
        draw.userDataHash = hashBytes(indices, std::size_t(count) * std::size_t(indexSize),
                                      hashBytes(vertices, std::size_t(vertexCount) * stride));
    if (d.computePasses && d.computePasses->tryDraw(type, primitiveCount, draw)) return;
    d.issueDraw(draw);
}

// --- presentation and read-back

void GraphicsDevice::Present() {
    if (!context_) return;
    if (context_->platform() == platform::Platform::GLFW) {
        // The back buffer is stored top row first; the window's row 0 is the bottom: flip once here.
        impl_->resolvePendingClearBeforeRead(impl_->backBuffer.get());
        std::vector<RenderTargetBinding> bound = impl_->targets;
        impl_->targets.clear();
        impl_->bindTargets();
        int w = parameters_.BackBufferWidth, h = parameters_.BackBufferHeight;
        impl_->backend->presentFlipped(impl_->boundFramebuffer, w, h);
        impl_->targets = bound;
        impl_->bindTargets();
    }
    context_->swapBuffers();
    context_->pollEvents();
}

std::vector<Color> GraphicsDevice::GetBackBufferData() const {
    std::vector<Color> pixels(std::size_t(parameters_.BackBufferWidth) * std::size_t(parameters_.BackBufferHeight));
    impl_->backBuffer->GetData(pixels.data(), pixels.size());
    return pixels;
}

// The frame as a window shows it: the back buffer's alpha does not reach the screen (XNA's neither),
// so it is written as 255; an effect that leaves alpha 0 must not save see-through pixels.
void GraphicsDevice::SaveBackBufferAsPng(const std::string& path) const { impl_->backBuffer->savePng(path, /*opaque=*/true); }

// --- GL object bookkeeping

// The core formats are GL 4.5's; the compressed families (S3TC above all) are extensions, asked once.
bool GraphicsDevice::Impl::isSampleable(SurfaceFormat format) {
    std::int8_t& known = sampleableFormats[std::size_t(format)];
    if (known == 0) known = backend->isSampleable(format) ? 1 : -1;
    return known > 0;
}

void GraphicsDevice::Impl::requireSampleable(SurfaceFormat format) {
    if (!isSampleable(format))
        throw ArgumentError(std::string("the graphics driver cannot make textures of SurfaceFormat::") + surfaceFormatName(format) +
                           (isCompressedFormat(format) ? " (its block compression is a GL extension this driver lacks)" : ""));
}

BackendObject GraphicsDevice::Impl::createTexture(bool cube, SurfaceFormat format, int levels, int width, int height) {
    requireSampleable(format);
    const BackendObject name = backend->createTexture(cube, format, levels, width, height);
    ++live.textures;
    return name;
}
BackendObject GraphicsDevice::Impl::createVolumeTexture(SurfaceFormat format, int levels, int width, int height, int depth) {
    requireSampleable(format);
    const BackendObject name = backend->createVolumeTexture(format, levels, width, height, depth);
    ++live.textures;
    return name;
}
BackendObject GraphicsDevice::Impl::createArrayTexture(SurfaceFormat format, int levels, int width, int height, int layers) {
    requireSampleable(format);
    const BackendObject name = backend->createArrayTexture(format, levels, width, height, layers);
    ++live.textures;
    return name;
}
BackendObject GraphicsDevice::Impl::createLineTexture(SurfaceFormat format, int levels, int width, int layers, bool array) {
    requireSampleable(format);
    const BackendObject name = backend->createLineTexture(format, levels, width, layers, array);
    ++live.textures;
    return name;
}
BackendObject GraphicsDevice::Impl::createTextureView(const std::string& who, BackendObject source, SurfaceFormat format, bool array, int firstLevel,
                                                      int levels, int firstLayer, int layers) {
    const BackendObject name = backend->createTextureView(source, format, array, firstLevel, levels, firstLayer, layers);
    if (name == 0)
        throw InvalidOperation(who + ": the graphics API cannot make a view of levels " + std::to_string(firstLevel) + "+" + std::to_string(levels) +
                           ", layers " + std::to_string(firstLayer) + "+" + std::to_string(layers) + " (texture views: GL 4.3)");
    ++live.textures;
    return name;
}
BackendObject GraphicsDevice::Impl::createMultisampleTexture(SurfaceFormat format, int samples, int width, int height, int& given) {
    const BackendObject name = backend->createMultisampleTexture(format, samples, width, height, given);
    ++live.textures;
    return name;
}
BackendObject GraphicsDevice::Impl::createMultisampleArrayTexture(SurfaceFormat format, int samples, int width, int height, int layers, int& given) {
    const BackendObject name = backend->createMultisampleArrayTexture(format, samples, width, height, layers, given);
    ++live.textures;
    return name;
}
void GraphicsDevice::Impl::deleteTexture(BackendObject& name) {
    if (!name) return;
    for (int unit = 0; unit < kMaxTextureSlots; ++unit)
        if (boundTextures[std::size_t(unit)] == name) boundTextures[std::size_t(unit)] = 0;
    backend->deleteTexture(name);
    --live.textures;
    name = 0;
}
BackendObject GraphicsDevice::Impl::createBuffer() {
    const BackendObject name = backend->createBuffer();
    ++live.buffers;
    return name;
}
void GraphicsDevice::Impl::deleteBuffer(BackendObject& name) {
    if (!name) return;
    for (BackendObject& b : boundUniformBuffers)
        if (b == name) b = 0;
    for (BackendObject& b : wantedUniformBuffers)
        if (b == name) b = 0;
    for (auto& [key, va] : vertexArrays) {
        if (va.buffer == name) va.buffer = 0, va.offset = -1;
        if (va.elements == name) va.elements = 0;
    }
    backend->deleteBuffer(name);
    --live.buffers;
    name = 0;
}
BackendObject GraphicsDevice::Impl::createRenderbuffer() {
    const BackendObject name = backend->createRenderbuffer();
    ++live.renderbuffers;
    return name;
}
void GraphicsDevice::Impl::deleteRenderbuffer(BackendObject& name) {
    if (!name) return;
    backend->deleteRenderbuffer(name);
    --live.renderbuffers;
    name = 0;
}
BackendObject GraphicsDevice::Impl::createProgram(int stage, const xlate::CompiledShader& shader, const std::string& source,
                                                  const std::string& label) {
    // Identical GLSL for the same stage (and the same captured outputs) shares one program (a
    // model's per-part material effects, the same effect loaded twice): effects hold references,
    // the last release deletes it. The varyings' semantics are part of the key: stages compiled
    // apart are linked per program (stage_links.cpp), and `return i.a;` reading GAMMA0 at
    // location 29 is the same GLSL as reading POSITION0 there.
    const std::vector<std::string> captured = xlate::capturedVaryings(shader.streamOutput);
    std::string key = source;
    for (const std::string& c : captured) key += "\n// captured " + c;
    for (const xlate::Varying& v : shader.varyingInputs) key += "\n// in " + v.semantic + "=" + std::to_string(v.location);
    for (const xlate::Varying& v : shader.varyingOutputs) key += "\n// out " + v.semantic + "=" + std::to_string(v.location);
    auto cached = programCache.find({stage, key});
    if (cached != programCache.end()) {
        ++cached->second.references;
        return cached->second.program;
    }
    std::string log;
    const BackendObject program = backend->createProgram(stage, source, captured, log);
    if (!program) throw InvalidOperation(label + ": the GL driver rejected the translated shader:\n" + log);
    ++live.programs;
    programCache.emplace(std::make_pair(stage, key), CachedProgram{program, 1});
    return program;
}

void GraphicsDevice::Impl::deleteProgram(BackendObject& name) {
    if (!name) return;
    for (auto it = programCache.begin(); it != programCache.end(); ++it) {
        if (it->second.program != name) continue;
        if (--it->second.references > 0) {
            name = 0;
            return;
        }
        programCache.erase(it);
        break;
    }
    dropLinkedReadersOf(name);
    dropPipelinesUsing(name);
    dropComputePipelinesUsing(name);
    dropVertexArraysUsing(name);
    startVertexUniforms.erase(name);
    if (boundVertexProgram == name) boundVertexProgram = 0;
    for (auto& s : shaders)
        if (s && s->program == name) s = nullptr;
    backend->deleteProgram(name);
    --live.programs;
    name = 0;
}
BackendObject GraphicsDevice::Impl::createQuery(QueryKind kind) {
    const BackendObject name = backend->createQuery(kind);
    ++live.queries;
    return name;
}
void GraphicsDevice::Impl::deleteQuery(BackendObject& name) {
    if (!name) return;
    backend->deleteQuery(name);
    --live.queries;
    name = 0;
}

void GraphicsDevice::Impl::dropPipelinesUsing(BackendObject program) {
    for (auto it = pipelines.begin(); it != pipelines.end();) {
        auto [vs, ps, gs, hs, ds] = it->first;
        if (vs == program || ps == program || gs == program || hs == program || ds == program) {
            if (boundPipeline == it->second) {
                backend->bindPipeline(0);
                boundPipeline = 0;
            }
            backend->deletePipeline(it->second);
            --live.pipelines;
            it = pipelines.erase(it);
        } else {
            ++it;
        }
    }
}

void GraphicsDevice::Impl::dropVertexArraysUsing(BackendObject program) {
    std::string suffix = "|" + std::to_string(program);
    for (auto it = vertexArrays.begin(); it != vertexArrays.end();) {
        const std::string& key = it->first;
        if (key.size() >= suffix.size() && key.compare(key.size() - suffix.size(), suffix.size(), suffix) == 0) {
            if (boundVertexArray == it->second.vao) {
                backend->bindVertexArray(0);
                boundVertexArray = 0;
            }
            if (lastVertexArray.array == &it->second) lastVertexArray = {};
            backend->deleteVertexArray(it->second.vao);
            --live.vertexArrays;
            it = vertexArrays.erase(it);
        } else {
            ++it;
        }
    }
}

void GraphicsDevice::Impl::forget(GraphicsResource* resource) {
    resources.erase(std::remove(resources.begin(), resources.end(), resource), resources.end());
}

void GraphicsDevice::Impl::releaseAll() {
    computePasses.reset();  // its programs and buffer, while the context is current
    fragmentTally.reset();  // its queries, likewise
    backend->bindPipeline(0);
    backend->bindVertexArray(0);
    backend->bindFramebuffer(0);
    for (auto& [key, pipeline] : pipelines) backend->deletePipeline(pipeline), --live.pipelines;
    pipelines.clear();
    for (auto& [key, pipeline] : computePipelines) backend->deletePipeline(pipeline), --live.pipelines;
    computePipelines.clear();
    for (auto& [key, va] : vertexArrays) backend->deleteVertexArray(va.vao), --live.vertexArrays;
    vertexArrays.clear();
    for (auto& [key, fbo] : framebuffers) backend->deleteFramebuffer(fbo), --live.framebuffers;
    framebuffers.clear();
    for (auto& [key, sampler] : samplerObjects) backend->deleteSampler(sampler);
    samplerObjects.clear();
    deleteBuffer(userVertices);
    deleteBuffer(userIndices);
}

}  // namespace fxport
