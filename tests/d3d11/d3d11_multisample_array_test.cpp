// Multisampled array textures through the D3D11 front end (Texture2DMSArray: ArraySize 3,
// SampleDesc.Count 4, R32G32B32A32_FLOAT). A pixel shader run per sample writes 16 * slice + 2^sample
// into each sample: slice 0 through a one-slice TEXTURE2DMSARRAY render-target view, slices 1 and 2
// through a layered view a geometry shader picks the slice of (SV_RenderTargetArrayIndex).
// ResolveSubresource of each slice gives the CPU mean, 16 * slice + 3.75 (into a 2D texture, and
// into a slice of a single-sample array); a TEXTURE2DMSARRAY shader-resource view of slices 1-2 reads
// every sample back (Texture2DMSArray.Load, GetDimensions). And the descriptions D3D refuses, with
// the field and value.
#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

using Texel = std::array<float, 4>;
constexpr UINT kSize = 4, kSamples = 4, kSlices = 3;

const char* const kFullScreen = R"(
struct V { float4 pos : SV_Position; };
V vs(uint id : SV_VertexID) { V v; float2 c = float2((id << 1) & 2, id & 2); v.pos = float4(c * float2(2, -2) + float2(-1, 1), 0, 1); return v; }
)";

// Each sample: 16 * slice + 2^sample, the sample index in w.
const char* const kPerSample = R"(
struct G { float4 pos : SV_Position; uint slice : SV_RenderTargetArrayIndex; };
[maxvertexcount(6)]
void gs(triangle V input[3], inout TriangleStream<G> stream) {
    for (uint slice = 0; slice < 2; ++slice) {
        for (int i = 0; i < 3; ++i) { G g; g.pos = input[i].pos; g.slice = slice; stream.Append(g); }
        stream.RestartStrip();
    }
}
float4 psLayered(G g, uint id : SV_SampleIndex) : SV_Target { return float4(16 * (g.slice + 1) + (1u << id), g.pos.x, g.pos.y, id); }
float4 psSlice0(V v, uint id : SV_SampleIndex) : SV_Target { return float4(1u << id, v.pos.x, v.pos.y, id); }
)";

D3D11_TEXTURE2D_DESC arrayDesc(UINT samples, UINT slices = kSlices) {
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = desc.Height = kSize;
    desc.MipLevels = 1;
    desc.ArraySize = slices;
    desc.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    desc.SampleDesc.Count = samples;
    desc.BindFlags = D3D11_BIND_RENDER_TARGET | D3D11_BIND_SHADER_RESOURCE;
    return desc;
}

template <class Shader>
ComPtr<Shader> make(Device& d, const std::string& text, const char* entry, const char* target) {
    ComPtr<ID3DBlob> code = compile(text, entry, target);
    EXPECT_TRUE(code);
    ComPtr<Shader> shader;
    if (!code) return shader;
    HRESULT hr = E_FAIL;
    if constexpr (std::is_same_v<Shader, ID3D11VertexShader>)
        hr = d.device->CreateVertexShader(code->GetBufferPointer(), code->GetBufferSize(), nullptr, shader.GetAddressOf());
    else if constexpr (std::is_same_v<Shader, ID3D11GeometryShader>)
        hr = d.device->CreateGeometryShader(code->GetBufferPointer(), code->GetBufferSize(), nullptr, shader.GetAddressOf());
    else
        hr = d.device->CreatePixelShader(code->GetBufferPointer(), code->GetBufferSize(), nullptr, shader.GetAddressOf());
    EXPECT_EQ(hr, S_OK) << lastError();
    return shader;
}

