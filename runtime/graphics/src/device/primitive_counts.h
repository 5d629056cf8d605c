// INTERNAL: XNA's primitive types checked and counted, for the draws of graphics_device.cpp and
// vertex_buffer_bindings.cpp.
#pragma once

#include <string>

#include "fxport/graphics/errors.h"
#include "fxport/graphics/graphics_device.h"

namespace fxport {

// An enum value made by a cast (PrimitiveType(77)) would draw GL_TRIANGLES from a count of 0.
inline void checkPrimitiveType(PrimitiveType type, const char* call) {
    if (static_cast<int>(type) > static_cast<int>(PrimitiveType::PointList))
        throw ArgumentError(std::string(call) + ": PrimitiveType(" + std::to_string(static_cast<int>(type)) +
                            ") is not a primitive type (TriangleList .. PointList)");
}

inline int vertexCountFor(PrimitiveType type, int primitives) {
    switch (type) {
    case PrimitiveType::TriangleList: return primitives * 3;
    case PrimitiveType::TriangleStrip: return primitives + 2;
    case PrimitiveType::LineList: return primitives * 2;
    case PrimitiveType::LineStrip: return primitives + 1;
    case PrimitiveType::PointList: return primitives;
    }
    return 0;
}

}  // namespace fxport
