// StockEffects.fxh: what XNA 4's stock effects share (BasicEffect.fx, AlphaTestEffect.fx,
// DualTextureEffect.fx, EnvironmentMapEffect.fx, SkinnedEffect.fx): the constants the C++ classes
// fill at each Apply, XNA's directional-light equations and its linear fog. Written for fxport from
// XNA's documented behaviour. The runtime puts this text in front of each effect's own (the
// effects are embedded in the library, where #include has no folder to read from); each effect
// starts with #line 1 so diagnostics keep its own line numbers.

float4x4 WorldViewProj;
float4x4 World;
float4x4 WorldInverseTranspose;  // only its 3x3 part is read (normals)
float3 EyePosition;               // camera position in world space

// The material, as the classes premultiply it: DiffuseColor = (diffuse * alpha, alpha);
// EmissiveColor = (emissive + ambient * diffuse) * alpha when lit (unlit effects fold emissive
// into DiffuseColor instead).
float4 DiffuseColor = float4(1, 1, 1, 1);
float3 EmissiveColor = float3(0, 0, 0);
float3 SpecularColor = float3(1, 1, 1);
float SpecularPower = 16;

// Three directional lights; a disabled light has black colours.
float3 DirLight0Direction;
float3 DirLight0DiffuseColor;
float3 DirLight0SpecularColor;
float3 DirLight1Direction;
float3 DirLight1DiffuseColor;
float3 DirLight1SpecularColor;
float3 DirLight2Direction;
float3 DirLight2DiffuseColor;
float3 DirLight2SpecularColor;

// Linear fog: factor = saturate(dot(objectPosition, FogVector)); the class builds FogVector from
// World * View, FogStart and FogEnd, so the factor is (depth - FogStart) / (FogEnd - FogStart).
float4 FogVector;
float3 FogColor;

struct LightSum
{
    float3 Diffuse;
    float3 Specular;
};

// One light's Lambert term and Blinn-Phong highlight. Specular only where the light reaches the
// surface (dot(N, L) >= 0).
void AddDirectionalLight(inout LightSum sum, float3 direction, float3 diffuseColor, float3 specularColor,
                         float3 toEye, float3 normal)
{
    float3 toLight = -direction;
    float nDotL = dot(normal, toLight);
    float lit = step(0, nDotL);
    float nDotH = dot(normal, normalize(toEye + toLight));
    sum.Diffuse += diffuseColor * (lit * nDotL);
    sum.Specular += specularColor * pow(max(nDotH, 0) * lit, SpecularPower);
}

// XNA's lighting: diffuse = sum(lights) * DiffuseColor + EmissiveColor,
// specular = sum(highlights) * SpecularColor.
LightSum ComputeLights(float3 toEye, float3 normal)
{
    LightSum sum;
    sum.Diffuse = 0;
    sum.Specular = 0;
    AddDirectionalLight(sum, DirLight0Direction, DirLight0DiffuseColor, DirLight0SpecularColor, toEye, normal);
    AddDirectionalLight(sum, DirLight1Direction, DirLight1DiffuseColor, DirLight1SpecularColor, toEye, normal);
    AddDirectionalLight(sum, DirLight2Direction, DirLight2DiffuseColor, DirLight2SpecularColor, toEye, normal);
    sum.Diffuse = sum.Diffuse * DiffuseColor.rgb + EmissiveColor;
    sum.Specular = sum.Specular * SpecularColor;
    return sum;
}

float ComputeFogFactor(float4 objectPosition)
{
    return saturate(dot(objectPosition, FogVector));
}

// Fog blends towards FogColor premultiplied by the pixel's alpha (the stock effects' colours are
// premultiplied).
float4 ApplyFog(float4 color, float fogFactor)
{
    color.rgb = lerp(color.rgb, FogColor * color.a, fogFactor);
    return color;
}

// XNA's stock shaders are vs_2_0, and Direct3D 9 saturates a vs_2_0 shader's COLOR0/COLOR1 outputs
// (the diffuse colour and the specular-plus-fog colour) before they are interpolated. Ours are
// vs_3_0 with TEXCOORD outputs, which nothing clamps, so each vertex shader clamps those two here.
float4 ColorOutput(float4 color)
{
    return saturate(color);
}

float3 WorldNormal(float3 objectNormal)
{
    return normalize(mul(objectNormal, (float3x3)WorldInverseTranspose));
}

// Technique macros spell 0/1 feature digits as bool literals for the entry points' uniform bool
// parameters (technique names keep the digits).
#define STOCK_FLAG_0 false
#define STOCK_FLAG_1 true
