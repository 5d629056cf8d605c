// D3D10/11 stream output in the device core: the targets SOSetTargets binds, and each draw whose
// last stage before the rasteriser carries a stream-output declaration (xlate/stream_output.h)
// wrapped in the backend's capture. The primitives written are read back after the draw (the GPU
// is waited for): they move the write position on and give each buffer D3D's filled size, which
// DrawAuto and appends read.
#include "device/device_impl.h"
#include "device/front_end_core.h"

namespace fxport {

namespace {

// Vertices per captured primitive: the geometry shader's output primitive, else the draw's.
int capturedPrimitiveVertices(const ShaderProgram& last, PrimitiveType drawn) {
    if (last.stage == 2) return last.shader->outputPrimitiveVertices;
    if (drawn == PrimitiveType::PointList) return 1;
    if (drawn == PrimitiveType::LineList || drawn == PrimitiveType::LineStrip) return 2;
    return 3;
}

}  // namespace

void GraphicsDevice::Impl::issueDraw(const DrawCall& call) {
    setStartVertex(call);
    const ShaderProgram* last = shaders[2] ? shaders[2] : shaders[kDomainStage] ? shaders[kDomainStage] : shaders[0];
    const xlate::StreamOutput* so = last && last->shader ? &last->shader->streamOutput : nullptr;
    if (!so || so->empty()) {
        backend->draw(call);
        return;
    }
    // D3D11_SO_NO_RASTERIZED_STREAM: nothing reaches the rasteriser.
    const bool discard = so->rasterizedStream == xlate::kNoRasterizedStream;
    if (discard) backend->setRasterizerDiscard(true);
    // Every slot the declaration writes needs a buffer with room (GL captures into all or none; D3D
    // would still write the others).
    std::array<Backend::StreamOutputBuffer, 4> buffers{};
    bool capture = true;
    for (std::size_t slot = 0; slot < buffers.size(); ++slot) {
        if (so->strides[slot] == 0) continue;
        const StreamTarget& t = streamTargets[slot];
        if (!t.buffer || t.offset >= t.buffer->size()) {
            capture = false;
            continue;
        }
        buffers[slot] = {t.buffer->backendObject(), t.offset, t.buffer->size() - t.offset};
    }
    if (!capture) {
        backend->draw(call);
    } else {
        if (!primitivesWrittenQuery) primitivesWrittenQuery = backend->createQuery(QueryKind::PrimitivesWritten);
        if (!primitivesGeneratedQuery) primitivesGeneratedQuery = backend->createQuery(QueryKind::PrimitivesGenerated);
        const int vertices = capturedPrimitiveVertices(*last, call.type);
        backend->beginStreamOutput(buffers, vertices, primitivesWrittenQuery, primitivesGeneratedQuery);
        backend->draw(call);
        backend->endStreamOutput();
        const std::uint64_t written = backend->queryResult(primitivesWrittenQuery);
        streamOutputWritten += written;
        streamOutputNeeded += backend->queryResult(primitivesGeneratedQuery);
        for (std::size_t slot = 0; slot < buffers.size(); ++slot) {
            if (so->strides[slot] == 0) continue;
            StreamTarget& t = streamTargets[slot];
            t.offset += std::size_t(written) * std::size_t(vertices) * std::size_t(so->strides[slot]);
            t.buffer->setStreamOutputFilled(t.offset);
        }
    }
    if (discard) backend->setRasterizerDiscard(false);
}

void GraphicsDevice::Impl::forgetStreamTarget(const core::ByteBuffer* buffer) {
    for (StreamTarget& t : streamTargets)
        if (t.buffer == buffer) t = {};
}

namespace core {

StreamOutputCounts streamOutputCounts(GraphicsDevice& device) {
    const GraphicsDevice::Impl& d = deviceImpl(device);
    return {d.streamOutputWritten, d.streamOutputNeeded};
}

void setStreamOutputTargets(GraphicsDevice& device, const std::array<ByteBuffer*, 4>& buffers, const std::array<std::size_t, 4>& offsets) {
    GraphicsDevice::Impl& d = deviceImpl(device);
    for (std::size_t slot = 0; slot < buffers.size(); ++slot) {
        ByteBuffer* b = buffers[slot];
        d.streamTargets[slot] = {b, !b ? 0 : offsets[slot] == kStreamOutputAppend ? b->streamOutputFilled() : offsets[slot]};
        // D3D: binding at an offset starts the buffer's contents there.
        if (b && offsets[slot] != kStreamOutputAppend) b->setStreamOutputFilled(offsets[slot]);
    }
}

}  // namespace core

}  // namespace fxport
