// fxport's Direct3D 11 front end: D3D11's device, context, resources, views, state objects,
// D3DCompile and shader reflection with D3D's own names, over the same device core as the XNA
// API (docs/DESIGN.md, "The D3D11 front end"; docs/API.md lists what is there and what is not).
//
//   using namespace fxport::d3d11;
//   ComPtr<ID3D11Device> device; ComPtr<ID3D11DeviceContext> context;
//   D3D11CreateDevice(nullptr, D3D_DRIVER_TYPE_HARDWARE, nullptr, 0, nullptr, 0, D3D11_SDK_VERSION,
//                     device.GetAddressOf(), nullptr, context.GetAddressOf());
#pragma once

#include "fxport/d3d11/com_ptr.h"
#include "fxport/d3d11/d3d11_interfaces.h"
#include "fxport/d3d11/d3d11_types.h"
#include "fxport/d3d11/d3dcompiler.h"
#include "fxport/d3d11/d3dx11tex.h"
#include "fxport/d3d11/dds_texture_loader.h"
#include "fxport/d3d11/wic_texture_loader.h"
#include "fxport/d3d11/d3dx11effect.h"
#include "fxport/d3d11/dxgi.h"
