// Vertex attribute formats (vertex_format.h).
#include "device/vertex_format.h"

namespace fxport {

int vertexFormatSize(const VertexFormat& f) {
    switch (f.component) {
    case VertexComponent::Float32:
    case VertexComponent::UInt32:
    case VertexComponent::SInt32: return 4 * f.count;
    case VertexComponent::Float16:
    case VertexComponent::UInt16:
    case VertexComponent::SInt16: return 2 * f.count;
    case VertexComponent::UInt8:
    case VertexComponent::SInt8: return f.count;
    case VertexComponent::UInt1010102:
    case VertexComponent::UInt8Bgra:
    case VertexComponent::UFloat111110: return 4;
    }
    return 0;
}

bool isPackedVertexComponent(VertexComponent c) { return c == VertexComponent::UInt1010102 || c == VertexComponent::UFloat111110; }

VertexFormat vertexFormatOf(VertexElementFormat f) {
    using C = VertexComponent;
    switch (f) {
    case VertexElementFormat::Single: return {C::Float32, 1, false};
    case VertexElementFormat::Vector2: return {C::Float32, 2, false};
    case VertexElementFormat::Vector3: return {C::Float32, 3, false};
    case VertexElementFormat::Vector4: return {C::Float32, 4, false};
    case VertexElementFormat::Color: return {C::UInt8, 4, true};
    case VertexElementFormat::Byte4: return {C::UInt8, 4, false};
    case VertexElementFormat::Short2: return {C::SInt16, 2, false};
    case VertexElementFormat::Short4: return {C::SInt16, 4, false};
    case VertexElementFormat::NormalizedShort2: return {C::SInt16, 2, true};
    case VertexElementFormat::NormalizedShort4: return {C::SInt16, 4, true};
    case VertexElementFormat::HalfVector2: return {C::Float16, 2, false};
    case VertexElementFormat::HalfVector4: return {C::Float16, 4, false};
    }
    return {};
}

}  // namespace fxport
