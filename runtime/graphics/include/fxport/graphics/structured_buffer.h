// StructuredBuffer: a D3D11-style buffer of fixed-size elements that shaders read as
// StructuredBuffer<T> / ByteAddressBuffer (a shader resource, register tN:
// GraphicsDevice::SetShaderResource) or read and write as RWStructuredBuffer<T> /
// RWByteAddressBuffer (an unordered-access view, register uN: GraphicsDevice::SetUnorderedAccess).
//
//   fxport::StructuredBuffer squares(device, sizeof(float), 64);
//   device.SetUnorderedAccess(0, squares);
//   effect.CurrentTechnique->Passes[0].Apply();       // a pass with SetComputeShader(...)
//   device.DispatchCompute(1, 1, 1);
//   std::vector<float> out = squares.GetData<float>();  // waits for the dispatch
//
// Element layout follows HLSL's structured-buffer packing (tightly packed, 4-byte aligned scalars),
// which is what GL's std430 gives for the scalar and vector members shaders use.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "fxport/graphics/graphics_resource.h"

namespace fxport {

class StructuredBuffer : public GraphicsResource {
public:
    // elementStride: bytes per element (a multiple of 4, as D3D11 requires); elementCount > 0.
    StructuredBuffer(fxport::GraphicsDevice& device, int elementStride, int elementCount);
    ~StructuredBuffer() override;

    int ElementStride() const { return stride_; }
    int ElementCount() const { return count_; }
    std::size_t SizeInBytes() const { return std::size_t(stride_) * std::size_t(count_); }

    // Writes/reads `count` values of T from byte `offsetInBytes` (the whole range must fit).
    template <class T> void SetData(const T* data, std::size_t count, std::size_t offsetInBytes = 0) {
        setBytes(offsetInBytes, data, sizeof(T) * count);
    }
    template <class T> void SetData(const std::vector<T>& data) { SetData(data.data(), data.size()); }
    template <class T> void GetData(T* data, std::size_t count, std::size_t offsetInBytes = 0) const {
        getBytes(offsetInBytes, data, sizeof(T) * count);
    }
    // The whole buffer as values of T (SizeInBytes() / sizeof(T) of them).
    template <class T> std::vector<T> GetData() const {
        std::vector<T> out(SizeInBytes() / sizeof(T));
        getBytes(0, out.data(), out.size() * sizeof(T));
        return out;
    }

    void setBytes(std::size_t offset, const void* data, std::size_t bytes);
    void getBytes(std::size_t offset, void* data, std::size_t bytes) const;
    std::uint32_t backendObject() const { return name_; }

protected:
    void releaseGpuObjects() override;

private:
    int stride_;
    int count_;
    std::uint32_t name_ = 0;
};

}  // namespace fxport
