#include "fxport/graphics/vertex_buffer.h"

#include <algorithm>

#include "device/device_impl.h"
#include "fxport/graphics/errors.h"

namespace fxport {

namespace {

// Checks a SetData/GetData range and returns its byte size.
std::size_t checkedRange(const std::string& who, const char* call, long long offset, std::size_t elementSize,
                         std::size_t count, std::size_t capacity) {
    if (offset < 0) throw ArgumentError(who + ": " + call + " at byte offset " + std::to_string(offset) + ", which is negative");
    // In this order nothing wraps: a count of 2^62 elements is not "0 bytes".
    if (elementSize != 0 && count > capacity / elementSize)
        throw ArgumentError(who + ": " + call + " of " + std::to_string(count) + " elements of " + std::to_string(elementSize) +
                            " bytes overruns the buffer's " + std::to_string(capacity) + " bytes");
    std::size_t bytes = elementSize * count;
    if (std::size_t(offset) > capacity - bytes)
        throw ArgumentError(who + ": " + call + " of " + std::to_string(count) + " elements of " +
                            std::to_string(elementSize) + " bytes at byte " + std::to_string(offset) +
                            " overruns the buffer's " + std::to_string(capacity) + " bytes");
    return bytes;
}

// A buffer's size, refused above kMaxBufferBytes: GL would fail the allocation silently
// (GL_OUT_OF_MEMORY) and every later SetData and draw would use a buffer that is not there.
constexpr long long kMaxBufferBytes = 1LL << 30;
void checkBufferSize(const std::string& who, long long count, long long elementBytes) {
    if (count * elementBytes > kMaxBufferBytes)
        throw ArgumentError(who + ": " + std::to_string(count) + " elements of " + std::to_string(elementBytes) + " bytes are " +
                            std::to_string(count * elementBytes) + " bytes; fxport makes buffers of at most " +
                            std::to_string(kMaxBufferBytes >> 20) + " MiB");
}

}  // namespace

VertexBuffer::VertexBuffer(fxport::GraphicsDevice& device, const fxport::VertexDeclaration& declaration,
                           int vertexCount, fxport::BufferUsage usage)
    : GraphicsResource(device, "VertexBuffer"), declaration_(declaration), count_(vertexCount), usage_(usage) {
    if (vertexCount <= 0 || declaration.VertexStride() <= 0)
        throw ArgumentError(describe() + ": vertex count " + std::to_string(vertexCount) + " and stride " +
                            std::to_string(declaration.VertexStride()) + " must both be positive");
    checkBufferSize(describe(), vertexCount, declaration.VertexStride());
    name_ = deviceImpl(device).createBuffer();
    deviceImpl(device).backend->allocateBuffer(name_, std::size_t(vertexCount) * std::size_t(declaration.VertexStride()), nullptr, false);
}

VertexBuffer::~VertexBuffer() { disposeFromDestructor(); }

void VertexBuffer::releaseGpuObjects() {
    fxport::GraphicsDevice& d = device();
    if (deviceImpl(d).vertexBuffer == this) deviceImpl(d).vertexBuffer = nullptr;
    deviceImpl(d).deleteBuffer(name_);
}

void VertexBuffer::setData(int offsetInBytes, const void* data, std::size_t elementSize, std::size_t count) {
    throwIfDisposed("SetData");
    std::size_t capacity = std::size_t(count_) * std::size_t(declaration_.VertexStride());
    std::size_t bytes = checkedRange(describe(), "SetData", offsetInBytes, elementSize, count, capacity);
    deviceImpl(device()).backend->writeBuffer(name_, std::size_t(offsetInBytes), bytes, data);
}

void VertexBuffer::getData(void* data, std::size_t elementSize, std::size_t count) const {
    throwIfDisposed("GetData");
    std::size_t capacity = std::size_t(count_) * std::size_t(declaration_.VertexStride());
    std::size_t bytes = checkedRange(describe(), "GetData", 0, elementSize, count, capacity);
    deviceImpl(device()).backend->readBuffer(name_, 0, bytes, data);
}

IndexBuffer::IndexBuffer(fxport::GraphicsDevice& device, fxport::IndexElementSize elementSize, int indexCount,
                         fxport::BufferUsage usage)
    : GraphicsResource(device, "IndexBuffer"), elementSize_(elementSize), count_(indexCount), usage_(usage) {
    if (indexCount <= 0) throw ArgumentError(describe() + ": index count " + std::to_string(indexCount) + " must be positive");
    checkBufferSize(describe(), indexCount, elementBytes());
    name_ = deviceImpl(device).createBuffer();
    deviceImpl(device).backend->allocateBuffer(name_, std::size_t(indexCount) * std::size_t(elementBytes()), nullptr, false);
}

IndexBuffer::~IndexBuffer() { disposeFromDestructor(); }

void IndexBuffer::releaseGpuObjects() {
    fxport::GraphicsDevice& d = device();
    if (d.Indices == this) d.Indices = nullptr;
    deviceImpl(d).deleteBuffer(name_);
}

void IndexBuffer::setData(int offsetInBytes, const void* data, std::size_t elementSize, std::size_t count) {
    throwIfDisposed("SetData");
    if (elementSize != std::size_t(elementBytes()))
        throw ArgumentError(describe() + ": SetData with " + std::to_string(elementSize * 8) + "-bit indices into a " +
                            std::to_string(elementBytes() * 8) + "-bit index buffer");
    std::size_t bytes = checkedRange(describe(), "SetData", offsetInBytes, elementSize, count,
                                     std::size_t(count_) * std::size_t(elementBytes()));
    deviceImpl(device()).backend->writeBuffer(name_, std::size_t(offsetInBytes), bytes, data);
}

void IndexBuffer::getData(void* data, std::size_t elementSize, std::size_t count) const {
    throwIfDisposed("GetData");
    if (elementSize != std::size_t(elementBytes()))
        throw ArgumentError(describe() + ": GetData with " + std::to_string(elementSize * 8) + "-bit indices from a " +
                            std::to_string(elementBytes() * 8) + "-bit index buffer");
    std::size_t bytes = checkedRange(describe(), "GetData", 0, elementSize, count,
                                     std::size_t(count_) * std::size_t(elementBytes()));
    deviceImpl(device()).backend->readBuffer(name_, 0, bytes, data);
}

std::vector<std::uint32_t> IndexBuffer::GetIndices() const {
    std::vector<std::uint32_t> indices(static_cast<std::size_t>(count_));
    if (elementSize_ == fxport::IndexElementSize::ThirtyTwoBits) {
        getData(indices.data(), 4, indices.size());
    } else {
        std::vector<std::uint16_t> narrow(indices.size());
        getData(narrow.data(), 2, narrow.size());
        std::copy(narrow.begin(), narrow.end(), indices.begin());
    }
    return indices;
}

}  // namespace fxport
