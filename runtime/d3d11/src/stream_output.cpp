// D3D10/11 stream output on the D3D11 front end: CreateGeometryShaderWithStreamOutput (the
// declaration resolved by xlate against the shader's outputs, the program linked to capture them),
// SOSetTargets/SOGetTargets (the device core's targets) and DrawAuto (the vertices the last stream
// output left in the vertex buffer at slot 0).
#include "context.h"
#include "guarded.h"

namespace fxport::d3d11 {

namespace {

// The declaration as xlate takes it; false with the reason in `error` for what D3D refuses.
bool declarationOf(const D3D11_SO_DECLARATION_ENTRY* entries, UINT count, xlate::StreamOutput& so, std::string& error) {
    if (count > 0 && !entries) {
        error = "pSODeclaration is null with NumEntries = " + std::to_string(count);
        return false;
    }
    for (UINT i = 0; i < count; ++i) {
        const D3D11_SO_DECLARATION_ENTRY& e = entries[i];
        xlate::StreamOutputEntry x;
        x.stream = int(e.Stream);
        x.semanticName = e.SemanticName ? e.SemanticName : "";
        x.semanticIndex = int(e.SemanticIndex);
        x.startComponent = e.StartComponent;
        x.componentCount = e.ComponentCount;
        x.outputSlot = e.OutputSlot;
        so.entries.push_back(x);
    }
    return true;
}

}  // namespace

HRESULT Device::CreateGeometryShaderWithStreamOutput(const void* bytecode, SIZE_T length, const D3D11_SO_DECLARATION_ENTRY* entries, UINT count,
                                                     const UINT* strides, UINT numStrides, UINT rasterizedStream, ID3D11ClassLinkage* linkage,
                                                     ID3D11GeometryShader** pp) {
    const char* call = "CreateGeometryShaderWithStreamOutput";
    if (linkage) return fail(E_NOTIMPL, std::string(call) + ": class linkage (dynamic shader linking) is not supported");
    if (!bytecode || length == 0) return fail(E_INVALIDARG, std::string(call) + ": pShaderBytecode is null or empty");
    if (numStrides > D3D11_SO_BUFFER_SLOT_COUNT || (numStrides > 0 && !strides))
        return fail(E_INVALIDARG, std::string(call) + ": NumStrides = " + std::to_string(numStrides) + " (at most 4, with pBufferStrides)");
    std::string error;
    BlobKind kind = BlobKind::Shader;
    std::shared_ptr<const xlate::CompiledEffect> blob = effectFromBytecode(bytecode, length, error, &kind);
    if (!blob) return fail(E_INVALIDARG, std::string(call) + ": " + error);
    if (kind != BlobKind::Shader || blob->shaders.empty()) return fail(E_INVALIDARG, std::string(call) + ": the bytecode is no compiled shader");
    int index = -1;
    for (std::size_t i = 0; i < blob->shaders.size(); ++i)
        if (blob->shaders[i].profile.stage == xlate::ShaderStage::Geometry || blob->shaders[i].profile.stage == xlate::ShaderStage::Vertex)
            index = index < 0 || blob->shaders[i].profile.stage == xlate::ShaderStage::Geometry ? int(i) : index;
    if (index < 0) return fail(E_INVALIDARG, std::string(call) + ": the bytecode holds a " + blob->shaders[0].profile.name + " shader, not a geometry or vertex shader");
    // The shader with the declaration: a copy of the blob's effect (the blob itself stays as it was).
    auto effect = std::make_shared<xlate::CompiledEffect>(*blob);
    xlate::CompiledShader& shader = effect->shaders[std::size_t(index)];
    xlate::StreamOutput& so = shader.streamOutput;
    so.rasterizedStream = rasterizedStream == D3D11_SO_NO_RASTERIZED_STREAM ? xlate::kNoRasterizedStream : int(rasterizedStream);
    for (UINT i = 0; i < numStrides; ++i) so.strides[i] = int(strides[i]);
    if (!declarationOf(entries, count, so, error) || !xlate::resolveStreamOutput(shader.outputs, so, error))
        return fail(E_INVALIDARG, std::string(call) + ": " + error);
    if (!pp) return succeed();  // D3D: validation only
    return guarded(call, [&] {
        ShaderBindings bindings = bindingsOf(*effect, index);
        if (std::string mismatch = layoutMismatch(*effect, bindings); !mismatch.empty()) return fail(E_FAIL, std::string(call) + ": " + mismatch);
        const std::string label = effect->sourcePath + ": " + shader.entryPoint + " (" + shader.profile.name + ", stream output)";
        auto code = std::make_unique<core::ShaderCode>(core(), effect, index, label);
        *pp = new GeometryShader(this, std::move(code), std::move(bindings));
        return succeed();
    });
}

void Context::SOSetTargets(UINT count, ID3D11Buffer* const* buffers, const UINT* offsets) {
    std::array<core::ByteBuffer*, 4> gpu{};
    std::array<std::size_t, 4> at{};
    for (UINT slot = 0; slot < D3D11_SO_BUFFER_SLOT_COUNT; ++slot) {
        soTargets_[slot] = slot < count && buffers ? own<Buffer>(buffers[slot], device_) : nullptr;
        if (soTargets_[slot] && !(soTargets_[slot]->desc.BindFlags & D3D11_BIND_STREAM_OUTPUT)) {
            note("SOSetTargets: the buffer at slot " + std::to_string(slot) + " was not created with D3D11_BIND_STREAM_OUTPUT; it is not bound");
            soTargets_[slot] = nullptr;
        }
        gpu[slot] = soTargets_[slot] ? soTargets_[slot]->gpu.get() : nullptr;
        const UINT offset = offsets && slot < count ? offsets[slot] : 0;
        at[slot] = offset == 0xffffffffu ? core::kStreamOutputAppend : std::size_t(offset);
    }
    core::setStreamOutputTargets(device_->core(), gpu, at);
}

void Context::SOGetTargets(UINT count, ID3D11Buffer** buffers) {
    if (!buffers) return;
    for (UINT slot = 0; slot < count; ++slot) {
        buffers[slot] = slot < D3D11_SO_BUFFER_SLOT_COUNT ? soTargets_[slot].Get() : nullptr;
        if (buffers[slot]) buffers[slot]->AddRef();
    }
}

void Context::DrawAuto() {
    const VertexSlot& v = vertexSlots_[0];
    if (!v.buffer || !v.buffer->gpu || v.stride == 0) {
        note("DrawAuto: no vertex buffer with a stride at slot 0; nothing drawn");
        return;
    }
    const std::size_t filled = v.buffer->gpu->streamOutputFilled();
    const UINT count = filled > v.offset ? UINT((filled - v.offset) / v.stride) : 0;
    draw("DrawAuto", core::DrawArguments{PrimitiveType::TriangleList, int(count), 0}, false);
}

}  // namespace fxport::d3d11
