// VertexBuffer and IndexBuffer: GPU buffers with XNA's SetData/GetData.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "fxport/graphics/graphics_resource.h"
#include "fxport/graphics/vertex_declaration.h"

namespace fxport {

// None = written once (or rarely); WriteOnly is a hint that GetData is not used.
enum class BufferUsage : std::uint8_t { None, WriteOnly };
enum class IndexElementSize : std::uint8_t { SixteenBits, ThirtyTwoBits };

class VertexBuffer : public GraphicsResource {
public:
    VertexBuffer(fxport::GraphicsDevice& device, const fxport::VertexDeclaration& declaration, int vertexCount,
                 BufferUsage usage = BufferUsage::None);
    ~VertexBuffer() override;

    int VertexCount() const { return count_; }
    const fxport::VertexDeclaration& VertexDeclaration() const { return declaration_; }
    fxport::BufferUsage BufferUsage() const { return usage_; }

    // sizeof(T) must equal the declaration's stride.
    template <class T> void SetData(const T* data, std::size_t count) { setData(0, data, sizeof(T), count); }
    template <class T> void SetData(const std::vector<T>& data) { SetData(data.data(), data.size()); }
    template <class T> void SetData(int offsetInBytes, const T* data, std::size_t count) {
        setData(offsetInBytes, data, sizeof(T), count);
    }
    template <class T> void GetData(T* data, std::size_t count) const { getData(data, sizeof(T), count); }

    void setData(int offsetInBytes, const void* data, std::size_t elementSize, std::size_t count);
    void getData(void* data, std::size_t elementSize, std::size_t count) const;
    std::uint32_t backendObject() const { return name_; }

protected:
    void releaseGpuObjects() override;

private:
    fxport::VertexDeclaration declaration_;
    int count_;
    fxport::BufferUsage usage_;
    std::uint32_t name_ = 0;
};

// XNA's VertexBufferBinding: a vertex buffer for GraphicsDevice::SetVertexBuffers, from vertex
// VertexOffset on, advancing once per vertex (InstanceFrequency 0) or once per InstanceFrequency
// instances (hardware instancing: DrawInstancedPrimitives). Its elements feed the vertex shader's
// inputs of their semantics, whichever buffer holds them.
struct VertexBufferBinding {
    fxport::VertexBuffer* VertexBuffer = nullptr;
    int VertexOffset = 0;
    int InstanceFrequency = 0;

    VertexBufferBinding() = default;
    VertexBufferBinding(fxport::VertexBuffer* buffer, int vertexOffset = 0, int instanceFrequency = 0)
        : VertexBuffer(buffer), VertexOffset(vertexOffset), InstanceFrequency(instanceFrequency) {}
    VertexBufferBinding(fxport::VertexBuffer& buffer, int vertexOffset = 0, int instanceFrequency = 0)
        : VertexBufferBinding(&buffer, vertexOffset, instanceFrequency) {}
    bool operator==(const VertexBufferBinding&) const = default;
};

class IndexBuffer : public GraphicsResource {
public:
    IndexBuffer(fxport::GraphicsDevice& device, fxport::IndexElementSize elementSize, int indexCount,
                BufferUsage usage = BufferUsage::None);
    ~IndexBuffer() override;

    int IndexCount() const { return count_; }
    fxport::IndexElementSize IndexElementSize() const { return elementSize_; }
    int elementBytes() const { return elementSize_ == fxport::IndexElementSize::SixteenBits ? 2 : 4; }

    // T must be a 16-bit integer for SixteenBits and a 32-bit integer for ThirtyTwoBits.
    template <class T> void SetData(const T* data, std::size_t count) { setData(0, data, sizeof(T), count); }
    template <class T> void SetData(const std::vector<T>& data) { SetData(data.data(), data.size()); }
    template <class T> void GetData(T* data, std::size_t count) const { getData(data, sizeof(T), count); }
    // fxport: every index, widened to 32 bits whatever the element size (tools and CPU references
    // that read a mesh back need not care how it was stored).
    std::vector<std::uint32_t> GetIndices() const;

    void setData(int offsetInBytes, const void* data, std::size_t elementSize, std::size_t count);
    void getData(void* data, std::size_t elementSize, std::size_t count) const;
    std::uint32_t backendObject() const { return name_; }

protected:
    void releaseGpuObjects() override;

private:
    fxport::IndexElementSize elementSize_;
    int count_;
    fxport::BufferUsage usage_;
    std::uint32_t name_ = 0;
};

}  // namespace fxport
