// What an Effect needs of the device (effect_programs.h), over the device's private state.
#include "device/effect_programs.h"

#include <algorithm>

#include "device/compute_passes.h"
#include "device/device_impl.h"

namespace fxport::effects {

void add(GraphicsDevice& device, Effect& effect) { deviceImpl(device).effects.push_back(&effect); }

void remove(GraphicsDevice& device, Effect& effect, const bool* srgbWriteReported) {
    GraphicsDevice::Impl& d = deviceImpl(device);
    // The device's pass emulation may point into this effect (its SRGBWriteEnable location).
    if (d.emulation.srgbWriteReported == srgbWriteReported) d.emulation = PassEmulation{};
    d.effects.erase(std::remove(d.effects.begin(), d.effects.end(), &effect), d.effects.end());
}

BackendObject createProgram(GraphicsDevice& device, int stage, const xlate::CompiledShader& shader, const std::string& glsl,
                            const std::string& label) {
    return deviceImpl(device).createProgram(stage, shader, glsl, label);
}

void deleteProgram(GraphicsDevice& device, BackendObject& program) { deviceImpl(device).deleteProgram(program); }

void releaseProgram(GraphicsDevice& device, ShaderProgram& program) {
    GraphicsDevice::Impl& d = deviceImpl(device);
    // The device may still point at this ShaderProgram record (the GL program itself can outlive
    // it when another effect shares it).
    for (const ShaderProgram*& bound : d.shaders)
        if (bound == &program) bound = nullptr;
    if (d.computeShader == &program) d.computeShader = nullptr;
    d.deleteProgram(program.program);
    d.releaseFixedFunctionVariants(program);
    if (program.computeAnalysis && d.computePasses) d.computePasses->forget(*program.computeAnalysis);
}

BackendObject createConstantBuffer(GraphicsDevice& device, std::size_t bytes) {
    GraphicsDevice::Impl& d = deviceImpl(device);
    const BackendObject buffer = d.createBuffer();
    d.backend->allocateBuffer(buffer, bytes, nullptr, false);
    return buffer;
}

void deleteBuffer(GraphicsDevice& device, BackendObject& buffer) { deviceImpl(device).deleteBuffer(buffer); }

Backend& backend(GraphicsDevice& device) { return *deviceImpl(device).backend; }

const ShaderProgram* boundShader(GraphicsDevice& device, int stage) {
    const GraphicsDevice::Impl& d = deviceImpl(device);
    return stage == kComputeStage ? d.computeShader : d.shaders[std::size_t(stage)];
}

void bindShader(GraphicsDevice& device, int stage, const ShaderProgram* program) {
    GraphicsDevice::Impl& d = deviceImpl(device);
    if (stage == kComputeStage) d.computeShader = program;
    else d.shaders[std::size_t(stage)] = program;
}

void wantUniformBuffer(GraphicsDevice& device, int binding, BackendObject buffer) {
    deviceImpl(device).wantedUniformBuffers[std::size_t(binding)] = buffer;
}

void passApplied(GraphicsDevice& device) { deviceImpl(device).passApplied = true; }

}  // namespace fxport::effects
