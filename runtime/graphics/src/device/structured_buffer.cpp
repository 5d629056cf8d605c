// StructuredBuffer: a GL buffer object that shaders see as an SSBO (see structured_buffer.h).
#include "fxport/graphics/structured_buffer.h"

#include "device/device_impl.h"
#include "fxport/graphics/errors.h"

namespace fxport {

namespace {

constexpr long long kMaxStructuredBufferBytes = 1LL << 30;  // as VertexBuffer: refused rather than a silent GL_OUT_OF_MEMORY

}  // namespace

StructuredBuffer::StructuredBuffer(fxport::GraphicsDevice& device, int elementStride, int elementCount)
    : GraphicsResource(device, "StructuredBuffer"), stride_(elementStride), count_(elementCount) {
    if (elementStride <= 0 || elementStride % 4 != 0 || elementStride > 2048)
        throw ArgumentError(describe() + ": element stride " + std::to_string(elementStride) +
                            " must be a positive multiple of 4 bytes, at most 2048 (D3D11's structured-buffer rule)");
    if (elementCount <= 0) throw ArgumentError(describe() + ": element count " + std::to_string(elementCount) + " must be positive");
    if (static_cast<long long>(elementStride) * elementCount > kMaxStructuredBufferBytes)
        throw ArgumentError(describe() + ": " + std::to_string(elementCount) + " elements of " + std::to_string(elementStride) +
                            " bytes exceed the " + std::to_string(kMaxStructuredBufferBytes >> 20) + " MiB fxport makes buffers of");
    name_ = deviceImpl(device).createBuffer();
    // Zero-filled, as D3D11 leaves a buffer made without initial data (and shaders may read it first).
    std::vector<std::uint8_t> zeros(SizeInBytes(), 0);
    deviceImpl(device).backend->allocateBuffer(name_, SizeInBytes(), zeros.data(), false);
}

StructuredBuffer::~StructuredBuffer() { disposeFromDestructor(); }

void StructuredBuffer::releaseGpuObjects() {
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.forgetStorage(this);
    d.deleteBuffer(name_);
}

namespace {

void checkRange(const std::string& who, const char* call, std::size_t offset, std::size_t bytes, std::size_t capacity) {
    if (bytes > capacity || offset > capacity - bytes)
        throw ArgumentError(who + ": " + call + " of " + std::to_string(bytes) + " bytes at byte " + std::to_string(offset) +
                            " overruns the buffer's " + std::to_string(capacity) + " bytes");
}

}  // namespace

void StructuredBuffer::setBytes(std::size_t offset, const void* data, std::size_t bytes) {
    throwIfDisposed("SetData");
    checkRange(describe(), "SetData", offset, bytes, SizeInBytes());
    if (bytes == 0) return;
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.storageBarrier();  // a shader's writes land before this upload replaces them
    d.backend->writeBuffer(name_, offset, bytes, data);
}

void StructuredBuffer::getBytes(std::size_t offset, void* data, std::size_t bytes) const {
    throwIfDisposed("GetData");
    checkRange(describe(), "GetData", offset, bytes, SizeInBytes());
    if (bytes == 0) return;
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.storageBarrier();  // what a dispatch or draw wrote is what GetData returns
    d.backend->readBuffer(name_, offset, bytes, data);
}

}  // namespace fxport
