// INTERNAL, GL-free: the seam between the device core and a graphics API, in the manner of
// FNA3D's driver table. The core (device/: XNA's semantics, validation, the state shadow, resources,
// draws) decides *what* the GPU must have; a Backend only says it in its API's words. The OpenGL
// backend is gl/gl_backend.cpp; tests use a recording one (tests/runtime/recording_backend.h) and
// need no GL context.
//
// The seam is being widened one concern at a time (issue 22 item 1): today it carries the
// fixed-function state, the sampler objects, texture and sampler bindings and buffer writes of a
// draw; the rest of the core still calls GL itself (tests/layering lists those files).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include "fxport/graphics/blend_state.h"
#include "fxport/graphics/depth_stencil_state.h"
#include "fxport/graphics/rasterizer_state.h"
#include "fxport/graphics/sampler_state.h"
#include "fxport/graphics/viewport.h"
#include "fxport/math/rectangle.h"

namespace fxport {

// A backend object (a GL name today): 0 is "none".
using BackendObject = std::uint32_t;

class Backend {
public:
    virtual ~Backend() = default;

    // Fixed-function state. `had` is the state this backend was last given (null when unknown: set
    // every field), so an implementation may touch only the fields that differ.
    virtual void setBlend(const BlendState& state, const BlendState* had) = 0;
    virtual void setDepthStencil(const DepthStencilState& state, const DepthStencilState* had) = 0;
    virtual void setRasterizer(const RasterizerState& state, const RasterizerState* had) = 0;
    virtual void setViewport(const Viewport& viewport) = 0;
    virtual void setScissor(const Rectangle& rectangle) = 0;  // the rectangle; RasterizerState switches the test
    virtual void setSrgbWrite(bool enabled) = 0;              // encode into sRGB-encoded targets (D3D9 SRGBWriteEnable)

    // Samplers and textures. A sampler object is made once per distinct SamplerState (the core caches it).
    virtual BackendObject createSampler(const SamplerState& state) = 0;
    virtual void deleteSampler(BackendObject sampler) = 0;
    virtual void bindTexture(int unit, BackendObject texture) = 0;
    virtual void bindSampler(int unit, BackendObject sampler) = 0;

    // Buffers.
    virtual void writeBuffer(BackendObject buffer, std::size_t offset, std::size_t bytes, const void* data) = 0;
};

// The backends there are (one registration each): OpenGL 4.5 core (gl/gl_backend.cpp).
std::unique_ptr<Backend> createGlBackend();

}  // namespace fxport
