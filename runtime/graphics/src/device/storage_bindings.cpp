// D3D11 unordered-access views and buffer shader-resource views: the slots the host fills
// (GraphicsDevice::SetUnorderedAccess / SetShaderResource) and their binding at each draw and
// dispatch. xlate's reflection (xlate::StorageBinding) says, per shader, which register each
// RWStructuredBuffer / RWTexture2D / StructuredBuffer reads and which GL SSBO binding or image unit
// it was given; this file binds the slot's GL object there and places the barriers GL needs
// between a shader's writes and whatever reads them next.
#include <string>

#include "device/device_impl.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/structured_buffer.h"
#include "fxport/graphics/texture.h"
#include "fxport/xlate/compiled_effect.h"
#include "gl/gl_formats.h"

namespace fxport {

namespace {

// The GLSL format qualifier of the texture formats image units can hold; "" for the rest.
const char* imageFormatName(GLenum internalFormat) {
    switch (internalFormat) {
    case GL_R32F: return "r32f";
    case GL_RG32F: return "rg32f";
    case GL_RGBA32F: return "rgba32f";
    case GL_R16F: return "r16f";
    case GL_RG16F: return "rg16f";
    case GL_RGBA16F: return "rgba16f";
    case GL_RGBA8: return "rgba8";
    case GL_RGBA16: return "rgba16";
    case GL_RG16: return "rg16";
    case GL_R32UI: return "r32ui";
    case GL_R32I: return "r32i";
    case GL_RGBA32UI: return "rgba32ui";
    case GL_RGBA32I: return "rgba32i";
    default: return "";
    }
}

std::string slotOutside(const char* call, int slot, int count) {
    return std::string(call) + ": slot " + std::to_string(slot) + " is outside 0.." + std::to_string(count - 1);
}

std::string registerName(const xlate::StorageBinding& b) { return std::string(1, b.registerClass) + std::to_string(b.slot); }

}  // namespace

void GraphicsDevice::SetUnorderedAccess(int slot, StructuredBuffer* buffer) {
    if (slot < 0 || slot >= kMaxUnorderedAccessSlots) throw ArgumentError(slotOutside("SetUnorderedAccess", slot, kMaxUnorderedAccessSlots));
    if (buffer && &buffer->device() != this) throw InvalidOperation("SetUnorderedAccess: the buffer was made by another GraphicsDevice");
    if (buffer && buffer->IsDisposed()) throw InvalidOperation("SetUnorderedAccess: the buffer was disposed");
    impl_->unorderedAccess[std::size_t(slot)] = buffer ? Impl::StorageSlot{buffer, buffer->glName(), false, 0} : Impl::StorageSlot{};
}

void GraphicsDevice::SetUnorderedAccess(int slot, Texture2D* texture) {
    if (slot < 0 || slot >= kMaxUnorderedAccessSlots) throw ArgumentError(slotOutside("SetUnorderedAccess", slot, kMaxUnorderedAccessSlots));
    if (!texture) {
        impl_->unorderedAccess[std::size_t(slot)] = {};
        return;
    }
    if (&texture->device() != this) throw InvalidOperation("SetUnorderedAccess: the texture was made by another GraphicsDevice");
    if (texture->IsDisposed()) throw InvalidOperation("SetUnorderedAccess: the texture was disposed");
    GLenum format = detail::glFormat(texture->Format()).internalFormat;
    if (!*imageFormatName(format))
        throw ArgumentError("SetUnorderedAccess: " + (texture->Name.empty() ? std::string("the texture") : "texture '" + texture->Name + "'") +
                            " has format " + surfaceFormatName(texture->Format()) +
                            ", which shaders cannot write as a RWTexture2D on GL (use Single, Vector2, Vector4, HalfSingle, HalfVector2, "
                            "HalfVector4, Color or Rgba64)");
    impl_->unorderedAccess[std::size_t(slot)] = Impl::StorageSlot{texture, texture->glName(), true, format};
}

void GraphicsDevice::SetShaderResource(int slot, StructuredBuffer* buffer) {
    if (slot < 0 || slot >= kMaxShaderResourceBuffers) throw ArgumentError(slotOutside("SetShaderResource", slot, kMaxShaderResourceBuffers));
    if (buffer && &buffer->device() != this) throw InvalidOperation("SetShaderResource: the buffer was made by another GraphicsDevice");
    if (buffer && buffer->IsDisposed()) throw InvalidOperation("SetShaderResource: the buffer was disposed");
    impl_->resourceBuffers[std::size_t(slot)] = buffer ? Impl::StorageSlot{buffer, buffer->glName(), false, 0} : Impl::StorageSlot{};
}

bool GraphicsDevice::Impl::applyStorage(const ShaderProgram* const* programs, std::size_t count, const char* what) {
    bool writes = false;
    for (std::size_t p = 0; p < count; ++p) {
        const ShaderProgram* program = programs[p];
        if (!program) continue;
        for (const xlate::StorageBinding& b : program->shader->storage) {
            const bool uav = b.registerClass == 'u';
            const int slots = uav ? kMaxUnorderedAccessSlots : kMaxShaderResourceBuffers;
            const std::string use = std::string(what) + ": " + program->label + " uses '" + b.name + "' (register " + registerName(b) + ")";
            if (b.slot < 0 || b.slot >= slots)
                throw InvalidOperation(use + ", but fxport has " + (uav ? "UAV" : "buffer SRV") + " slots 0.." + std::to_string(slots - 1) + " only");
            const StorageSlot& slot = uav ? unorderedAccess[std::size_t(b.slot)] : resourceBuffers[std::size_t(b.slot)];
            const char* setter = uav ? "SetUnorderedAccess" : "SetShaderResource";
            const bool image = b.kind == xlate::StorageKind::Image;
            if (!slot.name)
                throw InvalidOperation(use + ", but nothing is set there (" + setter + "(" + std::to_string(b.slot) + ", " +
                                       (image ? "texture" : "buffer") + "))");
            if (slot.image != image)
                throw InvalidOperation(use + ", a " + (image ? "texture" : "buffer") + ", but slot " + std::to_string(b.slot) + " holds a " +
                                       (slot.image ? "texture" : "buffer"));
            if (image) {
                const char* has = imageFormatName(slot.format);
                if (!b.format.empty() && b.format != has)
                    throw InvalidOperation(use + " as " + b.format + " texels, but the texture in slot " + std::to_string(b.slot) + " holds " + has +
                                           " texels; declare the RWTexture2D with the element type of the texture's format");
                glBindImageTexture(GLuint(b.binding), slot.name, 0, GL_FALSE, 0, b.writes ? GL_READ_WRITE : GL_READ_ONLY, slot.format);
            } else {
                glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(b.binding), slot.name);
            }
            writes |= b.writes;
        }
    }
    return writes;
}

void GraphicsDevice::Impl::storageBarrier() {
    if (!storageDirty) return;
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    storageDirty = false;
}

void GraphicsDevice::Impl::forgetStorage(const GraphicsResource* resource) {
    for (StorageSlot& s : unorderedAccess)
        if (s.resource == resource) s = {};
    for (StorageSlot& s : resourceBuffers)
        if (s.resource == resource) s = {};
}

}  // namespace fxport
