// Compute and tessellation through the runtime (issue 23 item 4, issue 24 item 6), each checked
// against a CPU computation of the same math:
//   - a technique11 effect with SetComputeShader: a RWStructuredBuffer filled from a
//     StructuredBuffer, a second dispatch reading the first one's output (the runtime's barrier),
//     and a RWTexture2D read back texel by texel;
//   - a technique11 effect with SetHullShader/SetDomainShader drawing one quad patch: the domain
//     shader's colour (u, v, u*v) at every covered pixel, where u*v is only within bounds if the
//     hull shader's tessellation factor (8) reached the tessellator;
//   - the same patch with a clip distance the vertex shader writes and hull and domain shader pass
//     on (as Wicked Engine's tessellated objects do): the pixels where it is negative stay empty;
//   - misuse: DispatchCompute without a compute pass, a plain draw with a tessellation pass, a
//     UAV slot left empty.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "fxport/graphics.h"
#include "runtime_test_support.h"
#include "shader_sources/quad_patch_stages.h"

using namespace fxport;

namespace {

const char* const kComputeEffect = R"(cbuffer Params { float Scale; uint Count; };
StructuredBuffer<float> Input : register(t0);
RWStructuredBuffer<float> Squares : register(u0);
StructuredBuffer<float> SquaresIn : register(t1);
RWStructuredBuffer<float> Sum : register(u2);
RWTexture2D<float4> Image : register(u1);

[numthreads(64, 1, 1)]
void Square(uint3 id : SV_DispatchThreadID)
{
    if (id.x < Count) Squares[id.x] = Input[id.x] * Input[id.x] * Scale + id.x;
}

[numthreads(1, 1, 1)]
void Accumulate()
{
    float s = 0;
    for (uint i = 0; i < Count; ++i) s += SquaresIn[i];
    Sum[0] = s;
}

[numthreads(8, 8, 1)]
void Fill(uint3 id : SV_DispatchThreadID)
{
    Image[id.xy] = float4(id.x / 16.0, id.y / 16.0, sin(id.x * 0.3) * cos(id.y * 0.2), 1);
}

technique11 Compute
{
    pass Square { SetComputeShader(CompileShader(cs_5_0, Square())); }
    pass Accumulate { SetComputeShader(CompileShader(cs_5_0, Accumulate())); }
    pass Fill { SetComputeShader(CompileShader(cs_5_0, Fill())); }
}
)";

// One pass of the four tessellation stages VS, HS, DS and PS, each effect below declares.
const char* const kTessellationTechnique = R"(
technique11 Tessellate
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetHullShader(CompileShader(hs_5_0, HS()));
        SetDomainShader(CompileShader(ds_5_0, DS()));
        SetPixelShader(CompileShader(ps_5_0, PS()));
    }
}
)";

const std::string kTessellationEffect = std::string(fxport::test::kQuadPatchDeclarations) + fxport::test::kQuadPatchStages + kTessellationTechnique;

// The clip distance x + 0.25 from the vertex shader, through the hull shader's input and output
// patch, interpolated by the domain shader and written as its SV_ClipDistance0.
const std::string kClippedTessellationEffect = std::string(R"(struct ControlPoint { float3 pos : POSITION; float clip : SV_ClipDistance0; };
struct PatchConstants { float edges[4] : SV_TessFactor; float inside[2] : SV_InsideTessFactor; };
struct DomainOut { float4 pos : SV_Position; float clip : SV_ClipDistance0; float4 color : COLOR0; };

ControlPoint VS(float3 pos : POSITION) { ControlPoint o; o.pos = pos; o.clip = pos.x + 0.25; return o; }

PatchConstants Constants(InputPatch<ControlPoint, 4> patch)
{
    PatchConstants o;
    o.edges[0] = o.edges[1] = o.edges[2] = o.edges[3] = 4;
    o.inside[0] = o.inside[1] = 4;
    return o;
}

[domain("quad")]
[partitioning("integer")]
[outputtopology("triangle_cw")]
[outputcontrolpoints(4)]
[patchconstantfunc("Constants")]
ControlPoint HS(InputPatch<ControlPoint, 4> patch, uint i : SV_OutputControlPointID) { return patch[i]; }

[domain("quad")]
DomainOut DS(PatchConstants pc, float2 uv : SV_DomainLocation, const OutputPatch<ControlPoint, 4> patch)
{
    DomainOut o;
    o.pos = float4(lerp(lerp(patch[0].pos, patch[1].pos, uv.x), lerp(patch[3].pos, patch[2].pos, uv.x), uv.y), 1);
    o.clip = lerp(lerp(patch[0].clip, patch[1].clip, uv.x), lerp(patch[3].clip, patch[2].clip, uv.x), uv.y);
    o.color = 1;
    return o;
}

float4 PS(DomainOut i) : SV_Target { return i.color; }
)") + kTessellationTechnique;

