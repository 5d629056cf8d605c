// INTERNAL, GL-free: the seam between the device core and a graphics API, in the manner of
// FNA3D's driver table. The core (device/: XNA's semantics, validation, the state shadow, resources,
// draws) decides *what* the GPU must have; a Backend only says it in its API's words. The OpenGL
// backend is gl/gl_backend.cpp; tests use a recording one (tests/runtime/recording_backend.h) and
// need no GL context.
//
// The seam is being widened one concern at a time (issue 22 item 1): today it carries what a draw
// sets up (device/draw_state.cpp: fixed-function state, sampler objects, texture, sampler and
// uniform-buffer bindings, program pipelines, vertex arrays) and the effects' constant writes; the
// rest of the core still calls GL itself (tests/layering lists those files).
#pragma once

#include <cstddef>
#include <cstdint>
#include <array>
#include <memory>
#include <vector>

#include "fxport/graphics/blend_state.h"
#include "fxport/graphics/depth_stencil_state.h"
#include "fxport/graphics/rasterizer_state.h"
#include "fxport/graphics/sampler_state.h"
#include "fxport/graphics/vertex_declaration.h"
#include "fxport/graphics/viewport.h"
#include "fxport/math/rectangle.h"

namespace fxport {

// A backend object (a GL name today): 0 is "none".
using BackendObject = std::uint32_t;

// One vertex-shader input fed from the bound vertex buffer (binding 0) at `offset` bytes.
struct VertexAttribute {
    int location = 0;
    VertexElementFormat format = VertexElementFormat::Vector4;
    int offset = 0;
    bool integer = false;  // the shader reads it as integers (no conversion to float)
};

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
    virtual void bindUniformBuffer(int binding, BackendObject buffer) = 0;

    // Programs and pipelines. A pipeline joins one program per draw stage (vertex, pixel, geometry,
    // hull, domain; 0 = none; vertex and pixel always set).
    virtual int uniformLocation(BackendObject program, const char* name) = 0;  // -1: none
    virtual void setUniform(BackendObject program, int location, int value) = 0;
    virtual void setUniform(BackendObject program, int location, float value) = 0;
    virtual BackendObject createPipeline(const std::array<BackendObject, 5>& stagePrograms) = 0;
    virtual void bindPipeline(BackendObject pipeline) = 0;

    // Vertex input: a layout of attributes read from one vertex buffer.
    virtual BackendObject createVertexArray(const std::vector<VertexAttribute>& attributes) = 0;
    virtual void bindVertexArray(BackendObject vertexArray) = 0;
};

// The backends there are (one registration each): OpenGL 4.5 core (gl/gl_backend.cpp).
std::unique_ptr<Backend> createGlBackend();

}  // namespace fxport
