// INTERNAL: one draw's GL parameters, as the device's draw entry points issue it. Compute passes
// (compute_pass.h) issue the same draw again under transform feedback and from indirect commands
// on the GPU, so they need its parameters rather than an opaque call.
#pragma once

#include <cstddef>
#include <cstdint>

#include "fxport/platform/gl.h"

namespace fxport {

// FNV-1a over `bytes` bytes, continuing from `hash`.
inline std::uint64_t hashBytes(const void* data, std::size_t bytes, std::uint64_t hash = 1469598103934665603ull) {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) hash = (hash ^ p[i]) * 1099511628211ull;
    return hash;
}

struct DrawCall {
    GLenum mode = GL_TRIANGLES;
    int count = 0;           // vertices or indices
    int first = 0;           // first vertex, or first index when indexed
    bool indexed = false;
    int baseVertex = 0;      // indexed only
    int indexSize = 2;       // bytes per index, 2 or 4
    // DrawUser(Indexed)Primitives of at most two triangles with compute passes on: a hash of the
    // vertex and index bytes (a hint that the vertices changed; exactness never depends on it). 0: unknown.
    std::uint64_t userDataHash = 0;

    GLenum indexType() const { return indexSize == 4 ? GL_UNSIGNED_INT : GL_UNSIGNED_SHORT; }
    void issue() const {
        if (indexed)
            glDrawElementsBaseVertex(mode, count, indexType(),
                                     reinterpret_cast<const void*>(std::uintptr_t(first) * std::uintptr_t(indexSize)), baseVertex);
        else
            glDrawArrays(mode, first, count);
    }
    // The draw as the command at `offset` bytes of the bound GL_DRAW_INDIRECT_BUFFER says (its
    // instance count may be 0: then it draws nothing).
    void issueIndirect(GLintptr offset) const {
        if (indexed) glDrawElementsIndirect(mode, indexType(), reinterpret_cast<const void*>(offset));
        else glDrawArraysIndirect(mode, reinterpret_cast<const void*>(offset));
    }
};

}  // namespace fxport
