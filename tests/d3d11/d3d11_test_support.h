// Helpers for the D3D11 front-end tests: a device, shaders compiled from source text, a texture
// read back the way D3D code does it (a staging copy, then Map READ).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fxport/d3d11.h"

namespace d3d11test {

using namespace fxport::d3d11;

struct Device {
    ComPtr<ID3D11Device> device;
    ComPtr<ID3D11DeviceContext> context;
    Device();
};

// Compiles `source` (named `name`) for entry/target; fails the test with the error blob if it fails.
ComPtr<ID3DBlob> compile(const std::string& source, const char* entry, const char* target, const char* name = "test.hlsl");

// RGBA8 pixels of a R8G8B8A8_UNORM texture, top row first (CopyResource into a staging texture, Map READ).
std::vector<std::array<std::uint8_t, 4>> readPixels(Device& d, ID3D11Texture2D* texture);

// A colour texture: RGBA8, `bind` flags, optional texels.
ComPtr<ID3D11Texture2D> makeTexture(Device& d, UINT width, UINT height, UINT bind, const std::vector<std::uint32_t>* texels = nullptr);

// The message GetLastErrorMessage() holds, for EXPECT_THAT-style checks.
std::string lastError();

}  // namespace d3d11test
