// Test support: one shared OSMesa context per test process, and a GLSL compile-and-link check that
// reports the driver's own info log.
#pragma once

#include <string>
#include <vector>

#include "fxport/platform/graphics_context.h"

namespace fxport::test {

struct GlslStageSource {
    enum Stage { Vertex, Fragment, Geometry } stage;
    std::string source;
};

// "vertex", "fragment", "geometry".
const char* stageName(GlslStageSource::Stage stage);

// With a current context: compiles every stage, links each one alone as a separable program
// (GL_PROGRAM_SEPARABLE, as program pipelines use them) and all of them together as one ordinary
// program (which also checks the interface between stages). Returns "" on success, otherwise every
// failing step, each naming its stage, followed by the driver's info log. Deletes every GL object it
// made, on success and on failure.
// It also applies one rule Mesa does not enforce but NVIDIA does, so that tests on OSMesa reject what
// the GPU would: in #version 410+ a vertex/geometry shader must redeclare gl_PerVertex (out, and for
// geometry also `in ... gl_in[]`) listing every built-in member it uses. Reported as
// "<stage> shader: portability: ...".
std::string compileAndLinkSeparable(const std::vector<GlslStageSource>& stages);

// An OSMesa context created on first use and kept until the process exits; made current on every
// call, so tests that made another context current get this one back.
platform::GraphicsContext& sharedTestContext();

// Sanitizer builds (FXPORT_SANITIZE): keeps the Mesa DRI drivers loaded now (EGL's llvmpipe,
// swrast_dri.so) mapped until the process exits. Mesa's EGL dlclose()s the driver at eglTerminate,
// and LeakSanitizer, which runs at exit, then no longer sees the driver's globals: what they hold
// is reported as leaked from an "<unknown module>" that no suppression can name. Kept mapped, the
// driver's globals are scanned like any others and nothing needs suppressing. Call it while an EGL
// context is alive. Does nothing in other builds.
void keepGraphicsDriversMapped();

}  // namespace fxport::test
