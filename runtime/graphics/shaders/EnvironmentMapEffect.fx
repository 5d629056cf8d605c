// EnvironmentMapEffect.fx: XNA 4's EnvironmentMapEffect (fxport/graphics/environment_map_effect.h):
// a texture lit per vertex by the three directional lights (diffuse only), blended with a cube
// map seen in the reflected view direction:
//   colour = Texture * (lit diffuse, alpha)
//   env    = EnvironmentMap(reflect(-toEye, normal)) * colour.a
//   colour.rgb = lerp(colour.rgb, env.rgb, amount), amount = EnvironmentMapAmount, times
//                pow(1 - |dot(toEye, normal)|, FresnelFactor) with Fresnel
//   colour.rgb += EnvironmentMapSpecular * env.a (the cube map's alpha as a specular mask)
// then fog. Techniques EnvironmentMapEffect_R<fresnel>_S<specular>_F<fog>.

texture Texture;
sampler TextureSampler : register(s0) = sampler_state
{
    Texture = <Texture>;
};

texture EnvironmentMap;
sampler EnvironmentMapSampler : register(s1) = sampler_state
{
    Texture = <EnvironmentMap>;
};

float EnvironmentMapAmount = 1;
float3 EnvironmentMapSpecular = float3(0, 0, 0);
float FresnelFactor = 1;

struct VSInput
{
    float4 Position : POSITION0;
    float3 Normal : NORMAL0;
    float2 TexCoord : TEXCOORD0;
};

struct VSOutput
{
    float4 PositionPS : POSITION0;
    float4 Diffuse : TEXCOORD0;
    float4 Amount : TEXCOORD1;  // rgb: the environment map's share, a: fog factor
    float2 TexCoord : TEXCOORD2;
    float3 EnvCoord : TEXCOORD3;
};

VSOutput VSEnvironmentMap(VSInput vin, uniform bool fresnel, uniform bool fog)
{
    VSOutput vout;
    vout.PositionPS = mul(vin.Position, WorldViewProj);
    float3 positionWS = mul(vin.Position, World).xyz;
    float3 normal = WorldNormal(vin.Normal);
    float3 toEye = normalize(EyePosition - positionWS);
    LightSum lights = ComputeLights(toEye, normal);
    vout.Diffuse = float4(lights.Diffuse, DiffuseColor.a);
    float amount = EnvironmentMapAmount;
    if (fresnel)
        amount *= pow(max(1 - abs(dot(toEye, normal)), 0), FresnelFactor);
    vout.Amount = float4(amount, amount, amount, 0);
    if (fog)
        vout.Amount.a = ComputeFogFactor(vin.Position);
    vout.Diffuse = ColorOutput(vout.Diffuse);
    vout.Amount = ColorOutput(vout.Amount);
    vout.TexCoord = vin.TexCoord;
    vout.EnvCoord = reflect(-toEye, normal);
    return vout;
}

float4 PSEnvironmentMap(VSOutput pin, uniform bool specular, uniform bool fog) : COLOR0
{
    float4 color = tex2D(TextureSampler, pin.TexCoord) * pin.Diffuse;
    float4 env = texCUBE(EnvironmentMapSampler, pin.EnvCoord) * color.a;
    color.rgb = lerp(color.rgb, env.rgb, pin.Amount.rgb);
    if (specular)
        color.rgb += EnvironmentMapSpecular * env.a;
    if (fog)
        color = ApplyFog(color, pin.Amount.a);
    return color;
}

#define ENVIRONMENT_MAP_TECHNIQUE(R, S, F) \
    technique EnvironmentMapEffect_R##R##_S##S##_F##F \
    { \
        pass \
        { \
            VertexShader = compile vs_3_0 VSEnvironmentMap(STOCK_FLAG_##R, STOCK_FLAG_##F); \
            PixelShader = compile ps_3_0 PSEnvironmentMap(STOCK_FLAG_##S, STOCK_FLAG_##F); \
        } \
    }

ENVIRONMENT_MAP_TECHNIQUE(0, 0, 0) ENVIRONMENT_MAP_TECHNIQUE(0, 0, 1) ENVIRONMENT_MAP_TECHNIQUE(0, 1, 0) ENVIRONMENT_MAP_TECHNIQUE(0, 1, 1)
ENVIRONMENT_MAP_TECHNIQUE(1, 0, 0) ENVIRONMENT_MAP_TECHNIQUE(1, 0, 1) ENVIRONMENT_MAP_TECHNIQUE(1, 1, 0) ENVIRONMENT_MAP_TECHNIQUE(1, 1, 1)
