// fxport/d3d11/core_access.h from a D3D10 port's side: the device core under an ID3D10Device is the
// one its draws run on (a GpuTimer made on it counts the fragments of a D3D10 draw: a 2 x 4
// rectangle, 8 pixel centres), and the fxport::Effect under an ID3D10Effect is the tutorial's
// effect (deferred.fx, read in place: DeferredTechnique with one pass, compiled once applied -- what
// fxdemo's --explain reports).
#include <cstring>

#include <gtest/gtest.h>

#include "fxport/d3d10.h"
#include "fxport/d3d11/core_access.h"

namespace d3d10test {
namespace {

using namespace fxport::d3d10;

struct D3D10CoreAccess : ::testing::Test {
    ComPtr<ID3D10Device> device;
    void SetUp() override {
        ASSERT_EQ(D3D10CreateDevice(nullptr, D3D10_DRIVER_TYPE_HARDWARE, nullptr, 0, D3D10_SDK_VERSION, device.GetAddressOf()), S_OK)
            << GetLastErrorMessage();
    }
};

TEST_F(D3D10CoreAccess, ATimerOnTheCoreCountsAD3D10Draw) {
    fxport::GraphicsDevice& core = fxport::d3d11::CoreDeviceOf(*device->GetD3D11Device());
    EXPECT_EQ(&core, &fxport::d3d11::CoreDeviceOf(*device->GetD3D11Device()));

    D3D10_TEXTURE2D_DESC td;
    td.Width = td.Height = 8;
    td.MipLevels = td.ArraySize = 1;
    td.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    td.BindFlags = D3D10_BIND_RENDER_TARGET;
    ComPtr<ID3D10Texture2D> target;
    ComPtr<ID3D10RenderTargetView> rtv;
    ASSERT_EQ(device->CreateTexture2D(&td, nullptr, target.GetAddressOf()), S_OK) << GetLastErrorMessage();
    ASSERT_EQ(device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK) << GetLastErrorMessage();
    device->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    D3D10_VIEWPORT viewport;
    viewport.Width = viewport.Height = 8;
    device->RSSetViewports(1, &viewport);
    // x in [-1, -0.5] (pixels 0..1) by y in [0, 1] (rows 0..3).
    const char* text = R"(
static const float2 kCorners[6] = { float2(-1, 1), float2(-0.5, 1), float2(-0.5, 0), float2(-1, 1), float2(-0.5, 0), float2(-1, 0) };
float4 vs(uint id : SV_VertexID) : SV_Position { return float4(kCorners[id], 0, 1); }
float4 ps() : SV_Target { return 1; }
)";
    ComPtr<ID3DBlob> v, p;
    ASSERT_EQ(D3DCompile(text, std::strlen(text), "rect.hlsl", nullptr, nullptr, "vs", "vs_4_0", 0, 0, v.GetAddressOf(), nullptr), S_OK);
    ASSERT_EQ(D3DCompile(text, std::strlen(text), "rect.hlsl", nullptr, nullptr, "ps", "ps_4_0", 0, 0, p.GetAddressOf(), nullptr), S_OK);
    ComPtr<ID3D10VertexShader> vs;
    ComPtr<ID3D10PixelShader> ps;
    ASSERT_EQ(device->CreateVertexShader(v->GetBufferPointer(), v->GetBufferSize(), vs.GetAddressOf()), S_OK) << GetLastErrorMessage();
    ASSERT_EQ(device->CreatePixelShader(p->GetBufferPointer(), p->GetBufferSize(), ps.GetAddressOf()), S_OK) << GetLastErrorMessage();
    device->VSSetShader(vs.Get());
    device->PSSetShader(ps.Get());
    device->IASetPrimitiveTopology(D3D10_PRIMITIVE_TOPOLOGY_TRIANGLELIST);

    fxport::GpuTimer timer(core);
    timer.CountFragments(true);
    timer.Begin("rect");
    device->Draw(6, 0);
    timer.End();
    timer.EndFrame();
    timer.Finish();
    const fxport::GpuTimer::Section* rect = nullptr;
    for (const fxport::GpuTimer::Section& s : timer.Sections())
        if (s.name == "rect") rect = &s;
    ASSERT_NE(rect, nullptr);
    ASSERT_EQ(rect->fragments.size(), 1u);
    EXPECT_EQ(rect->fragments[0], 8.0);
}

TEST_F(D3D10CoreAccess, TheEffectUnderAD3D10EffectIsTheTutorials) {
    ComPtr<ID3D10Effect> effect;
    ComPtr<ID3D10Blob> errors;
    ASSERT_EQ(D3DX10CreateEffectFromFile(L"hlsl/rastertek/deferred.fx", nullptr, nullptr, "fx_4_0", D3D10_SHADER_ENABLE_STRICTNESS, 0,
                                         device.Get(), nullptr, nullptr, effect.GetAddressOf(), errors.GetAddressOf(), nullptr),
              S_OK)
        << GetLastErrorMessage();
    fxport::Effect& core = fxport::d3d11::CoreEffectOf(*effect->GetD3DX11Effect());
    ASSERT_EQ(core.Techniques.Count(), 1);
    EXPECT_EQ(core.Techniques[0]->Name(), "DeferredTechnique");
    EXPECT_EQ(core.Techniques[0]->Passes.Count(), 1);
    ASSERT_EQ(effect->GetTechniqueByName("DeferredTechnique")->GetPassByIndex(0)->Apply(0), S_OK) << GetLastErrorMessage();
    EXPECT_TRUE(core.Techniques[0]->IsCompiled());
}

}  // namespace
}  // namespace d3d10test
