// The device core's entry points for front ends other than XNA's (front_end_core.h). Each one
// reuses the device's own machinery -- the backend object bookkeeping, flush() with its state
// shadow, the vertex-array cache, target binding, lazy depth storage -- and adds only the backend
// calls XNA's classes do not make (byte buffers by slot, instanced draws, clearing a texture or a
// depth buffer that is not bound).
#include "device/front_end_core.h"

#include <algorithm>
#include <string>

#include "device/device_impl.h"
#include "device/vertex_input.h"
#include "fxport/graphics/errors.h"
#include "fxport/xlate/compiled_effect.h"

namespace fxport::core {

namespace {

// Framebuffers keyed with this renderbuffer as their depth attachment (graphics_device.cpp's key:
// colour entries name << 8 | face, the depth entry name << 8 | 0xff).
void dropFramebuffersWithDepth(GraphicsDevice::Impl& d, BackendObject renderbuffer) {
    if (renderbuffer == 0) return;
    for (auto it = d.framebuffers.begin(); it != d.framebuffers.end();) {
        const std::uint64_t depthKey = it->first.back();
        if (BackendObject(depthKey >> 8) != renderbuffer) {
            ++it;
            continue;
        }
        if (d.boundFramebuffer == it->second) {
            d.backend->bindFramebuffer(0);
            d.boundFramebuffer = 0;
        }
        d.backend->deleteFramebuffer(it->second);
        --d.live.framebuffers;
        it = d.framebuffers.erase(it);
    }
}

}  // namespace

// --- ByteBuffer

ByteBuffer::ByteBuffer(GraphicsDevice& device, std::size_t bytes, const void* initial, bool dynamic)
    : GraphicsResource(device, "Buffer"), size_(bytes) {
    if (bytes == 0 || bytes > (std::size_t(1) << 31))
        throw ArgumentError(describe() + ": " + std::to_string(bytes) + " bytes; a buffer holds 1 byte to 2 GiB");
    GraphicsDevice::Impl& d = deviceImpl(device);
    name_ = d.createBuffer();
    std::vector<std::uint8_t> zeros;
    if (!initial) zeros.assign(bytes, 0);
    d.backend->allocateBuffer(name_, bytes, initial ? initial : zeros.data(), dynamic);
}

ByteBuffer::~ByteBuffer() { disposeFromDestructor(); }

void ByteBuffer::releaseGpuObjects() {
    deviceImpl(device()).forgetStorage(this);
    deviceImpl(device()).forgetStreamTarget(this);
    deviceImpl(device()).deleteBuffer(name_);
}

void ByteBuffer::write(std::size_t offset, std::size_t bytes, const void* data) {
    throwIfDisposed("write");
    if (offset > size_ || bytes > size_ - offset)
        throw ArgumentError(describe() + ": bytes [" + std::to_string(offset) + ", " + std::to_string(offset + bytes) +
                            ") are outside its " + std::to_string(size_));
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.storageBarrier();  // a shader's writes through a UAV land before this replaces them
    if (bytes) d.backend->writeBuffer(name_, offset, bytes, data);
}

void ByteBuffer::read(std::size_t offset, std::size_t bytes, void* out) const {
    throwIfDisposed("read");
    if (offset > size_ || bytes > size_ - offset)
        throw ArgumentError(describe() + ": bytes [" + std::to_string(offset) + ", " + std::to_string(offset + bytes) +
                            ") are outside its " + std::to_string(size_));
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.storageBarrier();  // what a dispatch or draw wrote is what this reads
    if (bytes) d.backend->readBuffer(name_, offset, bytes, out);
}

void ByteBuffer::copyFrom(const ByteBuffer& source) {
    throwIfDisposed("copy");
    if (source.size_ != size_)
        throw ArgumentError(describe() + ": copy from a buffer of " + std::to_string(source.size_) + " bytes into " +
                            std::to_string(size_));
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.storageBarrier();
    d.backend->copyBuffer(source.name_, name_, 0, 0, size_);
}

void ByteBuffer::copyFrom(const ByteBuffer& source, std::size_t sourceOffset, std::size_t destinationOffset, std::size_t bytes) {
    throwIfDisposed("copy");
    if (sourceOffset > source.size_ || bytes > source.size_ - sourceOffset || destinationOffset > size_ || bytes > size_ - destinationOffset)
        throw ArgumentError(describe() + ": copy of " + std::to_string(bytes) + " bytes from byte " + std::to_string(sourceOffset) + " of a " +
                            std::to_string(source.size_) + "-byte buffer to byte " + std::to_string(destinationOffset) + " of " +
                            std::to_string(size_));
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.storageBarrier();
    if (bytes) d.backend->copyBuffer(source.name_, name_, sourceOffset, destinationOffset, bytes);
}

// --- TexelBuffer

// What GL's buffer textures hold (the formats a typed buffer view may take).
bool isTexelBufferFormat(SurfaceFormat f) {
    if (isIntegerFormat(f)) return true;
    switch (f) {
    case SurfaceFormat::Single: case SurfaceFormat::Vector2: case SurfaceFormat::Vector4: case SurfaceFormat::HalfSingle:
    case SurfaceFormat::HalfVector2: case SurfaceFormat::HalfVector4: case SurfaceFormat::HdrBlendable: case SurfaceFormat::Color:
    case SurfaceFormat::Rgba64: case SurfaceFormat::Rg32: case SurfaceFormat::R16: case SurfaceFormat::Rg8: case SurfaceFormat::R8:
        return true;
    default: return false;
    }
}

std::size_t bufferOffsetAlignment(GraphicsDevice& device, bool storage) { return deviceImpl(device).backend->bufferOffsetAlignment(storage); }

TexelBuffer::TexelBuffer(GraphicsDevice& device, const ByteBuffer& buffer, SurfaceFormat format, std::size_t count, std::size_t first)
    : GraphicsResource(device, "TexelBuffer"), format_(format) {
    if (!isTexelBufferFormat(format))
        throw ArgumentError(describe() + ": format " + surfaceFormatName(format) + " is not one a typed buffer holds");
    const std::size_t texel = std::size_t(bytesPerPixel(format));
    const std::size_t bytes = count * texel, offset = first * texel;
    if (count == 0 || offset + bytes > buffer.size())
        throw ArgumentError(describe() + ": " + std::to_string(count) + " texels of " + surfaceFormatName(format) + " from texel " + std::to_string(first) +
                            " end at byte " + std::to_string(offset + bytes) + "; the buffer has " + std::to_string(buffer.size()));
    GraphicsDevice::Impl& d = deviceImpl(device);
    const std::size_t alignment = d.backend->bufferOffsetAlignment(false);
    if (offset % alignment != 0)
        throw ArgumentError(describe() + ": texel " + std::to_string(first) + " starts at byte " + std::to_string(offset) +
                            ", and buffer textures start at multiples of " + std::to_string(alignment) + " bytes on this GPU");
    name_ = d.backend->createBufferTexture(buffer.backendObject(), format, offset, bytes);
    ++d.live.textures;
}

TexelBuffer::~TexelBuffer() { disposeFromDestructor(); }

void TexelBuffer::releaseGpuObjects() {
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.forgetStorage(this);
    d.deleteTexture(name_);
}

void setTexelBuffer(GraphicsDevice& device, bool unorderedAccess, int slot, const TexelBuffer* buffer) {
    GraphicsDevice::Impl& d = deviceImpl(device);
    const int slots = unorderedAccess ? kMaxUnorderedAccessSlots : kMaxShaderResourceBuffers;
    if (slot < 0 || slot >= slots)
        throw ArgumentError(std::string(unorderedAccess ? "unordered-access" : "shader-resource buffer") + " slot " + std::to_string(slot) +
                            " is outside 0.." + std::to_string(slots - 1));
    GraphicsDevice::Impl::StorageSlot wanted;
    if (buffer) wanted = GraphicsDevice::Impl::StorageSlot{buffer, buffer->backendObject(), unorderedAccess, buffer->format(), true};
    if (unorderedAccess) d.unorderedAccess[std::size_t(slot)] = wanted;
    else d.resourceBuffers[std::size_t(slot)] = wanted;
}

// --- DepthBuffer

DepthBuffer::DepthBuffer(GraphicsDevice& device, int width, int height, DepthFormat format, int samples)
    : GraphicsResource(device, "DepthBuffer") {
    if (format == DepthFormat::None || width <= 0 || height <= 0)
        throw ArgumentError(describe() + ": " + std::to_string(width) + "x" + std::to_string(height) + " " +
                            depthFormatName(format) + " is not a depth buffer");
    if (samples < 0 || samples > device.maxSampleCount())
        throw ArgumentError(describe() + ": " + std::to_string(samples) + " samples (the driver makes up to " + std::to_string(device.maxSampleCount()) + ")");
    storage_.samples = samples;
    storage_.format = format;
    storage_.width = width;
    storage_.height = height;
    deviceImpl(device).adoptDepthStorage(storage_);
}

DepthBuffer::DepthBuffer(GraphicsDevice& device, Texture2D& texture) : GraphicsResource(device, "DepthBuffer") {
    switch (texture.Format()) {
    case SurfaceFormat::Depth32: storage_.format = DepthFormat::Depth32F; break;
    case SurfaceFormat::Depth24Stencil8: storage_.format = DepthFormat::Depth24Stencil8; break;
    case SurfaceFormat::Depth32Stencil8: storage_.format = DepthFormat::Depth32FStencil8; break;
    case SurfaceFormat::Depth16: storage_.format = DepthFormat::Depth16; break;
    default:
        throw ArgumentError(describe() + ": a texture of format " + surfaceFormatName(texture.Format()) +
                            " is not a depth texture (Depth32, Depth24Stencil8, Depth32Stencil8 or Depth16)");
    }
    storage_.width = texture.Width();
    storage_.height = texture.Height();
    storage_.renderbuffer = texture.backendObject();
    storage_.isTexture = true;
}

DepthBuffer::~DepthBuffer() { disposeFromDestructor(); }

void DepthBuffer::releaseGpuObjects() {
    GraphicsDevice::Impl& d = deviceImpl(device());
    if (d.depthOverride == &storage_) d.depthOverride = nullptr;  // the next draw binds the targets without it
    dropFramebuffersWithDepth(d, storage_.renderbuffer);
    d.releaseDepthStorage(storage_);
}

// --- ShaderCode

ShaderCode::ShaderCode(GraphicsDevice& device, std::shared_ptr<const xlate::CompiledEffect> effect, int shaderIndex,
                       const std::string& label)
    : GraphicsResource(device, "Shader"), effect_(std::move(effect)), program_(std::make_unique<ShaderProgram>()) {
    if (shaderIndex < 0 || std::size_t(shaderIndex) >= effect_->shaders.size())
        throw ArgumentError(describe() + ": shader " + std::to_string(shaderIndex) + " of " +
                            std::to_string(effect_->shaders.size()));
    const xlate::CompiledShader& s = effect_->shaders[std::size_t(shaderIndex)];
    const int stage = int(s.profile.stage);  // backend.h numbers stages as xlate does
    program_->stage = int(s.profile.stage);
    program_->shader = &s;
    program_->label = label;
    program_->mayDiscard = s.glsl.find("discard") != std::string::npos;
    program_->program = deviceImpl(device).createProgram(stage, s, s.glsl, label);
}

ShaderCode::~ShaderCode() { disposeFromDestructor(); }

const xlate::CompiledShader& ShaderCode::shader() const { return *program_->shader; }

void ShaderCode::releaseGpuObjects() {
    GraphicsDevice::Impl& d = deviceImpl(device());
    for (const ShaderProgram*& s : d.shaders)
        if (s == program_.get()) s = nullptr;
    if (d.computeShader == program_.get()) d.computeShader = nullptr;
    d.deleteProgram(program_->program);
}

// --- binding

void setShaderStages(GraphicsDevice& device, const ShaderCode* const (&stages)[5]) {
    if (!stages[0] || !stages[1]) throw InvalidOperation("a draw needs a vertex and a pixel shader");
    GraphicsDevice::Impl& d = deviceImpl(device);
    for (int stage = 0; stage < kStageCount; ++stage)
        d.shaders[std::size_t(stage)] = stages[stage] ? &stages[stage]->program() : nullptr;
    d.emulation = PassEmulation{};
    d.device.FixedFunction = FixedFunctionState{};  // D3D10+ has none of D3D9's fixed-function stages
    d.passApplied = true;
}

void setComputeShader(GraphicsDevice& device, const ShaderCode* computeShader) {
    deviceImpl(device).computeShader = computeShader ? &computeShader->program() : nullptr;
}

void setStorageBuffer(GraphicsDevice& device, bool unorderedAccess, int slot, const ByteBuffer* buffer, std::size_t offset, std::size_t bytes) {
    GraphicsDevice::Impl& d = deviceImpl(device);
    const int slots = unorderedAccess ? kMaxUnorderedAccessSlots : kMaxShaderResourceBuffers;
    if (slot < 0 || slot >= slots)
        throw ArgumentError(std::string(unorderedAccess ? "unordered-access" : "shader-resource buffer") + " slot " + std::to_string(slot) +
                            " is outside 0.." + std::to_string(slots - 1));
    GraphicsDevice::Impl::StorageSlot wanted;
    if (buffer && bytes != 0) {
        const std::size_t alignment = d.backend->bufferOffsetAlignment(true);
        if (offset + bytes > buffer->size() || offset % alignment != 0)
            throw ArgumentError("bytes " + std::to_string(offset) + ".." + std::to_string(offset + bytes) + " of a " + std::to_string(buffer->size()) +
                                "-byte buffer: a storage range lies inside the buffer and starts at a multiple of " + std::to_string(alignment) +
                                " bytes");
    }
    if (buffer) {
        wanted = GraphicsDevice::Impl::StorageSlot{buffer, buffer->backendObject(), false, SurfaceFormat::Color};
        wanted.offset = offset;
        wanted.bytes = bytes;
    }
    if (unorderedAccess) d.unorderedAccess[std::size_t(slot)] = wanted;
    else d.resourceBuffers[std::size_t(slot)] = wanted;
}

bool fillEmptyPixelStage(GraphicsDevice& device, const ShaderCode& code) {
    GraphicsDevice::Impl& d = deviceImpl(device);
    if (d.shaders[1]) return false;
    d.shaders[1] = &code.program();
    return true;
}

void setUniformBuffer(GraphicsDevice& device, int stage, int blockBinding, const ByteBuffer* buffer) {
    if (stage < 0 || stage >= kUniformStages || blockBinding < 0 || blockBinding >= kUniformBindingsPerStage || blockBinding == kUnusedUniformBinding)
        throw ArgumentError("uniform binding " + std::to_string(blockBinding) + " of stage " + std::to_string(stage) +
                            " is not one a front end may set");
    deviceImpl(device).wantedUniformBuffers[std::size_t(uniformBindingFor(stage, blockBinding))] = buffer ? buffer->backendObject() : 0;
}

void setTargets(GraphicsDevice& device, const std::vector<RenderTargetBinding>& colour, DepthBuffer* depth) {
    GraphicsDevice::Impl& d = deviceImpl(device);
    DepthStorage* wanted = depth ? &depth->storage() : nullptr;
    const bool depthChanged = d.depthOverride != wanted;
    d.depthOverride = wanted;
    if (colour != d.targets) {
        device.SetRenderTargets(colour);  // binds with the new depth buffer
    } else if (depthChanged) {
        d.bindTargets();
        device.Viewport = fxport::Viewport(0, 0, d.targetWidth, d.targetHeight);
    }
}

void setMoreViewports(GraphicsDevice& device, const std::vector<Viewport>& viewports, const std::vector<Rectangle>& scissors) {
    constexpr std::size_t kMost = 15;  // D3D11's 16 viewports (GL 4.1 has at least 16) less index 0
    if (viewports.size() > kMost || scissors.size() > kMost)
        throw ArgumentError(std::to_string(std::max(viewports.size(), scissors.size()) + 1) + " viewports or scissor rectangles; at most 16");
    GraphicsDevice::Impl& d = deviceImpl(device);
    d.moreViewports = viewports;
    d.moreScissors = scissors;
}

// --- draws

namespace {

constexpr int kMaxControlPoints = 32;  // D3D11's patch lists, and GL_MAX_PATCH_VERTICES's minimum

// flush() for a draw of `a`: a patch draw tells it so (it checks the hull and domain stages).
void flushFor(GraphicsDevice::Impl& d, const DrawArguments& a) {
    if (a.controlPoints < 0 || a.controlPoints > kMaxControlPoints)
        throw ArgumentError("Draw: " + std::to_string(a.controlPoints) + " control points per patch (1.." + std::to_string(kMaxControlPoints) + ")");
    d.patchDraw = a.controlPoints > 0;
    d.drawingPoints = false;  // D3D10+ points have no size or sprites; FixedFunction stays off (setShaderStages)
    try {
        d.flush("Draw");
    } catch (...) {
        d.patchDraw = false;
        throw;
    }
    d.patchDraw = false;
}

// The draw call itself, with the vertex array (and its element buffer) bound.
void issue(GraphicsDevice::Impl& d, GraphicsDevice::Impl::VertexArray& va, const DrawArguments& a) {
    DrawCall call;
    call.type = a.type;
    call.controlPoints = a.controlPoints;
    call.count = a.count;
    call.first = a.first;
    call.instanced = true;
    call.instances = a.instances;
    call.firstInstance = a.firstInstance;
    if (const std::uint32_t indices = a.indices ? a.indices->backendObject() : a.indexObject) {
        if (va.elements != indices) {
            va.elements = indices;
            d.backend->setIndexBuffer(va.vao, va.elements);
        }
        call.indexed = true;
        call.indexSize = a.indexSize;
        call.baseVertex = a.baseVertex;
    }
    d.issueDraw(call);
}

// The element of `streams` feeding a vertex-shader input (by semantic, any name; feedsInput).
bool findElement(const std::vector<InstancedStream>& streams, const xlate::VertexInput& input, std::size_t& stream,
                 const StreamElement*& element) {
    for (std::size_t s = 0; s < streams.size(); ++s) {
        if (!streams[s].vertices.layout) continue;
        for (const StreamElement& e : streams[s].vertices.layout->elements)
            if (feedsInput(e.semantic, input)) {
                stream = s;
                element = &e;
                return true;
            }
    }
    return false;
}

// The vertex array reading `streams` (stream i on vertex-buffer binding i) for the bound vertex shader; made
// once per layout and shader, kept with the device's others (so a deleted program drops it).
GraphicsDevice::Impl::VertexArray& streamVertexArray(GraphicsDevice::Impl& d, const std::vector<InstancedStream>& streams) {
    const ShaderProgram& vs = *d.shaders[0];
    std::string key = "streams";
    for (const InstancedStream& s : streams) {
        key += ";" + std::to_string(s.instanceStepRate) + ":";
        if (!s.vertices.layout) continue;
        key += std::to_string(s.vertices.layout->stride);
        for (const StreamElement& e : s.vertices.layout->elements)
            key += "," + e.semantic + "/" + std::to_string(e.offset) + "/" + std::to_string(int(e.format.component)) + "/" +
                   std::to_string(e.format.count) + (e.format.normalized ? "n" : "");
    }
    key += "|" + std::to_string(vs.program);
    auto it = d.vertexArrays.find(key);
    if (it == d.vertexArrays.end()) {
        struct Feed {
            const xlate::VertexInput* input;
            std::size_t stream;
            const StreamElement* element;
        };
        std::vector<Feed> feeds;  // checked before the backend makes anything
        for (const xlate::VertexInput& input : vs.shader->inputs) {
            Feed f{&input, 0, nullptr};
            if (findElement(streams, input, f.stream, f.element)) feeds.push_back(f);
            else if (input.semantic.rfind("SV_", 0) != 0 || input.semantic.rfind("SV_POSITION", 0) == 0)
                throw InvalidOperation("Draw: the input layout has no element for the vertex shader's input " + input.semantic);
        }
        std::vector<VertexAttribute> attributes;
        for (const Feed& f : feeds)
            attributes.push_back(VertexAttribute{f.input->location, f.element->format, f.element->offset,
                                                 f.input->isInteger, int(f.stream)});
        std::vector<int> divisors;
        for (const InstancedStream& s : streams) divisors.push_back(s.instanceStepRate);
        GraphicsDevice::Impl::VertexArray va;
        va.vao = d.backend->createVertexArray(attributes, divisors);
        ++d.live.vertexArrays;
        it = d.vertexArrays.emplace(key, va).first;
    }
    if (d.boundVertexArray != it->second.vao) {
        d.backend->bindVertexArray(it->second.vao);
        d.boundVertexArray = it->second.vao;
    }
    return it->second;
}

}  // namespace

StreamLayout streamLayoutOf(const VertexDeclaration& declaration) {
    StreamLayout layout;
    layout.stride = declaration.VertexStride();
    for (const VertexElement& e : declaration.GetVertexElements())
        layout.elements.push_back({vertexElementSemantic(e), e.Offset, vertexFormatOf(e.VertexElementFormat)});
    return layout;
}

void drawStreams(GraphicsDevice& device, const std::vector<InstancedStream>& streams, const DrawArguments& a) {
    GraphicsDevice::Impl& d = deviceImpl(device);
    if (a.count <= 0 || a.instances <= 0) return;  // D3D draws nothing
    flushFor(d, a);
    GraphicsDevice::Impl::VertexArray& va = streamVertexArray(d, streams);
    for (std::size_t s = 0; s < streams.size(); ++s) {
        const VertexStream& v = streams[s].vertices;
        const int stride = v.layout ? v.layout->stride : 0;
        d.backend->setVertexBuffer(va.vao, int(s), v.buffer ? v.buffer->backendObject() : v.object, v.offset, stride);
    }
    issue(d, va, a);
}

// --- clears and copies

void clearTexture(Texture& texture, const Vector4& color) {
    GraphicsDevice::Impl& d = deviceImpl(texture.device());
    // A clear of this target still pending in the device would land after ours.
    d.resolvePendingClearBeforeRead(&texture);
    const float rgba[4] = {color.X, color.Y, color.Z, color.W};
    d.backend->clearTexture(texture.backendObject(), 0, rgba);
}

void clearDepthBuffer(GraphicsDevice& device, DepthBuffer& buffer, bool depth, bool stencil, float depthValue,
                      int stencilValue) {
    DepthStorage& s = buffer.storage();
    const bool stencilled = hasStencil(s.format);
    stencil = stencil && stencilled;
    if (!depth && !stencil) return;
    if (s.renderbuffer == 0) {  // not made yet: the clear waits on it (depth_storage.cpp)
        s.waitingClear |= (depth ? unsigned(ClearOptions::DepthBuffer) : 0u) | (stencil ? unsigned(ClearOptions::Stencil) : 0u);
        if (depth) s.clearDepth = depthValue;
        if (stencil) s.clearStencil = stencilValue;
        return;
    }
    GraphicsDevice::Impl& d = deviceImpl(device);
    d.backend->clearDepthStencil(s.renderbuffer, stencilled, s.isTexture, depth, stencil, depthValue, stencilValue);
    d.shadow.invalidate();  // the next draw sets every state again (masks, scissor)
}

void generateMips(Texture& texture) {
    GraphicsDevice::Impl& d = deviceImpl(texture.device());
    d.resolvePendingClearBeforeRead(&texture);
    if (texture.LevelCount() > 1) d.backend->generateMipmaps(texture.backendObject());
}

void copyTexture(Texture& destination, const Texture& source) {
    GraphicsDevice::Impl& d = deviceImpl(destination.device());
    if (destination.Format() != source.Format() || destination.LevelCount() != source.LevelCount() ||
        destination.kind() != source.kind())
        throw ArgumentError("CopyResource: the textures differ in format, kind or level count");
    if (destination.sampleCount() != source.sampleCount())
        throw ArgumentError("CopyResource: the textures differ in sample count (a multisampled texture is read through ResolveSubresource)");
    d.resolvePendingClearBeforeRead(&source);
    const bool cube = source.kind() == Texture::Kind::TextureCube;
    for (int level = 0; level < source.LevelCount(); ++level) {
        const Rectangle size = d.backend->textureLevelSize(source.backendObject(), level);
        const Rectangle destinationSize = d.backend->textureLevelSize(destination.backendObject(), level);
        if (size.Width != destinationSize.Width || size.Height != destinationSize.Height)
            throw ArgumentError("CopyResource: the textures differ in size");
        TextureCopy copy;
        copy.source = source.backendObject();
        copy.destination = destination.backendObject();
        copy.cube = cube;
        copy.multisampled = source.sampleCount() > 0;
        copy.sourceLevel = copy.destinationLevel = level;
        copy.width = size.Width;
        copy.height = size.Height;
        d.backend->copyTexture(copy);
    }
}

void copyTextureRegion(Texture& destination, int destinationLevel, int x, int y, const Texture& source, int sourceLevel,
                       const Rectangle& area) {
    if (destination.Format() != source.Format()) throw ArgumentError("CopySubresourceRegion: the textures differ in format");
    if (destination.kind() != Texture::Kind::Texture2D || source.kind() != Texture::Kind::Texture2D)
        throw ArgumentError("CopySubresourceRegion: fxport copies regions of 2D textures only");
    if (destination.sampleCount() > 0 || source.sampleCount() > 0)
        throw ArgumentError("CopySubresourceRegion: fxport copies regions of single-sample textures only");
    if (sourceLevel < 0 || sourceLevel >= source.LevelCount() || destinationLevel < 0 || destinationLevel >= destination.LevelCount())
        throw ArgumentError("CopySubresourceRegion: level " + std::to_string(sourceLevel) + " -> " + std::to_string(destinationLevel) +
                            " is outside the textures' levels");
    GraphicsDevice::Impl& d = deviceImpl(destination.device());
    const Rectangle sourceSize = d.backend->textureLevelSize(source.backendObject(), sourceLevel);
    const Rectangle destinationSize = d.backend->textureLevelSize(destination.backendObject(), destinationLevel);
    const int sw = sourceSize.Width, sh = sourceSize.Height, dw = destinationSize.Width, dh = destinationSize.Height;
    if (area.X < 0 || area.Y < 0 || area.Width <= 0 || area.Height <= 0 || area.X + area.Width > sw || area.Y + area.Height > sh)
        throw ArgumentError("CopySubresourceRegion: the source box (" + std::to_string(area.X) + ", " + std::to_string(area.Y) + ") " +
                            std::to_string(area.Width) + "x" + std::to_string(area.Height) + " is outside its " + std::to_string(sw) + "x" +
                            std::to_string(sh) + " level");
    if (x < 0 || y < 0 || x + area.Width > dw || y + area.Height > dh)
        throw ArgumentError("CopySubresourceRegion: (" + std::to_string(x) + ", " + std::to_string(y) + ") + " + std::to_string(area.Width) + "x" +
                            std::to_string(area.Height) + " is outside the destination's " + std::to_string(dw) + "x" + std::to_string(dh) + " level");
    d.resolvePendingClearBeforeRead(&source);
    d.resolvePendingClearBeforeRead(&destination);
    d.storageBarrier();
    TextureCopy copy;
    copy.source = source.backendObject();
    copy.destination = destination.backendObject();
    copy.sourceLevel = sourceLevel;
    copy.destinationLevel = destinationLevel;
    copy.sourceX = area.X;
    copy.sourceY = area.Y;
    copy.destinationX = x;
    copy.destinationY = y;
    copy.width = area.Width;
    copy.height = area.Height;
    d.backend->copyTexture(copy);
}

}  // namespace fxport::core
