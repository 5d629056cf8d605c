// AlphaTestEffect.fx: XNA 4's AlphaTestEffect (fxport/graphics/alpha_test_effect.h): textured,
// unlit, with optional vertex colour and fog, discarding pixels whose alpha fails the comparison.
// Techniques AlphaTestEffect_C<compare>_V<vertex colour>_F<fog>: compare 0 tests
// "alpha < AlphaTest.x" (Less, LessEqual, Greater, GreaterEqual, Always, Never), compare 1 tests
// "|alpha - AlphaTest.x| < AlphaTest.y" (Equal, NotEqual). The pixel is kept when the test's result
// selects a positive sign: AlphaTest.z when it holds, AlphaTest.w when not.

texture Texture;
sampler TextureSampler : register(s0) = sampler_state
{
    Texture = <Texture>;
};

float4 AlphaTest;

struct VSInput
{
    float4 Position : POSITION0;
    float2 TexCoord : TEXCOORD0;
    float4 Color : COLOR0;
};

struct VSOutput
{
    float4 PositionPS : POSITION0;
    float4 Diffuse : TEXCOORD0;
    float2 TexCoord : TEXCOORD1;
    float Fog : TEXCOORD2;
};

VSOutput VSAlphaTest(VSInput vin, uniform bool vertexColor, uniform bool fog)
{
    VSOutput vout;
    vout.PositionPS = mul(vin.Position, WorldViewProj);
    vout.Diffuse = DiffuseColor;
    if (vertexColor)
        vout.Diffuse *= vin.Color;
    vout.Diffuse = ColorOutput(vout.Diffuse);
    vout.TexCoord = vin.TexCoord;
    vout.Fog = 0;
    if (fog)
        vout.Fog = ComputeFogFactor(vin.Position);
    return vout;
}

float4 PSAlphaTest(VSOutput pin, uniform int compare, uniform bool fog) : COLOR0
{
    float4 color = tex2D(TextureSampler, pin.TexCoord) * pin.Diffuse;
    bool holds;
    if (compare == 0)
        holds = color.a < AlphaTest.x;
    else
        holds = abs(color.a - AlphaTest.x) < AlphaTest.y;
    float keep = AlphaTest.w;
    if (holds)
        keep = AlphaTest.z;
    clip(keep);
    if (fog)
        color = ApplyFog(color, pin.Fog);
    return color;
}

#define ALPHA_TEST_TECHNIQUE(C, V, F) \
    technique AlphaTestEffect_C##C##_V##V##_F##F \
    { \
        pass \
        { \
            VertexShader = compile vs_3_0 VSAlphaTest(STOCK_FLAG_##V, STOCK_FLAG_##F); \
            PixelShader = compile ps_3_0 PSAlphaTest(C, STOCK_FLAG_##F); \
        } \
    }

ALPHA_TEST_TECHNIQUE(0, 0, 0) ALPHA_TEST_TECHNIQUE(0, 0, 1) ALPHA_TEST_TECHNIQUE(0, 1, 0) ALPHA_TEST_TECHNIQUE(0, 1, 1)
ALPHA_TEST_TECHNIQUE(1, 0, 0) ALPHA_TEST_TECHNIQUE(1, 0, 1) ALPHA_TEST_TECHNIQUE(1, 1, 0) ALPHA_TEST_TECHNIQUE(1, 1, 1)
