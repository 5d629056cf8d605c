// Array textures through the D3D11 front end (issue 25): a 2x2 array of three slices with two
// levels, a distinct RGBA8 colour per slice, level and texel, read in a pixel shader through a
// TEXTURE2DARRAY view (SampleLevel with a point sampler, Load, GetDimensions) and compared with the
// colours written; a draw and a clear into one slice through a render-target view, every slice
// read back (the other slices unchanged); a view of a sub-range of levels and slices; one
// subresource updated, mips generated per slice; a typeless depth array drawn slice by slice and
// sampled whole (a cascaded shadow map); and the descriptions refused with the field.
#include <cmath>
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

using Rgba = std::array<std::uint8_t, 4>;
using Texel = std::array<float, 4>;
constexpr int kSlices = 3, kLevels = 2;

const char* const kFullScreen = kFullScreenVertexShader;

// Texel (x, y) of `slice` at `level`: no two alike.
Rgba colourAt(int slice, int level, int x, int y) {
    return {std::uint8_t(20 + 70 * slice), std::uint8_t(30 + 100 * level), std::uint8_t(40 + 50 * x + 100 * y), std::uint8_t(255 - 10 * slice - level)};
}

std::vector<Rgba> levelTexels(int slice, int level) {
    const int size = 2 >> level;
    std::vector<Rgba> texels;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) texels.push_back(colourAt(slice, level, x, y));
    return texels;
}

D3D11_TEXTURE2D_DESC arrayDesc(UINT bind, UINT slices = kSlices, UINT levels = kLevels) {
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = desc.Height = 2;
    desc.MipLevels = levels;
    desc.ArraySize = slices;
    desc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    desc.BindFlags = bind;
    return desc;
}

// The 2x2, three-slice, two-level array with colourAt's texels, as pInitialData (level + slice * 2).
ComPtr<ID3D11Texture2D> makeArray(Device& d, UINT bind, UINT misc = 0) {
    std::vector<std::vector<Rgba>> texels;
    std::vector<D3D11_SUBRESOURCE_DATA> data;
    for (int slice = 0; slice < kSlices; ++slice)
        for (int level = 0; level < kLevels; ++level) texels.push_back(levelTexels(slice, level));
    for (std::size_t i = 0; i < texels.size(); ++i) data.push_back({texels[i].data(), UINT(sizeof(Rgba)) * UINT(2 >> (i % kLevels)), 0});
    D3D11_TEXTURE2D_DESC desc = arrayDesc(bind);
    desc.MiscFlags = misc;
    ComPtr<ID3D11Texture2D> t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, data.data(), t.GetAddressOf()), S_OK) << lastError();
    return t;
}

ComPtr<ID3D11Texture2D> floatTarget(Device& d, UINT width, UINT height) {
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = width;
    desc.Height = height;
    desc.MipLevels = desc.ArraySize = 1;
    desc.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    desc.BindFlags = D3D11_BIND_RENDER_TARGET;
    ComPtr<ID3D11Texture2D> t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), S_OK) << lastError();
    return t;
}

// Draws `ps` (entry "ps") into `rtv` (width x height) with `view` at t0 and a point sampler at s0.
void drawInto(Device& d, const std::string& ps, ID3D11RenderTargetView* rtv, UINT width, UINT height, ID3D11ShaderResourceView* view) {
    const std::string text = std::string(kFullScreen) + ps;
    ComPtr<ID3DBlob> vsCode = compile(text, "vs", "vs_5_0"), psCode = compile(text, "ps", "ps_5_0");
    ASSERT_TRUE(vsCode && psCode);
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> p;
    ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, p.GetAddressOf()), S_OK) << lastError();
    D3D11_SAMPLER_DESC samplerDesc;
    samplerDesc.Filter = D3D11_FILTER_MIN_MAG_MIP_POINT;
    ComPtr<ID3D11SamplerState> point;
    ASSERT_EQ(d.device->CreateSamplerState(&samplerDesc, point.GetAddressOf()), S_OK) << lastError();
    d.context->OMSetRenderTargets(1, &rtv, nullptr);
    D3D11_VIEWPORT viewport;
    viewport.Width = float(width);
    viewport.Height = float(height);
    d.context->RSSetViewports(1, &viewport);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(p.Get(), nullptr, 0);
    d.context->PSSetShaderResources(0, 1, &view);
    d.context->PSSetSamplers(0, 1, point.GetAddressOf());
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->Draw(3, 0);
    ID3D11RenderTargetView* none = nullptr;
    d.context->OMSetRenderTargets(1, &none, nullptr);
}

