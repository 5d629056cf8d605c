// XNA's SetVertexBuffers and DrawInstancedPrimitives: several vertex buffers at once, drawn through
// the device core's streams (front_end_core.h), which match each element to the vertex shader's
// input of its semantic whichever buffer holds it, and advance a buffer with an InstanceFrequency
// once per that many instances. One buffer without instancing keeps SetVertexBuffer's path.
#include <string>
#include <vector>

#include "device/device_impl.h"
#include "device/front_end_core.h"
#include "device/primitive_counts.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/graphics_device.h"

namespace fxport {

namespace {

void checkBinding(const GraphicsDevice& device, const VertexBufferBinding& b, std::size_t index) {
    const std::string who = "GraphicsDevice.SetVertexBuffers: binding " + std::to_string(index);
    if (!b.VertexBuffer) throw ArgumentError(who + " has no vertex buffer");
    if (b.VertexBuffer->IsDisposed()) throw InvalidOperation(who + ": the buffer was disposed");
    if (&b.VertexBuffer->device() != &device) throw InvalidOperation(who + ": its vertex buffer was made by another GraphicsDevice");
    if (b.VertexOffset < 0 || b.VertexOffset >= b.VertexBuffer->VertexCount())
        throw ArgumentError(who + ": vertex offset " + std::to_string(b.VertexOffset) + " is outside the buffer's " +
                            std::to_string(b.VertexBuffer->VertexCount()) + " vertices");
    if (b.InstanceFrequency < 0) throw ArgumentError(who + ": InstanceFrequency " + std::to_string(b.InstanceFrequency) + " is negative");
}

}  // namespace

void GraphicsDevice::SetVertexBuffers(const std::vector<VertexBufferBinding>& bindings) {
    if (bindings.size() > std::size_t(kMaxVertexBufferBindings))
        throw ArgumentError("GraphicsDevice.SetVertexBuffers: " + std::to_string(bindings.size()) + " bindings; at most " +
                            std::to_string(kMaxVertexBufferBindings));
    for (std::size_t i = 0; i < bindings.size(); ++i) checkBinding(*this, bindings[i], i);
    Impl& d = *impl_;
    d.vertexBindings = bindings;
    d.vertexBuffer = bindings.empty() ? nullptr : bindings[0].VertexBuffer;
    d.vertexOffset = bindings.empty() ? 0 : bindings[0].VertexOffset;
}

std::vector<VertexBufferBinding> GraphicsDevice::GetVertexBuffers() const { return impl_->vertexBindings; }

void GraphicsDevice::DrawInstancedPrimitives(PrimitiveType primitiveType, int baseVertex, int, int, int startIndex, int primitiveCount,
                                             int instanceCount) {
    const char* call = "DrawInstancedPrimitives";
    if (impl_->vertexBindings.empty()) throw InvalidOperation("DrawInstancedPrimitives: no vertex buffer set (SetVertexBuffers)");
    if (!Indices) throw InvalidOperation("DrawInstancedPrimitives: no index buffer set (GraphicsDevice.Indices)");
    if (Indices->IsDisposed()) throw InvalidOperation("DrawInstancedPrimitives: the index buffer was disposed");
    if (&Indices->device() != this) throw InvalidOperation("DrawInstancedPrimitives: the index buffer was made by another GraphicsDevice");
    checkPrimitiveType(primitiveType, call);
    const int count = vertexCountFor(primitiveType, primitiveCount);
    if (primitiveCount <= 0 || startIndex < 0 || startIndex + count > Indices->IndexCount())
        throw ArgumentError("DrawInstancedPrimitives: " + std::to_string(primitiveCount) + " primitives from index " +
                            std::to_string(startIndex) + " need " + std::to_string(count) + " indices; the index buffer has " +
                            std::to_string(Indices->IndexCount()));
    if (instanceCount <= 0) throw ArgumentError("DrawInstancedPrimitives: instanceCount " + std::to_string(instanceCount) + " must be positive");
    impl_->drawBindings(call, primitiveType, count, startIndex, baseVertex, true, instanceCount);
}

void GraphicsDevice::Impl::drawBindings(const char* call, PrimitiveType type, int count, int first, int baseVertex, bool indexed, int instances) {
    std::vector<core::StreamLayout> layouts;
    layouts.reserve(vertexBindings.size());  // the streams point into it
    std::vector<core::InstancedStream> streams;
    for (const VertexBufferBinding& b : vertexBindings) {
        if (b.VertexBuffer->IsDisposed()) throw InvalidOperation(std::string(call) + ": a bound vertex buffer was disposed");
        layouts.push_back(core::streamLayoutOf(b.VertexBuffer->VertexDeclaration()));
        core::InstancedStream s;
        s.vertices.layout = &layouts.back();
        s.vertices.object = b.VertexBuffer->backendObject();
        s.vertices.offset = std::size_t(b.VertexOffset) * std::size_t(layouts.back().stride);
        s.instanceStepRate = b.InstanceFrequency;
        streams.push_back(s);
    }
    core::DrawArguments a;
    a.type = type;
    a.count = count;
    a.first = first;
    a.baseVertex = baseVertex;
    a.instances = instances;
    if (indexed) {
        a.indexObject = device.Indices->backendObject();
        a.indexSize = device.Indices->IndexElementSize() == IndexElementSize::ThirtyTwoBits ? 4 : 2;
    }
    core::drawStreams(device, streams, a);
}

}  // namespace fxport
