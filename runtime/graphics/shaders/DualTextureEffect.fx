// DualTextureEffect.fx: XNA 4's DualTextureEffect (fxport/graphics/dual_texture_effect.h): two
// textures with two texture-coordinate sets, the second a "2x modulate" detail or light map:
// colour = Texture * (2, 2, 2, 1) * Texture2 * diffuse, on all four channels: the second texture's
// alpha multiplies too, as in XNA's own shader.
// Techniques DualTextureEffect_V<vertex colour>_F<fog>.

texture Texture;
sampler TextureSampler : register(s0) = sampler_state
{
    Texture = <Texture>;
};

texture Texture2;
sampler Texture2Sampler : register(s1) = sampler_state
{
    Texture = <Texture2>;
};

struct VSInput
{
    float4 Position : POSITION0;
    float2 TexCoord : TEXCOORD0;
    float2 TexCoord2 : TEXCOORD1;
    float4 Color : COLOR0;
};

struct VSOutput
{
    float4 PositionPS : POSITION0;
    float4 Diffuse : TEXCOORD0;
    float2 TexCoord : TEXCOORD1;
    float2 TexCoord2 : TEXCOORD2;
    float Fog : TEXCOORD3;
};

VSOutput VSDualTexture(VSInput vin, uniform bool vertexColor, uniform bool fog)
{
    VSOutput vout;
    vout.PositionPS = mul(vin.Position, WorldViewProj);
    vout.Diffuse = DiffuseColor;
    if (vertexColor)
        vout.Diffuse *= vin.Color;
    vout.Diffuse = ColorOutput(vout.Diffuse);
    vout.TexCoord = vin.TexCoord;
    vout.TexCoord2 = vin.TexCoord2;
    vout.Fog = 0;
    if (fog)
        vout.Fog = ComputeFogFactor(vin.Position);
    return vout;
}

float4 PSDualTexture(VSOutput pin, uniform bool fog) : COLOR0
{
    float4 color = tex2D(TextureSampler, pin.TexCoord);
    float4 overlay = tex2D(Texture2Sampler, pin.TexCoord2);
    color.rgb *= 2;
    color *= overlay * pin.Diffuse;
    if (fog)
        color = ApplyFog(color, pin.Fog);
    return color;
}

#define DUAL_TEXTURE_TECHNIQUE(V, F) \
    technique DualTextureEffect_V##V##_F##F \
    { \
        pass \
        { \
            VertexShader = compile vs_3_0 VSDualTexture(STOCK_FLAG_##V, STOCK_FLAG_##F); \
            PixelShader = compile ps_3_0 PSDualTexture(STOCK_FLAG_##F); \
        } \
    }

DUAL_TEXTURE_TECHNIQUE(0, 0) DUAL_TEXTURE_TECHNIQUE(0, 1) DUAL_TEXTURE_TECHNIQUE(1, 0) DUAL_TEXTURE_TECHNIQUE(1, 1)