std::vector<Texel> drawAndRead(Device& d, const std::string& ps, UINT width, UINT height, ID3D11ShaderResourceView* view) {
    ComPtr<ID3D11Texture2D> target = floatTarget(d, width, height);
    ComPtr<ID3D11RenderTargetView> rtv;
    EXPECT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    drawInto(d, ps, rtv.Get(), width, height, view);
    EXPECT_EQ(lastError(), "");
    return readTexels<Texel>(d, target.Get());
}

// A float the shader read from a unorm8 texel, back as the byte.
Rgba bytesOf(const Texel& t) {
    Rgba out;
    for (int c = 0; c < 4; ++c) out[std::size_t(c)] = std::uint8_t(std::lround(t[std::size_t(c)] * 255.0f));
    return out;
}

// Subresource `sub` (level 0 size: 2x2 >> level) of `array`, read as D3D code does: a region copy
// into a staging texture, then Map READ.
std::vector<Rgba> readSubresource(Device& d, ID3D11Texture2D* array, UINT sub, int size) {
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = desc.Height = UINT(size);
    desc.MipLevels = desc.ArraySize = 1;
    desc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    desc.Usage = D3D11_USAGE_STAGING;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
    ComPtr<ID3D11Texture2D> staging;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, staging.GetAddressOf()), S_OK) << lastError();
    d.context->CopySubresourceRegion(staging.Get(), 0, 0, 0, 0, array, sub, nullptr);
    EXPECT_EQ(lastError(), "");
    D3D11_MAPPED_SUBRESOURCE mapped;
    std::vector<Rgba> out(std::size_t(size * size));
    if (d.context->Map(staging.Get(), 0, D3D11_MAP_READ, 0, &mapped) != S_OK) return {};
    for (int y = 0; y < size; ++y) std::memcpy(&out[std::size_t(y * size)], static_cast<const std::uint8_t*>(mapped.pData) + y * mapped.RowPitch, std::size_t(size) * 4);
    d.context->Unmap(staging.Get(), 0);
    return out;
}

TEST(D3D11TextureArray, EverySliceAndLevelReadsWhatWasWritten) {
    Device d;
    ComPtr<ID3D11Texture2D> array = makeArray(d, D3D11_BIND_SHADER_RESOURCE);
    ASSERT_TRUE(array);
    D3D11_TEXTURE2D_DESC got;
    array->GetDesc(&got);
    EXPECT_EQ(got.ArraySize, UINT(kSlices));
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(array.Get(), nullptr, view.GetAddressOf()), S_OK) << lastError();
    D3D11_SHADER_RESOURCE_VIEW_DESC viewDesc;
    view->GetDesc(&viewDesc);
    EXPECT_EQ(viewDesc.ViewDimension, D3D11_SRV_DIMENSION_TEXTURE2DARRAY);
    EXPECT_EQ(viewDesc.Texture2DArray.ArraySize, UINT(kSlices));
    EXPECT_EQ(viewDesc.Texture2DArray.MipLevels, UINT(kLevels));
    // Columns: slice * 2 + x. Rows 0-1: level 0's texel (x, row) by SampleLevel; row 2: level 1's
    // texel by Load; row 3, column 0: GetDimensions.
    const std::vector<Texel> pixels = drawAndRead(d, R"(
Texture2DArray Layers : register(t0);
SamplerState Point : register(s0);
float4 ps(float4 pos : SV_Position) : SV_Target {
    int2 p = int2(pos.xy);
    float slice = float(p.x / 2);
    if (p.y < 2) return Layers.SampleLevel(Point, float3((float(p.x % 2) + 0.5) / 2.0, (float(p.y) + 0.5) / 2.0, slice), 0);
    if (p.y == 2) return Layers.Load(int4(0, 0, p.x / 2, 1));
    uint w, h, elements, levels;
    Layers.GetDimensions(0, w, h, elements, levels);
    return float4(w, h, elements, levels);
})",
                                                  2 * kSlices, 4, view.Get());
    ASSERT_EQ(pixels.size(), std::size_t(2 * kSlices * 4));
    for (int slice = 0; slice < kSlices; ++slice) {
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x)
                EXPECT_EQ(bytesOf(pixels[std::size_t(y * 2 * kSlices + slice * 2 + x)]), colourAt(slice, 0, x, y)) << "slice " << slice << " texel " << x << "," << y;
        EXPECT_EQ(bytesOf(pixels[std::size_t(2 * 2 * kSlices + slice * 2)]), colourAt(slice, 1, 0, 0)) << "slice " << slice << " level 1";
    }
    EXPECT_EQ(pixels[std::size_t(3 * 2 * kSlices)], (Texel{2, 2, float(kSlices), float(kLevels)}));
}

