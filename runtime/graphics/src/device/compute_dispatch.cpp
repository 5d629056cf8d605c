// GraphicsDevice::DispatchCompute: runs the compute shader of the last applied pass. Its own
// program pipeline (a compute program is used alone), its uniform blocks in the compute stage's
// binding range, Textures[] for what it samples, the UAV and buffer-SRV slots for its storage
// (storage_bindings.cpp); afterwards the writes are marked for a barrier before the next use.
#include <string>

#include "device/device_impl.h"
#include "fxport/graphics/errors.h"
#include "fxport/xlate/compiled_effect.h"

namespace fxport {

namespace {

constexpr int kMaxGroupsPerDimension = 65535;  // D3D11_CS_DISPATCH_MAX_THREAD_GROUPS_PER_DIMENSION

}  // namespace

void GraphicsDevice::DispatchCompute(int groupsX, int groupsY, int groupsZ) {
    Impl& d = *impl_;
    if (!d.computeShader)
        throw InvalidOperation("DispatchCompute: no pass with a compute shader is applied (a technique11 pass with "
                               "SetComputeShader(CompileShader(cs_5_0, Main())), then Passes[i].Apply())");
    for (int n : {groupsX, groupsY, groupsZ})
        if (n < 0 || n > kMaxGroupsPerDimension)
            throw ArgumentError("DispatchCompute(" + std::to_string(groupsX) + ", " + std::to_string(groupsY) + ", " + std::to_string(groupsZ) +
                                "): each group count must be 0.." + std::to_string(kMaxGroupsPerDimension));
    if (groupsX == 0 || groupsY == 0 || groupsZ == 0) return;  // D3D11 runs nothing
    d.dispatch(groupsX, groupsY, groupsZ);
}

void GraphicsDevice::Impl::dispatch(int x, int y, int z) {
    const ShaderProgram& program = *computeShader;
    // A clear still waiting for its target must land before a shader writes or samples it.
    resolvePendingClear(pendingClear.options);
    storageBarrier();
    auto it = computePipelines.find(program.program);
    if (it == computePipelines.end()) {
        const BackendObject pipeline = backend->createComputePipeline(program.program);
        ++live.pipelines;
        it = computePipelines.emplace(program.program, pipeline).first;
    }
    if (boundPipeline != it->second) {
        backend->bindPipeline(it->second);
        boundPipeline = it->second;
    }
    for (int b = 0; b < kUniformBindingsPerStage; ++b) {
        std::size_t i = std::size_t(uniformBindingFor(kComputeStage, b));
        if (wantedUniformBuffers[i] == boundUniformBuffers[i]) continue;
        backend->bindUniformBuffer(int(i), wantedUniformBuffers[i]);
        boundUniformBuffers[i] = wantedUniformBuffers[i];
    }
    const ShaderProgram* programs[] = {&program};
    applyTexturesOf(programs, 1);
    applyStorage(programs, 1, "DispatchCompute");
    backend->dispatch(x, y, z);
    storageDirty = true;  // groupshared-only shaders are rare; one barrier too many costs little
}

void GraphicsDevice::Impl::dropComputePipelinesUsing(BackendObject program) {
    auto it = computePipelines.find(program);
    if (it == computePipelines.end()) return;
    if (boundPipeline == it->second) {
        backend->bindPipeline(0);
        boundPipeline = 0;
    }
    backend->deletePipeline(it->second);
    --live.pipelines;
    computePipelines.erase(it);
}

}  // namespace fxport
