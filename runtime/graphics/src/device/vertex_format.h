// INTERNAL, GL-free: how the bytes of one vertex attribute read, in the device core's own words.
// XNA's VertexElementFormat (a closed list of twelve) and D3D11's DXGI vertex formats (any
// R32/R16/R8 float, integer or normalised layout) both map onto it, so the backend takes one kind
// of attribute whichever front end declared it.
#pragma once

#include <cstdint>

#include "fxport/graphics/vertex_declaration.h"

namespace fxport {

enum class VertexComponent : std::uint8_t {
    Float32, Float16, UInt8, SInt8, UInt16, SInt16, UInt32, SInt32,
    UInt1010102,  // four components packed in 32 bits (R10G10B10A2): x in the low bits
};

struct VertexFormat {
    VertexComponent component = VertexComponent::Float32;
    int count = 4;            // components, 1..4 (4 for UInt1010102)
    bool normalized = false;  // integers read as [0, 1] / [-1, 1] floats (UNORM / SNORM)
    bool operator==(const VertexFormat&) const = default;
};

// Bytes one attribute of `format` takes in a vertex.
int vertexFormatSize(const VertexFormat& format);
// XNA's formats: Color is four normalised bytes, Byte4 four unnormalised ones, and so on.
VertexFormat vertexFormatOf(VertexElementFormat format);

}  // namespace fxport