TEST(D3D11TextureArray, ASubRangeViewSeesItsSlicesAndLevelsOnly) {
    Device d;
    ComPtr<ID3D11Texture2D> array = makeArray(d, D3D11_BIND_SHADER_RESOURCE);
    ASSERT_TRUE(array);
    D3D11_SHADER_RESOURCE_VIEW_DESC desc;
    desc.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2DARRAY;
    desc.Texture2DArray = {1, 1, 1, 2};  // level 1 of slices 1 and 2
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(array.Get(), &desc, view.GetAddressOf()), S_OK) << lastError();
    const std::vector<Texel> pixels = drawAndRead(d, R"(
Texture2DArray Layers : register(t0);
float4 ps(float4 pos : SV_Position) : SV_Target {
    if (pos.x > 2) { uint w, h, elements, levels; Layers.GetDimensions(0, w, h, elements, levels); return float4(w, h, elements, levels); }
    return Layers.Load(int4(0, 0, int(pos.x), 0));
})",
                                                  3, 1, view.Get());
    ASSERT_EQ(pixels.size(), 3u);
    EXPECT_EQ(bytesOf(pixels[0]), colourAt(1, 1, 0, 0));
    EXPECT_EQ(bytesOf(pixels[1]), colourAt(2, 1, 0, 0));
    EXPECT_EQ(pixels[2], (Texel{1, 1, 2, 1}));
}

TEST(D3D11TextureArray, DrawsAndClearsReachOneSliceOnly) {
    Device d;
    ComPtr<ID3D11Texture2D> array = makeArray(d, D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_RENDER_TARGET);
    ASSERT_TRUE(array);
    D3D11_RENDER_TARGET_VIEW_DESC desc;
    desc.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE2DARRAY;
    desc.Texture2DArray = {0, 1, 1};  // level 0 of slice 1
    ComPtr<ID3D11RenderTargetView> slice1;
    ASSERT_EQ(d.device->CreateRenderTargetView(array.Get(), &desc, slice1.GetAddressOf()), S_OK) << lastError();
    drawInto(d, "float4 ps(float4 pos : SV_Position) : SV_Target { return float4(pos.x / 4.0, pos.y / 4.0, 1, 0.75); }\n", slice1.Get(), 2, 2, nullptr);
    EXPECT_EQ(lastError(), "");
    desc.Texture2DArray = {1, 2, 1};  // level 1 of slice 2
    ComPtr<ID3D11RenderTargetView> slice2;
    ASSERT_EQ(d.device->CreateRenderTargetView(array.Get(), &desc, slice2.GetAddressOf()), S_OK) << lastError();
    const float grey[4] = {0.2f, 0.4f, 0.6f, 0.8f};
    d.context->ClearRenderTargetView(slice2.Get(), grey);
    EXPECT_EQ(lastError(), "");
    // Slice 1, level 0: the pixel centres (x + 0.5) / 4 and (y + 0.5) / 4 in unorm8, alpha 0.75 (191.25:
    // no value at a rounding tie, which D3D and GL leave to the hardware; NVIDIA rounds 127.5 down).
    const std::vector<Rgba> drawn = readSubresource(d, array.Get(), 0 + 1 * kLevels, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x)
            EXPECT_EQ(drawn[std::size_t(y * 2 + x)], (Rgba{std::uint8_t(std::lround((x + 0.5) / 4 * 255)), std::uint8_t(std::lround((y + 0.5) / 4 * 255)), 255, 191}))
                << "texel " << x << "," << y;
    EXPECT_EQ(readSubresource(d, array.Get(), 1 + 2 * kLevels, 1), (std::vector<Rgba>{{51, 102, 153, 204}}));
    // Everything else as written.
    for (int slice = 0; slice < kSlices; ++slice)
        for (int level = 0; level < kLevels; ++level)
            if (!(slice == 1 && level == 0) && !(slice == 2 && level == 1)) {
                EXPECT_EQ(readSubresource(d, array.Get(), UINT(level + slice * kLevels), 2 >> level), levelTexels(slice, level))
                    << "slice " << slice << " level " << level;
            }
}