EffectPass& pass(Effect& effect, const std::string& name) {
    for (EffectPass& p : effect.CurrentTechnique->Passes)
        if (p.Name() == name) return p;
    throw std::runtime_error("no pass " + name);
}

}  // namespace

TEST(D3D11Stages, ComputeShaderFillsStructuredBuffersLikeTheCpu) {
    GraphicsDevice& device = test::testDevice();
    Effect effect(device, EffectSource{kComputeEffect, "compute.fx"});
    const int count = 200;  // not a multiple of the group size: the shader's bound check matters
    std::vector<float> input(count);
    for (int i = 0; i < count; ++i) input[std::size_t(i)] = 0.25f * float(i) - 7.0f;
    StructuredBuffer in(device, 4, count), squares(device, 4, 256), sum(device, 4, 1);
    in.SetData(input);
    std::vector<float> sentinel(256, -1.0f);
    squares.SetData(sentinel);
    effect.Parameters["Scale"].SetValue(1.5f);
    effect.Parameters["Count"].SetValue(count);

    device.SetShaderResource(0, in);
    device.SetUnorderedAccess(0, squares);
    pass(effect, "Square").Apply();
    device.DispatchCompute((count + 63) / 64, 1, 1);
    // The second dispatch reads what the first wrote: the runtime's barrier between them.
    device.SetShaderResource(1, squares);
    device.SetUnorderedAccess(2, sum);
    pass(effect, "Accumulate").Apply();
    device.DispatchCompute(1, 1, 1);

    std::vector<float> got = squares.GetData<float>();
    float cpuSum = 0;
    for (int i = 0; i < 256; ++i) {
        if (i >= count) {
            EXPECT_EQ(got[std::size_t(i)], -1.0f) << "element " << i << " is past Count and must stay untouched";
            continue;
        }
        float x = input[std::size_t(i)];
        float expected = x * x * 1.5f + float(i);
        cpuSum += expected;
        EXPECT_NEAR(got[std::size_t(i)], expected, std::abs(expected) * 2e-7f + 1e-6f) << "element " << i;
    }
    EXPECT_NEAR(sum.GetData<float>()[0], cpuSum, std::abs(cpuSum) * 1e-6f);
    device.SetShaderResource(0, nullptr);
    device.SetShaderResource(1, nullptr);
}

TEST(D3D11Stages, ComputeShaderWritesARWTexture2DLikeTheCpu) {
    GraphicsDevice& device = test::testDevice();
    Effect effect(device, EffectSource{kComputeEffect, "compute.fx"});
    RenderTarget2D image(device, 16, 16, false, SurfaceFormat::Vector4, DepthFormat::None);
    device.SetUnorderedAccess(1, &image);
    pass(effect, "Fill").Apply();
    device.DispatchCompute(2, 2, 1);
    device.SetUnorderedAccess(1, static_cast<Texture2D*>(nullptr));
    std::vector<float> texels = test::readFloats(image);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            const float* t = &texels[std::size_t((y * 16 + x) * 4)];
            EXPECT_FLOAT_EQ(t[0], float(x) / 16.0f) << x << "," << y;
            EXPECT_FLOAT_EQ(t[1], float(y) / 16.0f) << x << "," << y;
            // GLSL's sin/cos on llvmpipe: within 1e-5 of the double-precision value here.
            EXPECT_NEAR(t[2], std::sin(x * 0.3) * std::cos(y * 0.2), 1e-5) << x << "," << y;
            EXPECT_EQ(t[3], 1.0f);
        }
}

