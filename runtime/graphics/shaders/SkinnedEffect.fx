// SkinnedEffect.fx: XNA 4's SkinnedEffect (fxport/graphics/skinned_effect.h): BasicEffect's
// textured lighting (per vertex or per pixel) on vertices skinned by up to 72 bones, with 1, 2 or 4
// weights per vertex: skin = sum(Bones[index_i] * weight_i), position.xyz = mul(position, skin),
// normal = mul(normal, (float3x3)skin), before World. Techniques
// SkinnedEffect_W<weights>_P<per pixel>_F<fog>.

#define MAX_BONES 72

texture Texture;
sampler TextureSampler : register(s0) = sampler_state
{
    Texture = <Texture>;
};

float4x3 Bones[MAX_BONES];

struct VSInput
{
    float4 Position : POSITION0;
    float3 Normal : NORMAL0;
    float2 TexCoord : TEXCOORD0;
    int4 Indices : BLENDINDICES0;
    float4 Weights : BLENDWEIGHT0;
};

struct VSOutput
{
    float4 PositionPS : POSITION0;
    float4 Diffuse : TEXCOORD0;
    float4 Specular : TEXCOORD1;    // rgb: per-vertex highlight, a: fog factor
    float2 TexCoord : TEXCOORD2;
    float3 PositionWS : TEXCOORD3;
    float3 NormalWS : TEXCOORD4;
};

VSOutput VSSkinned(VSInput vin, uniform int weights, uniform bool perPixel, uniform bool fog)
{
    float4x3 skin = 0;
    [unroll]
    for (int i = 0; i < weights; i++)
        skin += Bones[vin.Indices[i]] * vin.Weights[i];
    float4 position = float4(mul(vin.Position, skin), 1);
    float3 normal = mul(vin.Normal, (float3x3)skin);

    VSOutput vout;
    vout.PositionPS = mul(position, WorldViewProj);
    vout.PositionWS = mul(position, World).xyz;
    vout.TexCoord = vin.TexCoord;
    vout.Specular = 0;
    if (fog)
        vout.Specular.a = ComputeFogFactor(position);
    if (perPixel)
    {
        vout.Diffuse = float4(1, 1, 1, DiffuseColor.a);
        vout.NormalWS = WorldNormal(normal);
    }
    else
    {
        float3 toEye = normalize(EyePosition - vout.PositionWS);
        LightSum lights = ComputeLights(toEye, WorldNormal(normal));
        vout.Diffuse = float4(lights.Diffuse, DiffuseColor.a);
        vout.Specular.rgb = lights.Specular;
        vout.NormalWS = 0;
    }
    vout.Diffuse = ColorOutput(vout.Diffuse);
    vout.Specular = ColorOutput(vout.Specular);
    return vout;
}

float4 PSSkinned(VSOutput pin, uniform bool perPixel, uniform bool fog) : COLOR0
{
    float4 color = tex2D(TextureSampler, pin.TexCoord) * pin.Diffuse;
    float3 specular = pin.Specular.rgb;
    if (perPixel)
    {
        float3 toEye = normalize(EyePosition - pin.PositionWS);
        LightSum lights = ComputeLights(toEye, normalize(pin.NormalWS));
        color.rgb *= lights.Diffuse;
        specular = lights.Specular;
    }
    color.rgb += specular * color.a;
    if (fog)
        color = ApplyFog(color, pin.Specular.a);
    return color;
}

#define SKINNED_TECHNIQUE(W, P, F) \
    technique SkinnedEffect_W##W##_P##P##_F##F \
    { \
        pass \
        { \
            VertexShader = compile vs_3_0 VSSkinned(W, STOCK_FLAG_##P, STOCK_FLAG_##F); \
            PixelShader = compile ps_3_0 PSSkinned(STOCK_FLAG_##P, STOCK_FLAG_##F); \
        } \
    }

SKINNED_TECHNIQUE(1, 0, 0) SKINNED_TECHNIQUE(1, 0, 1) SKINNED_TECHNIQUE(1, 1, 0) SKINNED_TECHNIQUE(1, 1, 1)
SKINNED_TECHNIQUE(2, 0, 0) SKINNED_TECHNIQUE(2, 0, 1) SKINNED_TECHNIQUE(2, 1, 0) SKINNED_TECHNIQUE(2, 1, 1)
SKINNED_TECHNIQUE(4, 0, 0) SKINNED_TECHNIQUE(4, 0, 1) SKINNED_TECHNIQUE(4, 1, 0) SKINNED_TECHNIQUE(4, 1, 1)
