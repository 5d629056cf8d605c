// Helpers for the D3D11 front-end tests: a device, shaders compiled from source text, a texture
// read back the way D3D code does it (a staging copy, then Map READ).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
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

// Level 0 of `texture` as bytes, top row first, rows packed at `texelBytes` per texel (CopyResource
// into a staging texture, Map READ).
std::vector<std::uint8_t> readTexelBytes(Device& d, ID3D11Texture2D* texture, std::size_t texelBytes);
// The same, as texels of type T (sizeof(T) bytes each: std::array<float, 4> for R32G32B32A32_FLOAT),
// or as `perTexel` values of T each (float and 4 for R32G32B32A32_FLOAT: RGBA floats in a row).
template <class T>
std::vector<T> readTexels(Device& d, ID3D11Texture2D* texture, std::size_t perTexel = 1) {
    const std::vector<std::uint8_t> bytes = readTexelBytes(d, texture, sizeof(T) * perTexel);
    std::vector<T> out(bytes.size() / sizeof(T));
    std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
    return out;
}
// "vs": one triangle over the whole target from SV_VertexID, no vertex buffer (tests add their "ps").
inline constexpr const char* kFullScreenVertexShader = R"(
float4 vs(uint id : SV_VertexID) : SV_Position {
    float2 corner = float2((id << 1) & 2, id & 2);
    return float4(corner * float2(2, -2) + float2(-1, 1), 0, 1);
}
)";
// "vs": a full-screen triangle from SV_VertexID; "ps": the texel of t0 under each pixel (Load, no
// filtering) -- what drawWithTexture draws to read a texture's texels back through a shader.
extern const char* const kTexelLoadShader;
// Draws `source`'s entries "vs" (a full-screen triangle from SV_VertexID) and "ps" (vs_5_0/ps_5_0)
// into a width x height R32G32B32A32_FLOAT target with `view` at t0 and `sampler` (may be null) at
// s0, and reads the target back.
std::vector<std::array<float, 4>> drawWithTexture(Device& d, const std::string& source, ID3D11ShaderResourceView* view, UINT width, UINT height,
                                                  ID3D11SamplerState* sampler = nullptr);
// Makes vertex and pixel shaders of the two blobs, draws three vertices (a triangle list) into a new
// width x height R8G8B8A8_UNORM target with a viewport of its size, and returns the target; whatever
// else the draw reads (constant buffers, views, samplers) the caller binds before.
ComPtr<ID3D11Texture2D> drawTriangleToRgba8(Device& d, ID3DBlob* vsCode, ID3DBlob* psCode, UINT width, UINT height);
// RGBA8 pixels of a R8G8B8A8_UNORM texture, top row first.
inline std::vector<std::array<std::uint8_t, 4>> readPixels(Device& d, ID3D11Texture2D* texture) {
    return readTexels<std::array<std::uint8_t, 4>>(d, texture);
}

// A DEFAULT buffer of `bytes` with `bind` flags (and structured `misc`/`stride`), filled from `data` if given.
ComPtr<ID3D11Buffer> makeBuffer(Device& d, const void* data, UINT bytes, UINT bind, UINT misc = 0, UINT stride = 0);
// The bytes of `buffer`, read as D3D code reads a GPU buffer: a staging copy, then Map READ.
std::vector<std::uint8_t> readBufferBytes(Device& d, ID3D11Buffer* buffer);
template <class T>
std::vector<T> readBuffer(Device& d, ID3D11Buffer* buffer) {
    const std::vector<std::uint8_t> bytes = readBufferBytes(d, buffer);
    std::vector<T> out(bytes.size() / sizeof(T));
    std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
    return out;
}

// A colour texture: RGBA8, `bind` flags, optional texels.
ComPtr<ID3D11Texture2D> makeTexture(Device& d, UINT width, UINT height, UINT bind, const std::vector<std::uint32_t>* texels = nullptr);

// A 1-level 2D texture of `format` with `bind` flags, filled from `texels` (rows `rowPitch` bytes apart) if given.
ComPtr<ID3D11Texture2D> makeFormatTexture(Device& d, DXGI_FORMAT format, UINT width, UINT height, UINT bind, const void* texels = nullptr,
                                          UINT rowPitch = 0);
// A TEXTURE2D shader-resource view of `texture`'s level 0 in `format` (a member of its typeless family).
ComPtr<ID3D11ShaderResourceView> viewAs(Device& d, ID3D11Texture2D* texture, DXGI_FORMAT format);
// The message GetLastErrorMessage() holds, for EXPECT_THAT-style checks.
std::string lastError();

}  // namespace d3d11test