// A full-screen triangle into `rtv` (kSize square) with `ps`, `gs` if given and `view` at t0 if given.
void draw(Device& d, ID3D11RenderTargetView* rtv, ID3D11PixelShader* ps, ID3D11GeometryShader* gs = nullptr, ID3D11ShaderResourceView* view = nullptr) {
    ComPtr<ID3D11VertexShader> vs = make<ID3D11VertexShader>(d, kFullScreen, "vs", "vs_5_0");
    ID3D11ShaderResourceView* none = nullptr;
    d.context->PSSetShaderResources(0, 1, &none);
    d.context->OMSetRenderTargets(1, &rtv, nullptr);
    D3D11_VIEWPORT viewport;
    viewport.Width = viewport.Height = float(kSize);
    d.context->RSSetViewports(1, &viewport);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->GSSetShader(gs, nullptr, 0);
    d.context->PSSetShader(ps, nullptr, 0);
    if (view) d.context->PSSetShaderResources(0, 1, &view);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->Draw(3, 0);
    EXPECT_EQ(lastError(), "");
    d.context->OMSetRenderTargets(0, nullptr, nullptr);
}

ComPtr<ID3D11Texture2D> singleTarget(Device& d, UINT slices = 1) {
    D3D11_TEXTURE2D_DESC desc = arrayDesc(1, slices);
    desc.BindFlags = D3D11_BIND_RENDER_TARGET;
    ComPtr<ID3D11Texture2D> t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), S_OK) << lastError();
    return t;
}

// Slice `slice` of a single-sample array, through a staging copy mapped for reading.
std::vector<Texel> readSlice(Device& d, ID3D11Texture2D* array, UINT slice) {
    D3D11_TEXTURE2D_DESC desc;
    array->GetDesc(&desc);
    desc.Usage = D3D11_USAGE_STAGING;
    desc.BindFlags = 0;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
    ComPtr<ID3D11Texture2D> staging;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, staging.GetAddressOf()), S_OK) << lastError();
    if (!staging) return {};
    d.context->CopyResource(staging.Get(), array);
    D3D11_MAPPED_SUBRESOURCE mapped;
    EXPECT_EQ(d.context->Map(staging.Get(), slice, D3D11_MAP_READ, 0, &mapped), S_OK) << lastError();
    std::vector<Texel> texels(kSize * kSize);
    for (UINT y = 0; y < kSize; ++y)
        std::memcpy(&texels[y * kSize], static_cast<const std::uint8_t*>(mapped.pData) + y * mapped.RowPitch, kSize * sizeof(Texel));
    d.context->Unmap(staging.Get(), slice);
    return texels;
}

