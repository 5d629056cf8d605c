// INTERNAL: the only header that exposes GL. fxport libraries and tests include it in .cpp files;
// never include it from a public runtime header (public headers carry no GL types).
//
// What it gives: the GL 4.5 core types and enums of <GL/glcorearb.h>, and one function pointer per
// entry point listed in gl_functions.inc, callable by its usual name (glCreateShader(...)). The
// pointers are filled by loadGLFunctions(), which every GraphicsContext runs when it is created and
// again when a context of another platform is made current (the pointers are process-wide: fxport
// drives GL from one thread).
//
// Why a namespace plus using-declarations, rather than glad's `#define glX fxport_glX`:
//  - libOSMesa and libGL export real C functions named glCreateShader etc.; a global variable of the
//    same unmangled name would collide with them. Variables inside fxport::gl get C++-mangled symbol
//    names, so they cannot.
//  - A using-declaration can be generated from the X-macro list (a #define cannot), so adding a
//    function stays one line in gl_functions.inc.
//  - If <GL/gl.h> (or anything declaring GL prototypes) was included first, the using-declarations
//    clash with those prototypes and the build fails loudly instead of calling the wrong thing.
#pragma once

#include <string>

#if defined(__gl_h_) || defined(__GL_H__)
#error "fxport/platform/gl.h must come before <GL/gl.h> (and it replaces it: do not include both)"
#endif

#include <GL/glcorearb.h>  // no GL_GLEXT_PROTOTYPES: types and enums only, no prototypes

// Turn a later #include <GL/gl.h> (osmesa.h, glfw3.h without GLFW_INCLUDE_NONE) into a no-op, so its
// prototypes never meet ours.
#define __gl_h_
#define __GL_H__

namespace fxport::gl {

#define FXPORT_GL_FUNCTION(type, name) extern type name;
#include "fxport/platform/gl_functions.inc"
#undef FXPORT_GL_FUNCTION

// Fills every pointer of gl_functions.inc through getProcAddress (a thin wrapper over
// OSMesaGetProcAddress, eglGetProcAddress or glfwGetProcAddress). Needs a current context on
// platforms whose pointers depend on it. Returns false if any function is missing; then `missing`
// (when given) receives their names, comma-separated. Note: glvnd and Mesa hand out a stub for
// almost any "gl*" name, so a missing function is mostly caught on real loaders only.
bool loadGLFunctions(void* (*getProcAddress)(const char*), std::string* missing);

}  // namespace fxport::gl

#define FXPORT_GL_FUNCTION(type, name) using ::fxport::gl::name;
#include "fxport/platform/gl_functions.inc"
#undef FXPORT_GL_FUNCTION
