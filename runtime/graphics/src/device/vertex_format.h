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
    UInt8Bgra,    // four bytes in B, G, R, A order (B8G8R8A8): x is the third byte
    UFloat111110, // three unsigned small floats packed in 32 bits (R11G11B10_FLOAT): x in the low bits
};
// Whether `c` packs its components into one 32-bit word (aligned to 4 bytes whatever its count).
bool isPackedVertexComponent(VertexComponent c);

struct VertexFormat {
    VertexComponent component = VertexComponent::Float32;
    int count = 4;            // components, 1..4 (4 for UInt1010102 and UInt8Bgra, 3 for UFloat111110)
    bool normalized = false;  // integers read as [0, 1] / [-1, 1] floats (UNORM / SNORM)
    bool operator==(const VertexFormat&) const = default;
};

// Bytes one attribute of `format` takes in a vertex.
int vertexFormatSize(const VertexFormat& format);
// XNA's formats: Color is four normalised bytes, Byte4 four unnormalised ones, and so on.
VertexFormat vertexFormatOf(VertexElementFormat format);

}  // namespace fxport
