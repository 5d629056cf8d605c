// Tessellated draws (GraphicsDevice::DrawPatches / DrawIndexedPatches): D3D11's
// N_CONTROL_POINT_PATCHLIST topologies are GL_PATCHES with GL_PATCH_VERTICES = N, drawn through the
// pass's hull (tessellation control) and domain (tessellation evaluation) programs, which
// flush() puts in the pipeline like the other stages.
#include <string>

#include "device/device_impl.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/vertex_buffer.h"

namespace fxport {

namespace {

constexpr int kMaxControlPoints = 32;  // D3D11 and GL_MAX_PATCH_VERTICES's minimum

void checkControlPoints(int controlPoints, int patchCount, const char* call) {
    if (controlPoints < 1 || controlPoints > kMaxControlPoints)
        throw ArgumentError(std::string(call) + ": " + std::to_string(controlPoints) + " control points per patch; D3D11 patch lists have 1.." +
                            std::to_string(kMaxControlPoints));
    if (patchCount <= 0) throw ArgumentError(std::string(call) + ": patch count " + std::to_string(patchCount) + " must be positive");
}

// Resets patchDraw however flush leaves.
struct PatchDrawScope {
    bool& flag;
    explicit PatchDrawScope(bool& f) : flag(f) { flag = true; }
    ~PatchDrawScope() { flag = false; }
};

}  // namespace

void GraphicsDevice::Impl::checkTessellation(bool patches, const char* what) const {
    const bool tessellates = shaders[kHullStage] && shaders[kDomainStage];
    if (patches && !tessellates)
        throw InvalidOperation(std::string(what) + ": the applied pass has no hull and domain shaders (SetHullShader / SetDomainShader); "
                                                   "patch lists draw only through them");
    if (!patches && (shaders[kHullStage] || shaders[kDomainStage]))
        throw InvalidOperation(std::string(what) + ": the applied pass has " + (shaders[kHullStage] ? "a hull" : "a domain") +
                               " shader, which draws patch lists only (DrawPatches / DrawIndexedPatches)");
}

void GraphicsDevice::DrawPatches(int controlPoints, int vertexStart, int patchCount) {
    Impl& d = *impl_;
    if (!d.vertexBuffer) throw InvalidOperation("DrawPatches: no vertex buffer set (SetVertexBuffer)");
    checkControlPoints(controlPoints, patchCount, "DrawPatches");
    long long count = static_cast<long long>(controlPoints) * patchCount;
    if (vertexStart < 0 || d.vertexOffset + vertexStart + count > d.vertexBuffer->VertexCount())
        throw ArgumentError("DrawPatches: " + std::to_string(patchCount) + " patches of " + std::to_string(controlPoints) + " control points from vertex " +
                            std::to_string(vertexStart) + " overrun the vertex buffer's " + std::to_string(d.vertexBuffer->VertexCount()) + " vertices");
    {
        PatchDrawScope scope(d.patchDraw);
        d.drawingPoints = false;
        d.flush("DrawPatches");
    }
    d.bindVertexBuffer();
    const DrawCall call{PrimitiveType::TriangleList, controlPoints, int(count), vertexStart};
    d.setStartVertex(call);
    d.backend->draw(call);
}

void GraphicsDevice::DrawIndexedPatches(int controlPoints, int baseVertex, int startIndex, int patchCount) {
    Impl& d = *impl_;
    if (!d.vertexBuffer) throw InvalidOperation("DrawIndexedPatches: no vertex buffer set (SetVertexBuffer)");
    if (!Indices) throw InvalidOperation("DrawIndexedPatches: no index buffer set (GraphicsDevice.Indices)");
    if (Indices->IsDisposed()) throw InvalidOperation("DrawIndexedPatches: the index buffer was disposed");
    checkControlPoints(controlPoints, patchCount, "DrawIndexedPatches");
    long long count = static_cast<long long>(controlPoints) * patchCount;
    if (startIndex < 0 || startIndex + count > Indices->IndexCount())
        throw ArgumentError("DrawIndexedPatches: " + std::to_string(patchCount) + " patches of " + std::to_string(controlPoints) +
                            " control points from index " + std::to_string(startIndex) + " need " + std::to_string(count) +
                            " indices; the index buffer has " + std::to_string(Indices->IndexCount()));
    {
        PatchDrawScope scope(d.patchDraw);
        d.drawingPoints = false;
        d.flush("DrawIndexedPatches");
    }
    Impl::VertexArray& va = d.bindVertexBuffer();
    if (va.elements != Indices->backendObject()) {
        va.elements = Indices->backendObject();
        d.backend->setIndexBuffer(va.vao, va.elements);
    }
    const bool wide = Indices->IndexElementSize() == IndexElementSize::ThirtyTwoBits;
    const DrawCall call{PrimitiveType::TriangleList, controlPoints, int(count), startIndex, true, baseVertex, wide ? 4 : 2};
    d.setStartVertex(call);
    d.backend->draw(call);
}

}  // namespace fxport