TEST(D3D11Stages, TessellatedQuadMatchesTheDomainShaderOnTheCpu) {
    GraphicsDevice& device = test::testDevice();
    Effect effect(device, EffectSource{kTessellationEffect, "tessellate.fx"});
    const int size = 64;
    RenderTarget2D target(device, size, size, false, SurfaceFormat::Vector4, DepthFormat::None);
    device.SetRenderTarget(target);
    device.Clear(ClearOptions::Target, Vector4(0, 0, 0, 0), 1, 0);
    // Control points: top-left, top-right, bottom-right, bottom-left of NDC [-0.5, 0.5]^2.
    std::vector<VertexPositionTexture> corners = {
        {Vector3(-0.5f, 0.5f, 0), Vector2(0, 0)}, {Vector3(0.5f, 0.5f, 0), Vector2(0, 0)},
        {Vector3(0.5f, -0.5f, 0), Vector2(0, 0)}, {Vector3(-0.5f, -0.5f, 0), Vector2(0, 0)}};
    VertexBuffer vb(device, VertexPositionTexture::VertexDeclaration, 4);
    vb.SetData(corners);
    device.SetVertexBuffer(vb);
    device.RasterizerState = RasterizerState::CullNone;
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::None;
    const float factor = 8;
    effect.Parameters["Factor"].SetValue(factor);
    effect.CurrentTechnique->Passes[0].Apply();
    device.DrawPatches(4, 0, 1);
    device.SetVertexBuffer(nullptr);
    device.SetRenderTarget(nullptr);

    std::vector<float> texels = test::readFloats(target);
    int inside = 0;
    double worstUV = 0, worstProduct = 0;
    for (int py = 0; py < size; ++py)
        for (int px = 0; px < size; ++px) {
            // The pixel centre in NDC (y up, row 0 at the top), then in the patch's (u, v).
            double x = (px + 0.5) / (size / 2.0) - 1, y = 1 - (py + 0.5) / (size / 2.0);
            double u = x + 0.5, v = 0.5 - y;
            const float* t = &texels[std::size_t((py * size + px) * 4)];
            const double edge = 1.0 / size;  // pixels on the quad's border follow GL's fill rule
            if (u < -edge || u > 1 + edge || v < -edge || v > 1 + edge) {
                EXPECT_EQ(t[3], 0.0f) << "pixel " << px << "," << py << " is outside the patch";
                continue;
            }
            if (u < edge || u > 1 - edge || v < edge || v > 1 - edge) continue;
            ++inside;
            EXPECT_EQ(t[3], 1.0f) << "pixel " << px << "," << py << " is inside the patch";
            worstUV = std::max({worstUV, std::abs(t[0] - u), std::abs(t[1] - v)});
            worstProduct = std::max(worstProduct, std::abs(t[2] - u * v));
        }
    EXPECT_EQ(inside, (size / 2) * (size / 2));  // the 32x32 pixels the patch covers
    // u and v are affine over the patch: exact up to interpolation rounding.
    EXPECT_LT(worstUV, 1e-4);
    // u*v is interpolated linearly inside each tessellated triangle: off by at most
    // du*dv/4 = 1/(4*8*8) ~ 0.0039 with factor 8; with 4 it could be 0.0156, untessellated 0.25.
    EXPECT_LT(worstProduct, 1.0 / (4 * factor * factor) + 1e-4);
    EXPECT_GT(worstProduct, 1e-3) << "u*v exact everywhere: the triangles were not interpolating at all?";
}

