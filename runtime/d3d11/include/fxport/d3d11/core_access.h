// fxport: fxport's own objects underneath the D3D front ends, for a port's harness that measures
// and reports with fxport's API (GpuTimer, the demos' --explain and PassTimer, which take a
// GraphicsDevice or an Effect) while the port itself draws through D3D. fxport's D3D11 and D3D10
// devices (ID3D10Device::GetD3D11Device()) are one implementation over one device core, and an
// ID3DX11Effect (ID3D10Effect::GetD3DX11Effect()) over one fxport::Effect, so these are plain
// accessors: no reference is added, and the objects live as long as the device or effect.
#pragma once

#include "fxport/d3d11/d3d11_interfaces.h"
#include "fxport/d3d11/d3dx11effect.h"
#include "fxport/graphics.h"

namespace fxport::d3d11 {

// The device core: its back buffer is never shown (the swap chain's is a texture), but its GPU
// timer queries, clear counts and renderer name are the D3D device's.
GraphicsDevice& CoreDeviceOf(ID3D11Device& device);
// The effect the D3DX11 effect wraps: its techniques, passes and compile statistics.
Effect& CoreEffectOf(ID3DX11Effect& effect);

}  // namespace fxport::d3d11