TEST(D3D11TextureArray, UpdateSubresourceAndStagingCopiesAddressOneSubresource) {
    Device d;
    ComPtr<ID3D11Texture2D> array = makeArray(d, D3D11_BIND_SHADER_RESOURCE);
    ASSERT_TRUE(array);
    const Rgba fresh = {1, 2, 3, 4};
    d.context->UpdateSubresource(array.Get(), 1 + 2 * kLevels, nullptr, &fresh, 4, 0);
    EXPECT_EQ(lastError(), "");
    // A staging array: CopyResource of every subresource, then Map of one.
    D3D11_TEXTURE2D_DESC desc = arrayDesc(0);
    desc.Usage = D3D11_USAGE_STAGING;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
    ComPtr<ID3D11Texture2D> staging;
    ASSERT_EQ(d.device->CreateTexture2D(&desc, nullptr, staging.GetAddressOf()), S_OK) << lastError();
    d.context->CopyResource(staging.Get(), array.Get());
    EXPECT_EQ(lastError(), "");
    D3D11_MAPPED_SUBRESOURCE mapped;
    ASSERT_EQ(d.context->Map(staging.Get(), 1 + 2 * kLevels, D3D11_MAP_READ, 0, &mapped), S_OK) << lastError();
    EXPECT_EQ(std::memcmp(mapped.pData, fresh.data(), 4), 0);
    d.context->Unmap(staging.Get(), 1 + 2 * kLevels);
    ASSERT_EQ(d.context->Map(staging.Get(), 0 + 1 * kLevels, D3D11_MAP_READ, 0, &mapped), S_OK) << lastError();
    const std::vector<Rgba> slice1 = levelTexels(1, 0);
    EXPECT_EQ(std::memcmp(mapped.pData, slice1.data(), 8), 0);
    EXPECT_EQ(std::memcmp(static_cast<const std::uint8_t*>(mapped.pData) + mapped.RowPitch, slice1.data() + 2, 8), 0);
    d.context->Unmap(staging.Get(), 0 + 1 * kLevels);
    EXPECT_EQ(d.context->Map(staging.Get(), UINT(kSlices * kLevels), D3D11_MAP_READ, 0, &mapped), E_INVALIDARG);
}

TEST(D3D11TextureArray, GenerateMipsAveragesEachSliceOnItsOwn) {
    Device d;
    ComPtr<ID3D11Texture2D> array = makeArray(d, D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_RENDER_TARGET, D3D11_RESOURCE_MISC_GENERATE_MIPS);
    ASSERT_TRUE(array);
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(array.Get(), nullptr, view.GetAddressOf()), S_OK) << lastError();
    d.context->GenerateMips(view.Get());
    EXPECT_EQ(lastError(), "");
    for (int slice = 0; slice < kSlices; ++slice) {
        const std::vector<Rgba> level0 = levelTexels(slice, 0);
        const std::vector<Rgba> level1 = readSubresource(d, array.Get(), UINT(1 + slice * kLevels), 1);
        ASSERT_EQ(level1.size(), 1u);
        for (int c = 0; c < 4; ++c) {
            const double mean = (level0[0][std::size_t(c)] + level0[1][std::size_t(c)] + level0[2][std::size_t(c)] + level0[3][std::size_t(c)]) / 4.0;
            EXPECT_NEAR(level1[0][std::size_t(c)], mean, 1.0) << "slice " << slice << " channel " << c;
        }
    }
}

TEST(D3D11TextureArray, AViewOfAnotherShapeBindsWithoutCrashing) {
    Device d;
    ComPtr<ID3D11Texture2D> array = makeArray(d, D3D11_BIND_SHADER_RESOURCE);
    ASSERT_TRUE(array);
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(array.Get(), nullptr, view.GetAddressOf()), S_OK) << lastError();
    // D3D binds it and leaves the result undefined: fxport draws (or notes why not), no more.
    ComPtr<ID3D11Texture2D> target = floatTarget(d, 1, 1);
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    drawInto(d, "Texture2D Flat : register(t0);\nfloat4 ps() : SV_Target { return Flat.Load(int3(0, 0, 0)); }\n", rtv.Get(), 1, 1, view.Get());
    EXPECT_EQ(lastError(), "");  // drawn: what the 2D read returns is undefined, as in D3D
    // The context's dimension check names t0, the view's 2D texture and the shader's cube; the draw is
    // skipped, nothing crashes.
    drawInto(d, "TextureCube Cube : register(t0);\nSamplerState S : register(s0);\nfloat4 ps() : SV_Target { return Cube.Sample(S, float3(1, 0, 0)); }\n", rtv.Get(), 1, 1,
             view.Get());
    EXPECT_NE(lastError().find("t0 holds a view of a 2D texture where the shader's 'Cube' is a cube texture"), std::string::npos) << lastError();
}