TEST(D3D11MultisampleArray, SlicesDrawResolveAndLoadSampleBySample) {
    Device d;
    D3D11_TEXTURE2D_DESC desc = arrayDesc(kSamples);
    ComPtr<ID3D11Texture2D> samples;
    ASSERT_EQ(d.device->CreateTexture2D(&desc, nullptr, samples.GetAddressOf()), S_OK) << lastError();

    // Slice 0 alone, then slices 1 and 2 as one layered view.
    D3D11_RENDER_TARGET_VIEW_DESC rtvDesc;
    rtvDesc.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE2DMSARRAY;
    rtvDesc.Texture2DMSArray = {0, 1};
    ComPtr<ID3D11RenderTargetView> slice0, layered;
    ASSERT_EQ(d.device->CreateRenderTargetView(samples.Get(), &rtvDesc, slice0.GetAddressOf()), S_OK) << lastError();
    rtvDesc.Texture2DMSArray = {1, 2};
    ASSERT_EQ(d.device->CreateRenderTargetView(samples.Get(), &rtvDesc, layered.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11RenderTargetView> whole;
    ASSERT_EQ(d.device->CreateRenderTargetView(samples.Get(), nullptr, whole.GetAddressOf()), S_OK) << lastError();
    whole->GetDesc(&rtvDesc);
    EXPECT_EQ(rtvDesc.ViewDimension, D3D11_RTV_DIMENSION_TEXTURE2DMSARRAY);
    EXPECT_EQ(rtvDesc.Texture2DMSArray.ArraySize, kSlices);
    const std::string text = std::string(kFullScreen) + kPerSample;
    ComPtr<ID3D11PixelShader> psSlice0 = make<ID3D11PixelShader>(d, text, "psSlice0", "ps_5_0");
    ComPtr<ID3D11PixelShader> psLayered = make<ID3D11PixelShader>(d, text, "psLayered", "ps_5_0");
    ComPtr<ID3D11GeometryShader> gs = make<ID3D11GeometryShader>(d, text, "gs", "gs_5_0");
    ASSERT_TRUE(psSlice0 && psLayered && gs);
    draw(d, slice0.Get(), psSlice0.Get());
    draw(d, layered.Get(), psLayered.Get(), gs.Get());

    // Each slice resolved: the mean of its four samples, 16 * slice + (1 + 2 + 4 + 8) / 4.
    ComPtr<ID3D11Texture2D> single = singleTarget(d);
    for (UINT slice = 0; slice < kSlices; ++slice) {
        d.context->ResolveSubresource(single.Get(), 0, samples.Get(), slice, DXGI_FORMAT_R32G32B32A32_FLOAT);
        EXPECT_EQ(lastError(), "");
        const std::vector<Texel> mean = readTexels<Texel>(d, single.Get());
        ASSERT_EQ(mean.size(), std::size_t(kSize * kSize));
        for (UINT i = 0; i < kSize * kSize; ++i) {
            EXPECT_EQ(mean[i][0], 16.0f * float(slice) + 3.75f) << "slice " << slice << ", pixel " << i;
            EXPECT_EQ(mean[i][1], float(i % kSize) + 0.5f) << "slice " << slice << ", pixel " << i;
            EXPECT_EQ(mean[i][3], 1.5f) << "slice " << slice << ", pixel " << i;
        }
    }
    // Into slice 1 of a single-sample array (DstSubresource 1): slice 0 keeps its clear.
    ComPtr<ID3D11Texture2D> singleArray = singleTarget(d, 2);
    ComPtr<ID3D11RenderTargetView> singleArrayRtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(singleArray.Get(), nullptr, singleArrayRtv.GetAddressOf()), S_OK) << lastError();
    const float clear[4] = {-1, -1, -1, -1};
    d.context->ClearRenderTargetView(singleArrayRtv.Get(), clear);
    d.context->ResolveSubresource(singleArray.Get(), 1, samples.Get(), 2, DXGI_FORMAT_R32G32B32A32_FLOAT);
    EXPECT_EQ(lastError(), "");
    EXPECT_EQ(readSlice(d, singleArray.Get(), 0), std::vector<Texel>(kSize * kSize, Texel{-1, -1, -1, -1}));
    const std::vector<Texel> resolved = readSlice(d, singleArray.Get(), 1);
    ASSERT_EQ(resolved.size(), std::size_t(kSize * kSize));
    for (UINT i = 0; i < kSize * kSize; ++i) EXPECT_EQ(resolved[i][0], 32.0f + 3.75f) << "pixel " << i;

    // Every sample of slices 1 and 2 through a TEXTURE2DMSARRAY view of them: layer l of the view is slice l + 1.
    D3D11_SHADER_RESOURCE_VIEW_DESC srvDesc;
    srvDesc.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2DMSARRAY;
    srvDesc.Texture2DMSArray = {1, 2};
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(samples.Get(), &srvDesc, view.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11RenderTargetView> singleRtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(single.Get(), nullptr, singleRtv.GetAddressOf()), S_OK) << lastError();
    for (UINT layer = 0; layer < 2; ++layer)
        for (UINT s = 0; s < kSamples; ++s) {
            const std::string load = std::string(kFullScreen) + R"(
Texture2DMSArray<float4> Samples : register(t0);
float4 ps(float4 pos : SV_Position) : SV_Target {
    uint w, h, elements, n;
    Samples.GetDimensions(w, h, elements, n);
    float4 v = Samples.Load(int3(pos.xy, )" + std::to_string(layer) + "), " + std::to_string(s) + R"();
    return float4(v.x, v.w, elements * 10 + n, w * 100 + h);
})";
            ComPtr<ID3D11PixelShader> ps = make<ID3D11PixelShader>(d, load, "ps", "ps_5_0");
            ASSERT_TRUE(ps);
            draw(d, singleRtv.Get(), ps.Get(), nullptr, view.Get());
            const std::vector<Texel> got = readTexels<Texel>(d, single.Get());
            const Texel expected{16.0f * float(layer + 1) + float(1u << s), float(s), 2 * 10 + float(kSamples), float(kSize * 100 + kSize)};
            for (UINT i = 0; i < kSize * kSize; ++i) EXPECT_EQ(got[i], expected) << "layer " << layer << ", sample " << s << ", pixel " << i;
        }
}

