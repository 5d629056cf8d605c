// INTERNAL, GL-free: what an Effect needs of the device, without its private state
// (device/device_impl.h): its programs and constant buffers made and released through the device's
// caches and object counts, its registration (so a disposed texture leaves its parameters), and what
// EffectPass::Apply binds for the next draw or dispatch.
#pragma once

#include <cstddef>
#include <string>

#include "device/backend.h"
#include "device/shader_program.h"
#include "fxport/graphics/graphics_device.h"

namespace fxport::xlate {
struct CompiledShader;
}

namespace fxport {

class Effect;

namespace effects {

// An effect made over `device` (GraphicsDevice::Impl::effects: disposed textures leave its parameters)
// and one released; `srgbWriteReported` is its "said once" flag, which the device's pass emulation
// may point at.
void add(GraphicsDevice& device, Effect& effect);
void remove(GraphicsDevice& device, Effect& effect, const bool* srgbWriteReported);

// The program of `shader` at `stage` (0 vertex .. 5 compute) from `glsl`, shared with every equal one
// (GraphicsDevice::Impl::createProgram); InvalidOperation naming `label` when the driver rejects it.
BackendObject createProgram(GraphicsDevice& device, int stage, const xlate::CompiledShader& shader, const std::string& glsl,
                            const std::string& label);
void deleteProgram(GraphicsDevice& device, BackendObject& program);
// `program`'s record goes away: the device stops pointing at it, and its program, its fixed-function
// variants and what compute passes made for it are released.
void releaseProgram(GraphicsDevice& device, ShaderProgram& program);

// A uniform buffer of `bytes` (contents undefined until written), and its release.
BackendObject createConstantBuffer(GraphicsDevice& device, std::size_t bytes);
void deleteBuffer(GraphicsDevice& device, BackendObject& buffer);
// The backend, for writing constant bytes (Backend::writeBuffer).
Backend& backend(GraphicsDevice& device);

// EffectPass::Apply: the shader of a draw stage (null: none), set or left; kComputeStage is the
// compute shader of the next dispatch.
const ShaderProgram* boundShader(GraphicsDevice& device, int stage);
void bindShader(GraphicsDevice& device, int stage, const ShaderProgram* program);
// The uniform buffer the next draw binds at `binding` (uniformBindingFor).
void wantUniformBuffer(GraphicsDevice& device, int binding, BackendObject buffer);
// A pass was applied: draws may run.
void passApplied(GraphicsDevice& device);

}  // namespace effects
}  // namespace fxport
