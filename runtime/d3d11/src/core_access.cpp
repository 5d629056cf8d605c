// CoreDeviceOf (core_access.h). Device is the only ID3D11Device there is, so the cast is exact;
// CoreEffectOf is in effect11.cpp, next to the only ID3DX11Effect.
#include "fxport/d3d11/core_access.h"

#include "d3d11_impl.h"

namespace fxport::d3d11 {

GraphicsDevice& CoreDeviceOf(ID3D11Device& device) { return static_cast<Device&>(device).core(); }

}  // namespace fxport::d3d11