TEST(D3D11Stages, ClipDistancePassedThroughHullAndDomainShaderClips) {
    GraphicsDevice& device = test::testDevice();
    Effect effect(device, EffectSource{kClippedTessellationEffect, "clipped_tessellation.fx"});
    const int size = 64;
    RenderTarget2D target(device, size, size, false, SurfaceFormat::Vector4, DepthFormat::None);
    device.SetRenderTarget(target);
    device.Clear(ClearOptions::Target, Vector4(0, 0, 0, 0), 1, 0);
    std::vector<VertexPositionTexture> corners = {
        {Vector3(-0.5f, 0.5f, 0), Vector2(0, 0)}, {Vector3(0.5f, 0.5f, 0), Vector2(0, 0)},
        {Vector3(0.5f, -0.5f, 0), Vector2(0, 0)}, {Vector3(-0.5f, -0.5f, 0), Vector2(0, 0)}};
    VertexBuffer vb(device, VertexPositionTexture::VertexDeclaration, 4);
    vb.SetData(corners);
    device.SetVertexBuffer(vb);
    device.RasterizerState = RasterizerState::CullNone;
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::None;
    effect.CurrentTechnique->Passes[0].Apply();
    device.DrawPatches(4, 0, 1);
    device.SetVertexBuffer(nullptr);
    device.SetRenderTarget(nullptr);

    std::vector<float> texels = test::readFloats(target);
    int drawn = 0, clipped = 0;
    for (int py = 0; py < size; ++py)
        for (int px = 0; px < size; ++px) {
            const double x = (px + 0.5) / (size / 2.0) - 1, y = 1 - (py + 0.5) / (size / 2.0);
            const double edge = 2.0 / size;  // a pixel from any edge: GL's fill rule decides there
            if (std::abs(y) > 0.5 - edge || x < -0.5 + edge || x > 0.5 - edge || std::abs(x + 0.25) < edge) continue;
            const float alpha = texels[std::size_t((py * size + px) * 4 + 3)];
            if (x + 0.25 < 0) {
                EXPECT_EQ(alpha, 0.0f) << "pixel " << px << "," << py << " has a negative clip distance";
                ++clipped;
            } else {
                EXPECT_EQ(alpha, 1.0f) << "pixel " << px << "," << py << " has a positive clip distance";
                ++drawn;
            }
        }
    EXPECT_GT(clipped, 100);
    EXPECT_GT(drawn, 300);
}

TEST(D3D11Stages, MisuseIsAClearError) {
    GraphicsDevice& device = test::testDevice();
    Effect tessellation(device, EffectSource{kTessellationEffect, "tessellate.fx"});
    Effect compute(device, EffectSource{kComputeEffect, "compute.fx"});
    RenderTarget2D target(device, 8, 8, false, SurfaceFormat::Vector4, DepthFormat::None);
    device.SetRenderTarget(target);
    tessellation.CurrentTechnique->Passes[0].Apply();
    std::vector<VertexPositionTexture> corners(4);
    VertexBuffer vb(device, VertexPositionTexture::VertexDeclaration, 4);
    vb.SetData(corners);
    device.SetVertexBuffer(vb);
    try {
        device.DrawPrimitives(PrimitiveType::TriangleList, 0, 1);
        ADD_FAILURE() << "a triangle list through hull and domain shaders must be refused";
    } catch (const InvalidOperation& e) {
        EXPECT_NE(std::string(e.what()).find("DrawPatches"), std::string::npos) << e.what();
    }
    EXPECT_THROW(device.DrawPatches(0, 0, 1), ArgumentError);
    EXPECT_THROW(device.DrawPatches(4, 1, 1), ArgumentError);  // overruns the 4 vertices
    device.SetVertexBuffer(nullptr);
    device.SetRenderTarget(nullptr);

    // A compute pass whose UAV slot is empty names the variable and the register.
    device.SetUnorderedAccess(0, static_cast<StructuredBuffer*>(nullptr));
    StructuredBuffer in(device, 4, 4);
    device.SetShaderResource(0, in);
    pass(compute, "Square").Apply();
    try {
        device.DispatchCompute(1, 1, 1);
        ADD_FAILURE() << "a dispatch with an empty UAV slot must be refused";
    } catch (const InvalidOperation& e) {
        EXPECT_NE(std::string(e.what()).find("'Squares' (register u0)"), std::string::npos) << e.what();
    }
    EXPECT_THROW(device.DispatchCompute(70000, 1, 1), ArgumentError);
    EXPECT_THROW(StructuredBuffer(device, 6, 4), ArgumentError);  // stride not a multiple of 4
    device.SetShaderResource(0, nullptr);
}
