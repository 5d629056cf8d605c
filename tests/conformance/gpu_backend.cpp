// Which session runs a shader model (see gpu_backend.h).
#include "gpu_backend.h"

#include "d3d11_session.h"
#include "xna_session.h"

namespace conformance {

std::unique_ptr<GpuBackend> makeBackend(SessionKind kind, int model, SectionCompiler& compiler, const std::string& cacheDir) {
    // SM 4.0+ constants live in cbuffers, which D3D11 takes as bytes: no layout guess. D3D9's
    // constant registers have no D3D11 counterpart, so SM 2.0/3.0 keep the Effect API.
    if (kind == SessionKind::D3d11 && model >= 40) return std::make_unique<D3d11Session>(model);
    return std::make_unique<XnaSession>(model, compiler, cacheDir);
}

}  // namespace conformance