// A cascaded shadow map: a typeless depth array, each slice cleared through its own
// depth-stencil view, one slice drawn into (depth test and write, no colour target), then all
// slices read through one TEXTURE2DARRAY view.
TEST(D3D11TextureArray, ADepthArrayIsDrawnSliceBySliceAndSampledWhole) {
    Device d;
    D3D11_TEXTURE2D_DESC desc = arrayDesc(D3D11_BIND_DEPTH_STENCIL | D3D11_BIND_SHADER_RESOURCE, kSlices, 1);
    desc.Format = DXGI_FORMAT_R32_TYPELESS;
    ComPtr<ID3D11Texture2D> array;
    ASSERT_EQ(d.device->CreateTexture2D(&desc, nullptr, array.GetAddressOf()), S_OK) << lastError();
    std::vector<ComPtr<ID3D11DepthStencilView>> slices(kSlices);
    for (int slice = 0; slice < kSlices; ++slice) {
        D3D11_DEPTH_STENCIL_VIEW_DESC dsv;
        dsv.Format = DXGI_FORMAT_D32_FLOAT;
        dsv.ViewDimension = D3D11_DSV_DIMENSION_TEXTURE2DARRAY;
        dsv.Texture2DArray = {0, UINT(slice), 1};
        ASSERT_EQ(d.device->CreateDepthStencilView(array.Get(), &dsv, slices[std::size_t(slice)].GetAddressOf()), S_OK) << lastError();
        d.context->ClearDepthStencilView(slices[std::size_t(slice)].Get(), D3D11_CLEAR_DEPTH, 0.25f * float(slice + 1), 0);
    }
    const std::string text = R"(
float4 vs(uint id : SV_VertexID) : SV_Position {
    float2 corner = float2((id << 1) & 2, id & 2);
    return float4(corner * float2(2, -2) + float2(-1, 1), 0.125, 1);
}
float4 ps() : SV_Target { return 1; }
)";
    ComPtr<ID3DBlob> vsCode = compile(text, "vs", "vs_5_0"), psCode = compile(text, "ps", "ps_5_0");
    ASSERT_TRUE(vsCode && psCode);
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> ps;
    ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
    d.context->OMSetRenderTargets(0, nullptr, slices[1].Get());
    D3D11_VIEWPORT viewport;
    viewport.Width = viewport.Height = 2;
    d.context->RSSetViewports(1, &viewport);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->Draw(3, 0);
    EXPECT_EQ(lastError(), "");
    d.context->OMSetRenderTargets(0, nullptr, nullptr);

    D3D11_SHADER_RESOURCE_VIEW_DESC srv;
    srv.Format = DXGI_FORMAT_R32_FLOAT;
    srv.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2DARRAY;
    srv.Texture2DArray = {0, 1, 0, UINT(kSlices)};
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(array.Get(), &srv, view.GetAddressOf()), S_OK) << lastError();
    const std::vector<Texel> pixels = drawAndRead(d, R"(
Texture2DArray<float> Depth : register(t0);
float4 ps(float4 pos : SV_Position) : SV_Target {
    int2 p = int2(pos.xy);
    return Depth.Load(int4(p.x % 2, p.y, p.x / 2, 0));
})",
                                                  2 * kSlices, 2, view.Get());
    ASSERT_EQ(pixels.size(), std::size_t(4 * kSlices));
    const float expected[kSlices] = {0.25f, 0.125f, 0.75f};  // slice 1 drawn at z 0.125 over its 0.5
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2 * kSlices; ++x)
            EXPECT_EQ(pixels[std::size_t(y * 2 * kSlices + x)][0], expected[x / 2]) << "pixel " << x << "," << y;
}

