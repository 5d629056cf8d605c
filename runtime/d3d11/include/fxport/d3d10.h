// fxport's Direct3D 10 front end: D3D10's device (device and immediate context in one), its
// descriptions and the D3D10 effects framework, as thin adapters over the D3D11 front end
// (fxport/d3d11.h) -- one implementation underneath. docs/API.md lists what is there.
//
//   using namespace fxport::d3d10;
//   ID3D10Device* device;  IDXGISwapChain* swapChain;
//   D3D10CreateDeviceAndSwapChain(NULL, D3D10_DRIVER_TYPE_HARDWARE, NULL, 0, D3D10_SDK_VERSION,
//                                 &swapChainDesc, &swapChain, &device);
#pragma once

#include "fxport/d3d10/d3d10_interfaces.h"
#include "fxport/d3d10/d3d10_types.h"
#include "fxport/d3d10/d3dx10effect.h"
#include "fxport/d3d10/d3dx10tex.h"
#include "fxport/d3d11.h"
