// The device core's entry points for front ends other than XNA's (front_end_core.h). Each one
// reuses the device's own machinery -- the GL object bookkeeping, flush() with its state shadow,
// the vertex-array cache, target binding, lazy depth storage -- and adds only the GL calls XNA's
// classes do not make (byte buffers by slot, instanced draws, clearing a texture or a depth buffer
// that is not bound).
#include "device/front_end_core.h"

#include <algorithm>
#include <string>

#include "device/device_impl.h"
#include "fxport/graphics/errors.h"
#include "fxport/xlate/compiled_effect.h"
#include "gl/gl_formats.h"

namespace fxport::core {

namespace {

GLenum glPrimitiveOf(PrimitiveType type) {
    switch (type) {
    case PrimitiveType::TriangleList: return GL_TRIANGLES;
    case PrimitiveType::TriangleStrip: return GL_TRIANGLE_STRIP;
    case PrimitiveType::LineList: return GL_LINES;
    case PrimitiveType::LineStrip: return GL_LINE_STRIP;
    case PrimitiveType::PointList: return GL_POINTS;
    }
    return GL_TRIANGLES;
}

// Framebuffers keyed with this renderbuffer as their depth attachment (graphics_device.cpp's key:
// colour entries name << 8 | face, the depth entry name << 8 | 0xff).
void dropFramebuffersWithDepth(GraphicsDevice::Impl& d, GLuint renderbuffer) {
    if (renderbuffer == 0) return;
    for (auto it = d.framebuffers.begin(); it != d.framebuffers.end();) {
        const std::uint64_t depthKey = it->first.back();
        if (GLuint(depthKey >> 8) != renderbuffer) {
            ++it;
            continue;
        }
        if (d.boundFramebuffer == it->second) {
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            d.boundFramebuffer = 0;
        }
        glDeleteFramebuffers(1, &it->second);
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
    name_ = deviceImpl(device).createBuffer();
    std::vector<std::uint8_t> zeros;
    if (!initial) zeros.assign(bytes, 0);
    glNamedBufferStorage(name_, GLsizeiptr(bytes), initial ? initial : zeros.data(),
                         GL_DYNAMIC_STORAGE_BIT | (dynamic ? GL_CLIENT_STORAGE_BIT : 0));
}

ByteBuffer::~ByteBuffer() { disposeFromDestructor(); }

void ByteBuffer::releaseGpuObjects() { deviceImpl(device()).deleteBuffer(name_); }

void ByteBuffer::write(std::size_t offset, std::size_t bytes, const void* data) {
    throwIfDisposed("write");
    if (offset > size_ || bytes > size_ - offset)
        throw ArgumentError(describe() + ": bytes [" + std::to_string(offset) + ", " + std::to_string(offset + bytes) +
                            ") are outside its " + std::to_string(size_));
    if (bytes) glNamedBufferSubData(name_, GLintptr(offset), GLsizeiptr(bytes), data);
}

void ByteBuffer::read(std::size_t offset, std::size_t bytes, void* out) const {
    throwIfDisposed("read");
    if (offset > size_ || bytes > size_ - offset)
        throw ArgumentError(describe() + ": bytes [" + std::to_string(offset) + ", " + std::to_string(offset + bytes) +
                            ") are outside its " + std::to_string(size_));
    if (bytes) glGetNamedBufferSubData(name_, GLintptr(offset), GLsizeiptr(bytes), out);
}

void ByteBuffer::copyFrom(const ByteBuffer& source) {
    throwIfDisposed("copy");
    if (source.size_ != size_)
        throw ArgumentError(describe() + ": copy from a buffer of " + std::to_string(source.size_) + " bytes into " +
                            std::to_string(size_));
    glCopyNamedBufferSubData(source.name_, name_, 0, 0, GLsizeiptr(size_));
}

// --- DepthBuffer

DepthBuffer::DepthBuffer(GraphicsDevice& device, int width, int height, DepthFormat format)
    : GraphicsResource(device, "DepthBuffer") {
    if (format == DepthFormat::None || width <= 0 || height <= 0)
        throw ArgumentError(describe() + ": " + std::to_string(width) + "x" + std::to_string(height) + " " +
                            depthFormatName(format) + " is not a depth buffer");
    storage_.format = format;
    storage_.width = width;
    storage_.height = height;
    deviceImpl(device).adoptDepthStorage(storage_);
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
    const GLenum stage = s.profile.stage == xlate::ShaderStage::Vertex  ? GL_VERTEX_SHADER
                         : s.profile.stage == xlate::ShaderStage::Pixel ? GL_FRAGMENT_SHADER
                                                                        : GL_GEOMETRY_SHADER;
    program_->stage = int(s.profile.stage);
    program_->shader = &s;
    program_->label = label;
    program_->mayDiscard = s.glsl.find("discard") != std::string::npos;
    program_->program = deviceImpl(device).createProgram(stage, s.glsl, label);
}

ShaderCode::~ShaderCode() { disposeFromDestructor(); }

const xlate::CompiledShader& ShaderCode::shader() const { return *program_->shader; }

void ShaderCode::releaseGpuObjects() {
    GraphicsDevice::Impl& d = deviceImpl(device());
    for (const ShaderProgram*& s : d.shaders)
        if (s == program_.get()) s = nullptr;
    d.deleteProgram(program_->program);
}

// --- binding

void setShaders(GraphicsDevice& device, const ShaderCode& vertexShader, const ShaderCode& pixelShader) {
    GraphicsDevice::Impl& d = deviceImpl(device);
    d.shaders = {&vertexShader.program(), &pixelShader.program(), nullptr};
    d.emulation = PassEmulation{};
    d.passApplied = true;
}

void setUniformBuffer(GraphicsDevice& device, int stage, int glBinding, const ByteBuffer* buffer) {
    if (stage < 0 || stage >= kStageCount || glBinding < 0 || glBinding >= kUniformBindingsPerStage || glBinding == kInternalBlockBinding)
        throw ArgumentError("uniform binding " + std::to_string(glBinding) + " of stage " + std::to_string(stage) +
                            " is not one a front end may set");
    deviceImpl(device).wantedUniformBuffers[std::size_t(uniformBindingFor(stage, glBinding))] = buffer ? buffer->glName() : 0;
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

// --- draws

void draw(GraphicsDevice& device, const VertexStream& vertices, const DrawArguments& a) {
    GraphicsDevice::Impl& d = deviceImpl(device);
    if (!vertices.declaration) throw InvalidOperation("Draw: no input layout");
    if (a.count <= 0 || a.instances <= 0) return;  // D3D draws nothing
    d.flush("Draw");
    GraphicsDevice::Impl::VertexArray& va = d.vertexArrayFor(*vertices.declaration);
    const GLuint buffer = vertices.buffer ? vertices.buffer->glName() : 0;
    const GLintptr offset = GLintptr(vertices.offset);
    const GLsizei stride = GLsizei(vertices.declaration->VertexStride());
    if (va.buffer != buffer || va.offset != offset || va.stride != stride) {
        va.buffer = buffer;
        va.offset = offset;
        va.stride = stride;
        glVertexArrayVertexBuffer(va.vao, 0, buffer, offset, stride);
    }
    const GLenum mode = glPrimitiveOf(a.type);
    if (a.indices) {
        if (va.elements != a.indices->glName()) {
            va.elements = a.indices->glName();
            glVertexArrayElementBuffer(va.vao, va.elements);
        }
        const GLenum type = a.indexSize == 4 ? GL_UNSIGNED_INT : GL_UNSIGNED_SHORT;
        const void* first = reinterpret_cast<const void*>(std::uintptr_t(a.first) * std::uintptr_t(a.indexSize));
        glDrawElementsInstancedBaseVertexBaseInstance(mode, a.count, type, first, a.instances, a.baseVertex,
                                                      GLuint(a.firstInstance));
    } else {
        glDrawArraysInstancedBaseInstance(mode, a.first, a.count, a.instances, GLuint(a.firstInstance));
    }
}

// --- clears and copies

void clearTexture(Texture& texture, const Vector4& color) {
    GraphicsDevice::Impl& d = deviceImpl(texture.device());
    // A clear of this target still pending in the device would land after ours.
    d.resolvePendingClearBeforeRead(&texture);
    const float rgba[4] = {color.X, color.Y, color.Z, color.W};
    glClearTexImage(texture.glName(), 0, GL_RGBA, GL_FLOAT, rgba);
}

void clearDepthBuffer(GraphicsDevice& device, DepthBuffer& buffer, bool depth, bool stencil, float depthValue,
                      int stencilValue) {
    DepthStorage& s = buffer.storage();
    const bool hasStencil = s.format == DepthFormat::Depth24Stencil8;
    stencil = stencil && hasStencil;
    if (!depth && !stencil) return;
    if (s.renderbuffer == 0) {  // not made yet: the clear waits on it (depth_storage.cpp)
        s.waitingClear |= (depth ? unsigned(ClearOptions::DepthBuffer) : 0u) | (stencil ? unsigned(ClearOptions::Stencil) : 0u);
        if (depth) s.clearDepth = depthValue;
        if (stencil) s.clearStencil = stencilValue;
        return;
    }
    // A framebuffer of its own, so that neither the bound targets nor the viewport matter.
    GLuint fbo = 0;
    glCreateFramebuffers(1, &fbo);
    glNamedFramebufferRenderbuffer(fbo, hasStencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                   s.renderbuffer);
    glNamedFramebufferDrawBuffer(fbo, GL_NONE);
    // glClear* honour the write masks and the scissor: the shadowed state says what GL has now.
    GraphicsDevice::Impl& d = deviceImpl(device);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glDisable(GL_SCISSOR_TEST);
    const GLfloat clamped = std::clamp(depthValue, 0.0f, 1.0f);
    if (depth && stencil) glClearNamedFramebufferfi(fbo, GL_DEPTH_STENCIL, 0, clamped, stencilValue);
    else if (depth) glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &clamped);
    else glClearNamedFramebufferiv(fbo, GL_STENCIL, 0, &stencilValue);
    glDeleteFramebuffers(1, &fbo);
    d.shadow.invalidate();  // the next draw sets every state again (masks, scissor)
}

void generateMips(Texture& texture) {
    deviceImpl(texture.device()).resolvePendingClearBeforeRead(&texture);
    if (texture.LevelCount() > 1) glGenerateTextureMipmap(texture.glName());
}

void copyTexture(Texture& destination, const Texture& source) {
    GraphicsDevice::Impl& d = deviceImpl(destination.device());
    if (destination.Format() != source.Format() || destination.LevelCount() != source.LevelCount() ||
        destination.kind() != source.kind())
        throw ArgumentError("CopyResource: the textures differ in format, kind or level count");
    d.resolvePendingClearBeforeRead(&source);
    const GLenum target = source.kind() == Texture::Kind::TextureCube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
    for (int level = 0; level < source.LevelCount(); ++level) {
        GLint w = 0, h = 0, wd = 0, hd = 0;
        glGetTextureLevelParameteriv(source.glName(), level, GL_TEXTURE_WIDTH, &w);
        glGetTextureLevelParameteriv(source.glName(), level, GL_TEXTURE_HEIGHT, &h);
        glGetTextureLevelParameteriv(destination.glName(), level, GL_TEXTURE_WIDTH, &wd);
        glGetTextureLevelParameteriv(destination.glName(), level, GL_TEXTURE_HEIGHT, &hd);
        if (w != wd || h != hd) throw ArgumentError("CopyResource: the textures differ in size");
        glCopyImageSubData(source.glName(), target, level, 0, 0, 0, destination.glName(), target, level, 0, 0, 0, w, h,
                           target == GL_TEXTURE_CUBE_MAP ? 6 : 1);
    }
}

}  // namespace fxport::core