// A view of slices 1 and 2 drawn into once: a geometry shader sends one triangle to each slice of
// the view through SV_RenderTargetArrayIndex, and a second draw without it reaches the view's
// first slice, as D3D's rule is; slice 0 (outside the view) keeps its texels.
TEST(D3D11TextureArray, ALayeredViewDrawsEachPrimitiveIntoTheSliceItNames) {
    Device d;
    ComPtr<ID3D11Texture2D> array = makeArray(d, D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_RENDER_TARGET);
    ASSERT_TRUE(array);
    D3D11_RENDER_TARGET_VIEW_DESC desc;
    desc.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE2DARRAY;
    desc.Texture2DArray = {0, 1, 2};
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(array.Get(), &desc, rtv.GetAddressOf()), S_OK) << lastError();
    const char* text = R"(
struct V { float4 pos : SV_Position; };
struct G { float4 pos : SV_Position; float4 colour : COLOR0; uint slice : SV_RenderTargetArrayIndex; };
V vs(uint id : SV_VertexID) { V v; float2 c = float2((id << 1) & 2, id & 2); v.pos = float4(c * float2(2, -2) + float2(-1, 1), 0, 1); return v; }
[maxvertexcount(6)]
void gs(triangle V input[3], inout TriangleStream<G> stream) {
    for (uint slice = 0; slice < 2; ++slice) {
        for (int i = 0; i < 3; ++i) {
            G g;
            g.pos = input[i].pos;
            g.colour = float4(slice == 0 ? 1 : 0, slice == 1 ? 1 : 0, 0, 1);
            g.slice = slice;
            stream.Append(g);
        }
        stream.RestartStrip();
    }
}
float4 ps(G g) : SV_Target { return g.colour; }
float4 psPlain(V v) : SV_Target { return float4(0, 0, 1, 1); }
)";
    ComPtr<ID3DBlob> vsCode = compile(text, "vs", "vs_5_0"), gsCode = compile(text, "gs", "gs_5_0"), psCode = compile(text, "ps", "ps_5_0");
    ASSERT_TRUE(vsCode && gsCode && psCode);
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11GeometryShader> gs;
    ComPtr<ID3D11PixelShader> ps;
    ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreateGeometryShader(gsCode->GetBufferPointer(), gsCode->GetBufferSize(), nullptr, gs.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    D3D11_VIEWPORT viewport;
    viewport.Width = viewport.Height = 2;
    d.context->RSSetViewports(1, &viewport);
    D3D11_RASTERIZER_DESC rd;
    rd.CullMode = D3D11_CULL_NONE;
    ComPtr<ID3D11RasterizerState> noCull;
    ASSERT_EQ(d.device->CreateRasterizerState(&rd, noCull.GetAddressOf()), S_OK);
    d.context->RSSetState(noCull.Get());
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->GSSetShader(gs.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->Draw(3, 0);
    EXPECT_EQ(lastError(), "");
    d.context->OMSetRenderTargets(0, nullptr, nullptr);
    const std::vector<Rgba> red(4, Rgba{255, 0, 0, 255}), green(4, Rgba{0, 255, 0, 255});
    EXPECT_EQ(readSubresource(d, array.Get(), 0 + 1 * kLevels, 2), red);    // the view's slice 0
    EXPECT_EQ(readSubresource(d, array.Get(), 0 + 2 * kLevels, 2), green);  // the view's slice 1
    EXPECT_EQ(readSubresource(d, array.Get(), 0, 2), levelTexels(0, 0));   // outside the view

    // No SV_RenderTargetArrayIndex: the view's first slice.
    ComPtr<ID3DBlob> plainCode = compile(text, "psPlain", "ps_5_0");
    ASSERT_TRUE(plainCode);
    ComPtr<ID3D11PixelShader> plain;
    ASSERT_EQ(d.device->CreatePixelShader(plainCode->GetBufferPointer(), plainCode->GetBufferSize(), nullptr, plain.GetAddressOf()), S_OK) << lastError();
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    d.context->GSSetShader(nullptr, nullptr, 0);
    d.context->PSSetShader(plain.Get(), nullptr, 0);
    d.context->Draw(3, 0);
    EXPECT_EQ(lastError(), "");
    d.context->OMSetRenderTargets(0, nullptr, nullptr);
    EXPECT_EQ(readSubresource(d, array.Get(), 0 + 1 * kLevels, 2), std::vector<Rgba>(4, Rgba{0, 0, 255, 255}));
    EXPECT_EQ(readSubresource(d, array.Get(), 0 + 2 * kLevels, 2), green);
}

TEST(D3D11TextureArray, DescriptionsOutsideTheTextureAreRefusedNamingTheField) {
    Device d;
    D3D11_TEXTURE2D_DESC desc = arrayDesc(D3D11_BIND_SHADER_RESOURCE, 0);
    ComPtr<ID3D11Texture2D> t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("ArraySize = 0"), std::string::npos) << lastError();
    desc = arrayDesc(D3D11_BIND_SHADER_RESOURCE, 4);
    desc.SampleDesc.Count = 4;
    desc.MipLevels = 1;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), E_NOTIMPL);
    EXPECT_NE(lastError().find("SampleDesc.Count = 4"), std::string::npos) << lastError();

    ComPtr<ID3D11Texture2D> array = makeArray(d, D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_RENDER_TARGET);

    ASSERT_TRUE(array);
    D3D11_SHADER_RESOURCE_VIEW_DESC srv;
    srv.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2DARRAY;
    srv.Texture2DArray = {0, UINT(-1), 2, 2};
    ComPtr<ID3D11ShaderResourceView> view;
    EXPECT_EQ(d.device->CreateShaderResourceView(array.Get(), &srv, view.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("Texture2DArray.FirstArraySlice + ArraySize = 2 + 2 (the texture has 3 slices)"), std::string::npos) << lastError();
    srv.Texture2DArray = {0, UINT(-1), 0, 0};
    EXPECT_EQ(d.device->CreateShaderResourceView(array.Get(), &srv, view.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("FirstArraySlice + ArraySize = 0 + 0"), std::string::npos) << lastError();
    srv.Texture2DArray = {2, 1, 0, 1};
    EXPECT_EQ(d.device->CreateShaderResourceView(array.Get(), &srv, view.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("Texture2DArray.MostDetailedMip = 2"), std::string::npos) << lastError();

    D3D11_RENDER_TARGET_VIEW_DESC rtv;
    rtv.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE2DARRAY;
    ComPtr<ID3D11RenderTargetView> target;
    rtv.Texture2DArray = {2, 0, 1};
    EXPECT_EQ(d.device->CreateRenderTargetView(array.Get(), &rtv, target.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("Texture2DArray.MipSlice = 2 (the texture has 2 levels)"), std::string::npos) << lastError();
    rtv.Texture2DArray = {0, 3, 1};
    EXPECT_EQ(d.device->CreateRenderTargetView(array.Get(), &rtv, target.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("FirstArraySlice + ArraySize = 3 + 1"), std::string::npos) << lastError();

    D3D11_TEXTURE2D_DESC depthDesc = arrayDesc(D3D11_BIND_DEPTH_STENCIL, kSlices, 1);
    depthDesc.Format = DXGI_FORMAT_D32_FLOAT;
    ComPtr<ID3D11Texture2D> depth;
    ASSERT_EQ(d.device->CreateTexture2D(&depthDesc, nullptr, depth.GetAddressOf()), S_OK) << lastError();
    D3D11_DEPTH_STENCIL_VIEW_DESC dsv;
    dsv.ViewDimension = D3D11_DSV_DIMENSION_TEXTURE2DARRAY;
    dsv.Texture2DArray = {0, 1, 3};
    ComPtr<ID3D11DepthStencilView> depthView;
    EXPECT_EQ(d.device->CreateDepthStencilView(depth.Get(), &dsv, depthView.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("D3D11_DEPTH_STENCIL_VIEW_DESC.Texture2DArray.FirstArraySlice + ArraySize = 1 + 3"), std::string::npos) << lastError();
    dsv.Texture2DArray = {0, 0, 3};  // every slice: a layered depth buffer
    EXPECT_EQ(d.device->CreateDepthStencilView(depth.Get(), &dsv, depthView.GetAddressOf()), S_OK) << lastError();
    depthDesc.BindFlags = D3D11_BIND_DEPTH_STENCIL | D3D11_BIND_UNORDERED_ACCESS;
    EXPECT_EQ(d.device->CreateTexture2D(&depthDesc, nullptr, depth.GetAddressOf()), E_NOTIMPL);
    EXPECT_NE(lastError().find("no UAV arrays"), std::string::npos) << lastError();
}

}  // namespace
}  // namespace d3d11test
