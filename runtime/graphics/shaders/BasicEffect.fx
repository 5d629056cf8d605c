// BasicEffect.fx: XNA 4's BasicEffect (fxport/graphics/basic_effect.h): one technique per shader
// permutation, named BasicEffect_L<lighting>_T<texture>_V<vertex colour>_F<fog> with lighting
// 0 = off, 1 = per vertex, 2 = per pixel. The class applies the technique its properties ask for;
// the runtime compiles a technique at its first Apply, so only the permutations a program uses are
// ever compiled. The constants and the lighting/fog functions come from StockEffects.fxh.

texture Texture;
sampler TextureSampler : register(s0) = sampler_state
{
    Texture = <Texture>;
};

struct VSInput
{
    float4 Position : POSITION0;
    float3 Normal : NORMAL0;
    float2 TexCoord : TEXCOORD0;
    float4 Color : COLOR0;
};

struct VSOutput
{
    float4 PositionPS : POSITION0;
    float4 Diffuse : TEXCOORD0;     // premultiplied colour (lit per vertex: the lit diffuse)
    float4 Specular : TEXCOORD1;    // rgb: per-vertex highlight, a: fog factor
    float2 TexCoord : TEXCOORD2;
    float3 PositionWS : TEXCOORD3;  // per-pixel lighting only
    float3 NormalWS : TEXCOORD4;    // per-pixel lighting only
};

VSOutput VSBasic(VSInput vin, uniform int lighting, uniform bool textured, uniform bool vertexColor, uniform bool fog)
{
    VSOutput vout;
    vout.PositionPS = mul(vin.Position, WorldViewProj);
    vout.Diffuse = DiffuseColor;
    vout.Specular = 0;
    if (fog)
        vout.Specular.a = ComputeFogFactor(vin.Position);
    vout.TexCoord = vin.TexCoord;  // unused by the untextured permutations
    vout.PositionWS = mul(vin.Position, World).xyz;
    vout.NormalWS = 0;
    if (lighting == 1)
    {
        float3 toEye = normalize(EyePosition - vout.PositionWS);
        LightSum lights = ComputeLights(toEye, WorldNormal(vin.Normal));
        vout.Diffuse = float4(lights.Diffuse, DiffuseColor.a);
        vout.Specular.rgb = lights.Specular;
    }
    else if (lighting == 2)
    {
        vout.Diffuse = float4(1, 1, 1, DiffuseColor.a);
        vout.NormalWS = WorldNormal(vin.Normal);
    }
    if (vertexColor)
        vout.Diffuse *= vin.Color;
    vout.Diffuse = ColorOutput(vout.Diffuse);
    vout.Specular = ColorOutput(vout.Specular);
    return vout;
}

float4 PSBasic(VSOutput pin, uniform int lighting, uniform bool textured, uniform bool vertexColor, uniform bool fog) : COLOR0
{
    float4 color = pin.Diffuse;
    if (textured)
        color *= tex2D(TextureSampler, pin.TexCoord);
    float3 specular = pin.Specular.rgb;
    if (lighting == 2)
    {
        float3 toEye = normalize(EyePosition - pin.PositionWS);
        LightSum lights = ComputeLights(toEye, normalize(pin.NormalWS));
        color.rgb *= lights.Diffuse;
        specular = lights.Specular;
    }
    if (lighting != 0)
        color.rgb += specular * color.a;
    if (fog)
        color = ApplyFog(color, pin.Specular.a);
    return color;
}

#define BASIC_TECHNIQUE(L, T, V, F) \
    technique BasicEffect_L##L##_T##T##_V##V##_F##F \
    { \
        pass \
        { \
            VertexShader = compile vs_3_0 VSBasic(L, STOCK_FLAG_##T, STOCK_FLAG_##V, STOCK_FLAG_##F); \
            PixelShader = compile ps_3_0 PSBasic(L, STOCK_FLAG_##T, STOCK_FLAG_##V, STOCK_FLAG_##F); \
        } \
    }

#define BASIC_TECHNIQUES_L(L) \
    BASIC_TECHNIQUE(L, 0, 0, 0) BASIC_TECHNIQUE(L, 0, 0, 1) BASIC_TECHNIQUE(L, 0, 1, 0) BASIC_TECHNIQUE(L, 0, 1, 1) \
    BASIC_TECHNIQUE(L, 1, 0, 0) BASIC_TECHNIQUE(L, 1, 0, 1) BASIC_TECHNIQUE(L, 1, 1, 0) BASIC_TECHNIQUE(L, 1, 1, 1)

BASIC_TECHNIQUES_L(0)
BASIC_TECHNIQUES_L(1)
BASIC_TECHNIQUES_L(2)
