// D3D's SV_VertexID counts from the draw's start: it leaves out StartVertexLocation (Draw*) and
// BaseVertexLocation (DrawIndexed*), where GL's gl_VertexID counts them in (HLSL proposal 0015,
// microsoft/hlsl-specs: "SV_VertexID doesn't include the StartVertexLocation"). xlate's vertex
// shaders that read it subtract xlate::kStartVertexUniform; each draw sets it here.
#include "device/device_impl.h"
#include "fxport/xlate/compiled_effect.h"

namespace fxport {

void GraphicsDevice::Impl::setStartVertex(const DrawCall& call) {
    if (!boundVertexProgram) return;
    auto [it, added] = startVertexUniforms.try_emplace(boundVertexProgram);
    StartVertexUniform& u = it->second;
    if (added) u.location = backend->uniformLocation(boundVertexProgram, xlate::kStartVertexUniform);
    const int start = call.indexed ? call.baseVertex : call.first;
    if (u.location < 0 || u.value == start) return;
    backend->setUniform(boundVertexProgram, u.location, start);
    u.value = start;
}

}  // namespace fxport
