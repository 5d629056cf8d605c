// INTERNAL to gl/: a DrawCall (device/backend.h) issued from indirect commands written on the GPU
// (compute passes, gl/passes/compute_pass.h), which the backend's draw() does not do.
#pragma once

#include "gl/gl_backend.h"

namespace fxport {

// The draw as the command at `offset` bytes of the bound GL_DRAW_INDIRECT_BUFFER says (its
// instance count may be 0: then it draws nothing).
inline void issueDrawIndirect(const DrawCall& call, GLintptr offset) {
    if (call.indexed) glDrawElementsIndirect(glModeOf(call), glIndexTypeOf(call), reinterpret_cast<const void*>(offset));
    else glDrawArraysIndirect(glModeOf(call), reinterpret_cast<const void*>(offset));
}

}  // namespace fxport
