// d3d11_cube's shaders (the DirectX SDK's Tutorial07 with a directional light added): a textured,
// lit cube. Constant buffers by how often they change, as the tutorial has them.
Texture2D txDiffuse : register(t0);
SamplerState samPoint : register(s0);

cbuffer cbNeverChanges : register(b0)
{
    matrix View;
};

cbuffer cbChangeOnResize : register(b1)
{
    matrix Projection;
};

cbuffer cbChangesEveryFrame : register(b2)
{
    matrix World;
    float4 vMeshColor;
    float4 vLightDir;   // world space, towards the surface
    float4 vAmbient;
};

struct VS_INPUT
{
    float4 Pos : POSITION;
    float3 Norm : NORMAL;
    float2 Tex : TEXCOORD0;
};

struct PS_INPUT
{
    float4 Pos : SV_POSITION;
    float3 Norm : NORMAL;
    float2 Tex : TEXCOORD0;
};

PS_INPUT VS(VS_INPUT input)
{
    PS_INPUT output = (PS_INPUT)0;
    output.Pos = mul(input.Pos, World);
    output.Pos = mul(output.Pos, View);
    output.Pos = mul(output.Pos, Projection);
    output.Norm = mul(input.Norm, (float3x3)World);
    output.Tex = input.Tex;
    return output;
}

float4 PS(PS_INPUT input) : SV_Target
{
    float diffuse = saturate(dot(normalize(input.Norm), -vLightDir.xyz));
    return txDiffuse.Sample(samPoint, input.Tex) * vMeshColor * (vAmbient + diffuse);
}
