// D3D11 unordered-access views and buffer shader-resource views: the slots the host fills
// (GraphicsDevice::SetUnorderedAccess / SetShaderResource) and their binding at each draw and
// dispatch. xlate's reflection (xlate::StorageBinding) says, per shader, which register each
// RWStructuredBuffer / RWTexture2D / StructuredBuffer reads and which GL SSBO binding or image unit
// it was given; this file binds the slot's object there and places the barriers the backend
// needs between a shader's writes and whatever reads them next.
#include <string>

#include "device/device_impl.h"
#include "device/surface_formats.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/structured_buffer.h"
#include "fxport/graphics/texture.h"
#include "fxport/graphics/texture_1d.h"
#include "fxport/xlate/compiled_effect.h"

namespace fxport {

namespace {

std::string slotOutside(const char* call, int slot, int count) {
    return std::string(call) + ": slot " + std::to_string(slot) + " is outside 0.." + std::to_string(count - 1);
}

std::string registerName(const xlate::StorageBinding& b) { return std::string(1, b.registerClass) + std::to_string(b.slot); }

// What a binding reads or writes, and what a slot holds, in the words of the messages.
const char* kindName(xlate::StorageKind kind) {
    switch (kind) {
    case xlate::StorageKind::Image: return "texture";
    case xlate::StorageKind::TexelBuffer:
    case xlate::StorageKind::ImageBuffer: return "typed buffer";
    case xlate::StorageKind::Buffer: break;
    }
    return "buffer";
}
// D3D reads an integer view through a shader's other integer type bit for bit (an R32_SINT UAV as
// RWBuffer<uint>): the integer format of `format`'s size and channels that the shader declares
// (`shaderFormat`, "r32ui"), or `format` itself when there is none.
SurfaceFormat sameBitsAs(Backend& backend, SurfaceFormat format, const std::string& shaderFormat) {
    if (!isIntegerFormat(format)) return format;
    for (int f = 0; f <= int(SurfaceFormat::Depth16); ++f) {
        const SurfaceFormat other = SurfaceFormat(f);
        if (isIntegerFormat(other) && bytesPerPixel(other) == bytesPerPixel(format) && channelCount(other) == channelCount(format) &&
            shaderFormat == backend.imageFormatName(other))
            return other;
    }
    return format;
}

const char* heldName(const GraphicsDevice::Impl::StorageSlot& slot) { return slot.typedBuffer ? "typed buffer" : slot.image ? "texture" : "buffer"; }

// Any texture a shader writes as an image: its level 0 (a 1D array's every layer).
void setTextureUnorderedAccess(GraphicsDevice& device, GraphicsDevice::Impl& impl, int slot, Texture* texture) {
    if (slot < 0 || slot >= kMaxUnorderedAccessSlots) throw ArgumentError(slotOutside("SetUnorderedAccess", slot, kMaxUnorderedAccessSlots));
    if (!texture) {
        impl.unorderedAccess[std::size_t(slot)] = {};
        return;
    }
    if (&texture->device() != &device) throw InvalidOperation("SetUnorderedAccess: the texture was made by another GraphicsDevice");
    if (texture->IsDisposed()) throw InvalidOperation("SetUnorderedAccess: the texture was disposed");
    if (!*impl.backend->imageFormatName(texture->Format()))
        throw ArgumentError("SetUnorderedAccess: " + (texture->Name.empty() ? std::string("the texture") : "texture '" + texture->Name + "'") +
                            " has format " + surfaceFormatName(texture->Format()) +
                            ", which shaders cannot write as a RWTexture2D on GL (use Single, Vector2, Vector4, HalfSingle, HalfVector2, "
                            "HalfVector4, Color or Rgba64)");
    impl.unorderedAccess[std::size_t(slot)] = GraphicsDevice::Impl::StorageSlot{texture, texture->backendObject(), true, texture->Format()};
}

}  // namespace

void GraphicsDevice::SetUnorderedAccess(int slot, StructuredBuffer* buffer) {
    if (slot < 0 || slot >= kMaxUnorderedAccessSlots) throw ArgumentError(slotOutside("SetUnorderedAccess", slot, kMaxUnorderedAccessSlots));
    if (buffer && &buffer->device() != this) throw InvalidOperation("SetUnorderedAccess: the buffer was made by another GraphicsDevice");
    if (buffer && buffer->IsDisposed()) throw InvalidOperation("SetUnorderedAccess: the buffer was disposed");
    impl_->unorderedAccess[std::size_t(slot)] = buffer ? Impl::StorageSlot{buffer, buffer->backendObject(), false, SurfaceFormat::Color} : Impl::StorageSlot{};
}

void GraphicsDevice::SetUnorderedAccess(int slot, Texture2D* texture) { setTextureUnorderedAccess(*this, *impl_, slot, texture); }
void GraphicsDevice::SetUnorderedAccess(int slot, Texture1D* texture) { setTextureUnorderedAccess(*this, *impl_, slot, texture); }


void GraphicsDevice::SetShaderResource(int slot, StructuredBuffer* buffer) {
    if (slot < 0 || slot >= kMaxShaderResourceBuffers) throw ArgumentError(slotOutside("SetShaderResource", slot, kMaxShaderResourceBuffers));
    if (buffer && &buffer->device() != this) throw InvalidOperation("SetShaderResource: the buffer was made by another GraphicsDevice");
    if (buffer && buffer->IsDisposed()) throw InvalidOperation("SetShaderResource: the buffer was disposed");
    impl_->resourceBuffers[std::size_t(slot)] = buffer ? Impl::StorageSlot{buffer, buffer->backendObject(), false, SurfaceFormat::Color} : Impl::StorageSlot{};
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
            const std::string wanted = kindName(b.kind);
            if (!slot.name)
                throw InvalidOperation(use + ", but nothing is set there (" + setter + "(" + std::to_string(b.slot) + ", " + wanted + "))");
            if (wanted != heldName(slot))
                throw InvalidOperation(use + ", a " + wanted + ", but slot " + std::to_string(b.slot) + " holds a " + heldName(slot));
            if (b.kind == xlate::StorageKind::Image || b.kind == xlate::StorageKind::ImageBuffer) {
                const char* has = backend->imageFormatName(slot.format);
                const SurfaceFormat as = b.format.empty() || b.format == has ? slot.format : sameBitsAs(*backend, slot.format, b.format);
                if (as == slot.format && !b.format.empty() && b.format != has)
                    throw InvalidOperation(use + " as " + b.format + " texels, but the " + wanted + " in slot " + std::to_string(b.slot) + " holds " +
                                           has + " texels; declare the RWTexture2D / RWBuffer with the element type of its format");
                backend->bindStorageImage(b.binding, slot.name, as, b.writes);
            } else if (b.kind == xlate::StorageKind::TexelBuffer) {
                backend->bindTexture(b.binding, slot.name);
            } else {
                backend->bindStorageBuffer(b.binding, slot.name, slot.offset, slot.bytes);
            }
            writes |= b.writes;
        }
    }
    return writes;
}

void GraphicsDevice::Impl::storageBarrier() {
    if (!storageDirty) return;
    backend->storageBarrier();
    storageDirty = false;
}

void GraphicsDevice::Impl::forgetStorage(const GraphicsResource* resource) {
    for (StorageSlot& s : unorderedAccess)
        if (s.resource == resource) s = {};
    for (StorageSlot& s : resourceBuffers)
        if (s.resource == resource) s = {};
}

}  // namespace fxport
