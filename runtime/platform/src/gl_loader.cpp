#include "fxport/platform/gl.h"

namespace fxport::gl {

#define FXPORT_GL_FUNCTION(type, name) type name = nullptr;
#include "fxport/platform/gl_functions.inc"
#undef FXPORT_GL_FUNCTION

bool loadGLFunctions(void* (*getProcAddress)(const char*), std::string* missing) {
    std::string absent;
    // Function and object pointers have the same size on every platform GL runs on (POSIX requires
    // it for dlsym); reinterpret_cast between them is conditionally supported and fine here.
#define FXPORT_GL_FUNCTION(type, name)                    \
    name = reinterpret_cast<type>(getProcAddress(#name)); \
    if (name == nullptr) absent.append(absent.empty() ? "" : ", ").append(#name);
#include "fxport/platform/gl_functions.inc"
#undef FXPORT_GL_FUNCTION
    if (missing != nullptr) *missing = absent;
    return absent.empty();
}

}  // namespace fxport::gl