TEST(D3D11MultisampleArray, RefusedDescriptionsViewsAndResolvesNameTheField) {
    Device d;
    ComPtr<ID3D11Texture2D> t;
    D3D11_TEXTURE2D_DESC desc = arrayDesc(kSamples);
    desc.MipLevels = 2;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("MipLevels = 2 for a multisampled texture"), std::string::npos) << lastError();
    desc = arrayDesc(kSamples);
    desc.BindFlags = D3D11_BIND_RENDER_TARGET | D3D11_BIND_UNORDERED_ACCESS;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("BindFlags = 160"), std::string::npos) << lastError();
    desc = arrayDesc(kSamples);
    desc.Format = DXGI_FORMAT_D32_FLOAT;
    desc.BindFlags = D3D11_BIND_DEPTH_STENCIL;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), E_NOTIMPL);
    EXPECT_NE(lastError().find("BindFlags = 64 with ArraySize = 3 and SampleDesc.Count = 4"), std::string::npos) << lastError();
    desc = arrayDesc(kSamples);
    desc.MiscFlags = D3D11_RESOURCE_MISC_TEXTURECUBE;
    desc.ArraySize = 6;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("MiscFlags = 4 for a multisampled texture"), std::string::npos) << lastError();

    desc = arrayDesc(kSamples);
    ComPtr<ID3D11Texture2D> samples;
    ASSERT_EQ(d.device->CreateTexture2D(&desc, nullptr, samples.GetAddressOf()), S_OK) << lastError();
    D3D11_SHADER_RESOURCE_VIEW_DESC srv;
    srv.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2DARRAY;
    srv.Texture2DArray = {0, 1, 0, kSlices};
    ComPtr<ID3D11ShaderResourceView> view;
    EXPECT_EQ(d.device->CreateShaderResourceView(samples.Get(), &srv, view.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("ViewDimension = 5 for a multisampled array texture"), std::string::npos) << lastError();
    srv.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2DMSARRAY;
    srv.Texture2DMSArray = {2, 2};
    EXPECT_EQ(d.device->CreateShaderResourceView(samples.Get(), &srv, view.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("Texture2DMSArray.FirstArraySlice + ArraySize = 2 + 2 (the texture has 3 slices)"), std::string::npos) << lastError();
    D3D11_RENDER_TARGET_VIEW_DESC rtv;
    rtv.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE2DMSARRAY;
    rtv.Texture2DMSArray = {0, 0};
    ComPtr<ID3D11RenderTargetView> target;
    EXPECT_EQ(d.device->CreateRenderTargetView(samples.Get(), &rtv, target.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("Texture2DMSArray.FirstArraySlice + ArraySize = 0 + 0"), std::string::npos) << lastError();
    rtv.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE2DMS;
    EXPECT_EQ(d.device->CreateRenderTargetView(samples.Get(), &rtv, target.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("ViewDimension = 6 for a multisampled array texture"), std::string::npos) << lastError();

    ComPtr<ID3D11Texture2D> single = singleTarget(d);
    d.context->ResolveSubresource(single.Get(), 0, samples.Get(), kSlices, DXGI_FORMAT_R32G32B32A32_FLOAT);
    EXPECT_NE(lastError().find("SrcSubresource = 3 (the source has 3 slices of one level)"), std::string::npos) << lastError();
    d.context->ResolveSubresource(single.Get(), 1, samples.Get(), 0, DXGI_FORMAT_R32G32B32A32_FLOAT);
    EXPECT_NE(lastError().find("DstSubresource = 1 (the destination has 1)"), std::string::npos) << lastError();
    ComPtr<ID3D11Texture2D> other;
    ASSERT_EQ(d.device->CreateTexture2D(&desc, nullptr, other.GetAddressOf()), S_OK) << lastError();
    d.context->CopyResource(other.Get(), samples.Get());
    EXPECT_NE(lastError().find("CopyResource: multisampled arrays (SampleDesc.Count = 4)"), std::string::npos) << lastError();
}

}  // namespace
}  // namespace d3d11test
